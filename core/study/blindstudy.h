// A blind A/B study, the part without widgets: the seeded order of the trials, the answers and
// their times, the score, and the trials file (CSV). The tuner's blind test drives it (which
// slot to present, when the participant answered); this class decides nothing about timing.
//
// Protocol (paired comparison, two intervals): each trial presents both slots one after the
// other, intervals 1 and 2, in an order drawn from the seed (AB or BA); the participant
// answers which interval felt more <question>, 1 or 2. The answered slot is the slot of the
// chosen interval. Orders are balanced: as many AB as BA (one more of either for an odd count).
#pragma once

#include <QDateTime>
#include <QList>
#include <QString>

#include <array>
#include <optional>

namespace hatpic {

struct BlindSetup
{
    int trials = 10;
    quint64 seed = 0;
    QString profileA; //!< the slots' profile names, for the file's header
    QString profileB;
    QString question; //!< "Which felt stiffer?"
};

struct BlindTrial
{
    int number = 0;                 //!< 1-based
    std::array<int, 2> order{0, 1}; //!< the slot (0 = A, 1 = B) of interval 1 and of interval 2
    int answer = 0;                 //!< the chosen interval, 1 or 2; 0: not answered yet
    double responseSeconds = 0;     //!< from interval 2 being ready to the answer [s]
    QDateTime presentedAt;          //!< interval 1 ready on the device (UTC)
    QDateTime answeredAt;           //!< (UTC)

    //! The slot of the chosen interval (0 or 1), or -1 before the answer.
    int answeredSlot() const { return answer == 0 ? -1 : order[std::size_t(answer - 1)]; }
};

class BlindStudy
{
public:
    static constexpr int kMaxTrials = 1000;
    //! The trials file's column header (one fact, one home).
    static constexpr char kColumns[] =
        "trial,order,answer,answer_slot,response_s,presented_utc,answered_utc";

    struct Score
    {
        int answered = 0;
        int chosenB = 0;     //!< trials whose answer was slot B
        int chosenFirst = 0; //!< trials answered "1" (a bias towards an interval)
        //! Exact two-sided binomial test of chosenB against chance (p = ½); 1 with no answers.
        double pValue = 1;
    };

    //! The order of `trials` trials from `seed`: balanced, shuffled with std::mt19937_64 (whose
    //! output the C++ standard fixes), so a seed gives the same order on every machine.
    static QList<std::array<int, 2>> sequence(int trials, quint64 seed);
    //! "" when the setup can run, else why not ("trials: must be 1 … 1000, got 0").
    static QString check(const BlindSetup &setup);
    //! "A" or "B".
    static QString slotName(int slot);
    //! "AB" or "BA".
    static QString orderText(const std::array<int, 2> &order);

    //! The setup must pass check().
    explicit BlindStudy(const BlindSetup &setup);

    const BlindSetup &setup() const { return m_setup; }
    const QList<BlindTrial> &trials() const { return m_trials; }
    int answeredCount() const { return m_answered; }
    bool isFinished() const { return m_answered == m_trials.size(); }
    //! The trial to present now (the first unanswered), or nullptr when finished.
    const BlindTrial *current() const;

    //! Interval 1 of the current trial is ready on the device.
    void markPresented(const QDateTime &utc);
    //! Records the answer to the current trial and moves to the next. False (changing
    //! nothing) when finished or `interval` is not 1 or 2.
    bool answer(int interval, double responseSeconds, const QDateTime &utc);

    Score score() const;
    //! The trials file: '#' header lines (protocol, profiles, seed, question, count), the
    //! column line, one row per answered trial.
    QByteArray csv() const;
    //! Writes csv() to `path` atomically (QSaveFile): "" on success, else the error. Called
    //! after every answer, so a crash loses no answered trial.
    QString writeCsv(const QString &path) const;

private:
    BlindSetup m_setup;
    QList<BlindTrial> m_trials;
    int m_answered = 0;
};

} // namespace hatpic
