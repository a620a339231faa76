// Runs a blind A/B study on the device: for each trial it activates the slot of interval 1,
// pushes it (TuningModel::push, as the editor's Push does) and waits for the ACK and the
// matching read-back (the model's "in sync") before the interval starts; Space (next()) does the
// same for interval 2, then the participant's answer (1 or 2) is recorded and the trials file
// rewritten (atomically) before the next trial. No widgets: BlindDialog shows what it says.
#pragma once

#include "study/blindstudy.h"

#include <QElapsedTimer>
#include <QObject>

#include <memory>

namespace hatpic {

class ProfileController;
class TuningModel;

class BlindRunner : public QObject
{
    Q_OBJECT
public:
    enum class Phase {
        Idle,      //!< not started
        Preparing, //!< pushing an interval's slot, waiting for the device to be in sync
        Feeling,   //!< interval 1 on the device: the participant feels it, Space for 2
        Answering, //!< interval 2 on the device: the participant answers 1 or 2
        Finished,  //!< every trial answered
        Stopped,   //!< aborted or failed (error() says which); answered trials are in the file
    };
    Q_ENUM(Phase)

    //! Neither is owned: the window's profiles and tuning.
    BlindRunner(ProfileController *profiles, TuningModel *model, QObject *parent = nullptr);
    ~BlindRunner() override;

    //! Why a study cannot start now ("" when it can): both slots loaded and valid, a device
    //! that takes parameters.
    QString readiness() const;
    //! Starts the study, writing the trials file to `csvPath` (which the caller has cleared
    //! for replacing); false with error() when it cannot start.
    bool start(const BlindSetup &setup, const QString &csvPath);
    void next();               //!< Space: from interval 1 to interval 2
    void answer(int interval); //!< 1 or 2, while answering
    void abort();              //!< Escape: stops; answered trials are already in the file
    //! Whether a stopped study can go on (trials are left); resume() still checks readiness().
    bool canResume() const;
    //! Goes on with a stopped study from its first unanswered trial (interval 1 again), in the
    //! same trials file; false with error() when it cannot.
    bool resume();

    Phase phase() const { return m_phase; }
    int interval() const { return m_interval; } //!< 1 or 2 while preparing/feeling/answering
    const BlindStudy *study() const { return m_study.get(); }
    QString csvPath() const { return m_path; }
    QString error() const { return m_error; }
    bool isRunning() const;
    //! The name of slot 0 (A) or 1 (B)'s profile, for the trials file.
    QString slotProfileName(int slot) const;

Q_SIGNALS:
    void phaseChanged(hatpic::BlindRunner::Phase phase);
    //! The study started (true) or ended, finished or stopped (false).
    void runningChanged(bool running);

private:
    void present(int interval);
    //! The push of the interval's slot ended (or its late read-back came): in sync or not.
    void onPushed();
    void setPhase(Phase phase);
    void stop(const QString &error);
    void end();

    ProfileController *m_profiles;
    TuningModel *m_model;
    bool m_readBackLate = false; //!< the push was taken, its read-back unanswered: a read will do
    std::unique_ptr<BlindStudy> m_study;
    QString m_path;
    QString m_error;
    Phase m_phase = Phase::Idle;
    int m_interval = 0;
    int m_slotBefore = 0;  //!< the active slot before the study, made active again after
    QElapsedTimer m_since; //!< since interval 2 was ready: the response time
};

} // namespace hatpic
