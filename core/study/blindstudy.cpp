#include "study/blindstudy.h"

#include <QSaveFile>

#include <cmath>
#include <random>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

//! ln P(X = k) for X ~ Binomial(n, ½).
double logBinomialHalf(int n, int k)
{
    return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) -
           n * std::log(2.0);
}

//! One header line's text: no line breaks (a profile name could hold one).
QString oneLine(const QString &text)
{
    QString s = text;
    s.replace(u'\r', u' ').replace(u'\n', u' ');
    return s;
}

QString utcText(const QDateTime &t)
{
    return t.isValid() ? t.toUTC().toString(Qt::ISODateWithMs) : QString();
}

} // namespace

QList<std::array<int, 2>> BlindStudy::sequence(int trials, quint64 seed)
{
    std::mt19937_64 rng(seed);
    QList<std::array<int, 2>> orders;
    if (trials <= 0)
        return orders;
    orders.reserve(trials);
    for (int i = 0; i < trials / 2; ++i) {
        orders.append({0, 1});
        orders.append({1, 0});
    }
    if (trials % 2 != 0)
        orders.append(rng() % 2 == 0 ? std::array<int, 2>{0, 1} : std::array<int, 2>{1, 0});
    // Fisher–Yates with the raw generator (std::shuffle's use of it is unspecified); the modulo
    // bias is below 2⁻⁵⁰ for at most kMaxTrials items.
    for (qsizetype i = orders.size() - 1; i > 0; --i)
        std::swap(orders[i], orders[qsizetype(rng() % quint64(i + 1))]);
    return orders;
}

QString BlindStudy::check(const BlindSetup &setup)
{
    if (setup.trials < 1 || setup.trials > kMaxTrials)
        return u"trials: must be 1 … %1, got %2"_s.arg(kMaxTrials).arg(setup.trials);
    if (setup.question.trimmed().isEmpty())
        return u"question: must not be empty"_s;
    return {};
}

QString BlindStudy::slotName(int slot)
{
    return slot == 0 ? u"A"_s : u"B"_s;
}

QString BlindStudy::orderText(const std::array<int, 2> &order)
{
    return slotName(order[0]) + slotName(order[1]);
}

BlindStudy::BlindStudy(const BlindSetup &setup) : m_setup(setup)
{
    const auto orders = sequence(setup.trials, setup.seed);
    m_trials.reserve(orders.size());
    for (qsizetype i = 0; i < orders.size(); ++i) {
        BlindTrial t;
        t.number = int(i + 1);
        t.order = orders[i];
        m_trials.append(t);
    }
}

const BlindTrial *BlindStudy::current() const
{
    return isFinished() ? nullptr : &m_trials[m_answered];
}

void BlindStudy::markPresented(const QDateTime &utc)
{
    if (!isFinished())
        m_trials[m_answered].presentedAt = utc.toUTC();
}

bool BlindStudy::answer(int interval, double responseSeconds, const QDateTime &utc)
{
    if (isFinished() || (interval != 1 && interval != 2))
        return false;
    BlindTrial &t = m_trials[m_answered];
    t.answer = interval;
    t.responseSeconds = std::isfinite(responseSeconds) ? std::max(responseSeconds, 0.0) : 0.0;
    t.answeredAt = utc.toUTC();
    ++m_answered;
    return true;
}

BlindStudy::Score BlindStudy::score() const
{
    Score s;
    for (int i = 0; i < m_answered; ++i) {
        ++s.answered;
        s.chosenB += m_trials[i].answeredSlot() == 1 ? 1 : 0;
        s.chosenFirst += m_trials[i].answer == 1 ? 1 : 0;
    }
    if (s.answered == 0)
        return s;
    // Two-sided: twice the smaller tail, at most 1.
    const int n = s.answered;
    const int k = s.chosenB;
    double lower = 0;
    double upper = 0;
    for (int i = 0; i <= n; ++i) {
        const double p = std::exp(logBinomialHalf(n, i));
        if (i <= k)
            lower += p;
        if (i >= k)
            upper += p;
    }
    s.pValue = std::min(1.0, 2.0 * std::min(lower, upper));
    return s;
}

QByteArray BlindStudy::csv() const
{
    QString text;
    text += u"# HATPIC blind A/B study: paired comparison, each trial presents intervals 1 and 2 "
            u"(one A, one B, in the order given); the participant answers 1 or 2\n"_s;
    text += u"# profile A: "_s + oneLine(m_setup.profileA) + u'\n';
    text += u"# profile B: "_s + oneLine(m_setup.profileB) + u'\n';
    text += u"# seed: "_s + QString::number(m_setup.seed) + u'\n';
    text += u"# trials: "_s + QString::number(m_trials.size()) + u'\n';
    text += u"# question: "_s + oneLine(m_setup.question) + u'\n';
    text += QLatin1StringView(kColumns) + u'\n';
    for (int i = 0; i < m_answered; ++i) {
        const BlindTrial &t = m_trials[i];
        text += QString::number(t.number) + u',' + orderText(t.order) + u',' +
                QString::number(t.answer) + u',' + slotName(t.answeredSlot()) + u',' +
                QString::number(t.responseSeconds, 'f', 3) + u',' + utcText(t.presentedAt) + u',' +
                utcText(t.answeredAt) + u'\n';
    }
    return text.toUtf8();
}

QString BlindStudy::writeCsv(const QString &path) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return u"cannot write %1: %2"_s.arg(path, file.errorString());
    const QByteArray data = csv();
    if (file.write(data) != data.size() || !file.commit())
        return u"cannot write %1: %2"_s.arg(path, file.errorString());
    return {};
}

} // namespace hatpic
