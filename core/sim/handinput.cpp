#include "handinput.h"

#include "model/params.h"
#include "telemetry/numbertext.h"

#include <QStringList>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace hatpic {

namespace {

struct KindInfo
{
    HandInput::Kind kind;
    QLatin1String name;
    QLatin1String usage; //!< the SPEC form, for error messages
    int minValues;
    int maxValues;
};

const KindInfo kKinds[] = {
    {HandInput::Kind::Idle, QLatin1String("idle"), QLatin1String("idle"), 0, 0},
    {HandInput::Kind::Constant, QLatin1String("const"), QLatin1String("const:T"), 1, 1},
    {HandInput::Kind::Step, QLatin1String("step"), QLatin1String("step:T[:T0[:AT]]"), 1, 3},
    {HandInput::Kind::Sine, QLatin1String("sine"), QLatin1String("sine:A:F"), 2, 2},
    {HandInput::Kind::Chirp, QLatin1String("chirp"), QLatin1String("chirp:A:F0:F1"), 3, 3},
    {HandInput::Kind::VirtualHand, QLatin1String("hand"), QLatin1String("hand:ANGLE"), 1, 1},
    {HandInput::Kind::Pushes, QLatin1String("pushes"), QLatin1String("pushes:T:N:ON:OFF"), 4, 4},
};

const KindInfo &infoOf(HandInput::Kind kind)
{
    for (const KindInfo &info : kKinds) {
        if (info.kind == kind)
            return info;
    }
    return kKinds[0];
}

QString valueCount(int n)
{
    return n == 1 ? QStringLiteral("1 value") : QStringLiteral("%1 values").arg(n);
}

void setError(QString *error, const QString &text)
{
    if (error)
        *error = text;
}

} // namespace

double HandInput::torque(double t, double theta, double omega) const
{
    switch (kind) {
    case Kind::Idle:
        return 0.0;
    case Kind::Constant:
        return amplitude;
    case Kind::Step:
        return t < stepTime ? offset : amplitude;
    case Kind::Sine:
        return amplitude * std::sin(2.0 * std::numbers::pi * frequency * t);
    case Kind::Chirp: {
        // Linear sweep: the instantaneous frequency goes from F0 to F1 over one period, then
        // the sweep starts again (phase restarts at 0, so each sweep is identical).
        const double tau = std::fmod(std::max(t, 0.0), kChirpPeriod);
        const double rate = (frequency1 - frequency) / kChirpPeriod; // [Hz/s]
        const double phase = 2.0 * std::numbers::pi * (frequency * tau + 0.5 * rate * tau * tau);
        return amplitude * std::sin(phase);
    }
    case Kind::VirtualHand:
        return kHandStiffness * (angle - theta) - kHandDamping * omega;
    case Kind::Pushes: {
        const double period = pushTime + releaseTime;
        if (t < 0 || period <= 0)
            return 0.0;
        const double index = std::floor(t / period);
        return index < pushes && t - index * period < pushTime ? amplitude : 0.0;
    }
    }
    return 0.0;
}

HandInput HandInput::pushing(double torque, int count, double on, double off)
{
    HandInput hand;
    hand.kind = Kind::Pushes;
    hand.amplitude = torque;
    hand.pushes = count;
    hand.pushTime = on;
    hand.releaseTime = off;
    return hand;
}

std::optional<HandInput> HandInput::parse(const QString &spec, QString *error)
{
    const QString text = spec.trimmed();
    if (text.isEmpty()) {
        setError(error, QStringLiteral("The hand input is empty; expected idle, const:T, "
                                       "step:T[:T0[:AT]], sine:A:F, chirp:A:F0:F1, hand:ANGLE "
                                       "or pushes:T:N:ON:OFF."));
        return std::nullopt;
    }
    const QStringList parts = text.split(QLatin1Char(':'));
    const QString kindName = parts.first().trimmed().toLower();
    const KindInfo *info = nullptr;
    for (const KindInfo &candidate : kKinds) {
        if (kindName == candidate.name)
            info = &candidate;
    }
    if (!info) {
        setError(error, QStringLiteral("Unknown hand input kind \"%1\" in \"%2\"; expected idle, "
                                       "const, step, sine, chirp, hand or pushes.")
                            .arg(parts.first(), text));
        return std::nullopt;
    }
    const int count = int(parts.size()) - 1;
    if (count < info->minValues || count > info->maxValues) {
        const QString expected =
            info->minValues == info->maxValues ? valueCount(info->minValues)
            : info->maxValues - info->minValues == 1
                ? QStringLiteral("%1 or %2 values").arg(info->minValues).arg(info->maxValues)
                : QStringLiteral("%1 to %2 values").arg(info->minValues).arg(info->maxValues);
        setError(error, QStringLiteral("Hand input \"%1\" has %2 but %3 takes %4 (%5).")
                            .arg(text, valueCount(count), QString(info->name), expected,
                                 QString(info->usage)));
        return std::nullopt;
    }

    QList<double> values;
    for (int i = 1; i < parts.size(); ++i) {
        const QString field = parts.at(i).trimmed();
        bool ok = false;
        const double value = field.toDouble(&ok);
        if (!ok || field.isEmpty()) {
            setError(error, QStringLiteral("Hand input value \"%1\" in \"%2\" is not a number.")
                                .arg(parts.at(i), text));
            return std::nullopt;
        }
        if (!std::isfinite(value)) {
            setError(error, QStringLiteral("Hand input value \"%1\" in \"%2\" is not finite.")
                                .arg(parts.at(i), text));
            return std::nullopt;
        }
        values.append(value);
    }

    HandInput hand;
    hand.kind = info->kind;
    auto checkFrequency = [&](double f) {
        if (f < 0) {
            setError(error,
                     QStringLiteral("Hand input frequency %1 Hz in \"%2\" must not be negative.")
                         .arg(compactNumberText(f), text));
            return false;
        }
        if (f > kMaxFrequency) {
            setError(error, QStringLiteral("Hand input frequency %1 Hz in \"%2\" is above the "
                                           "%3 Hz a simulated hand may have.")
                                .arg(compactNumberText(f), text, compactNumberText(kMaxFrequency)));
            return false;
        }
        return true;
    };
    auto checkTorque = [&](double tau) {
        if (std::abs(tau) <= kMaxTorque)
            return true;
        setError(error, QStringLiteral("Hand input torque %1 N·m in \"%2\" is beyond the ±%3 N·m "
                                       "a simulated hand may apply.")
                            .arg(compactNumberText(tau), text, compactNumberText(kMaxTorque)));
        return false;
    };
    // A time of the hand's pattern: from 0 (or above 0, for a push that must last) to `most`.
    auto checkTime = [&](const char *what, double t, double most, bool zeroAllowed) {
        if ((zeroAllowed ? t >= 0 : t > 0) && t <= most)
            return true;
        const QString range = zeroAllowed ? QStringLiteral("must be from 0 to %1 s.")
                                          : QStringLiteral("must be above 0 and at most %1 s.");
        setError(error, QStringLiteral("Hand input %1 time %2 s in \"%3\" ")
                                .arg(QLatin1String(what), compactNumberText(t), text) +
                            range.arg(compactNumberText(most)));
        return false;
    };
    switch (hand.kind) {
    case Kind::Idle:
        break;
    case Kind::Constant:
        hand.amplitude = values.at(0);
        if (!checkTorque(hand.amplitude))
            return std::nullopt;
        break;
    case Kind::Step:
        hand.amplitude = values.at(0);
        hand.offset = values.size() > 1 ? values.at(1) : 0.0;
        hand.stepTime = values.size() > 2 ? values.at(2) : kStepTime;
        if (!checkTorque(hand.amplitude) || !checkTorque(hand.offset))
            return std::nullopt;
        if (!checkTime("step", hand.stepTime, kMaxStepTime, true))
            return std::nullopt;
        break;
    case Kind::Sine:
        hand.amplitude = values.at(0);
        hand.frequency = values.at(1);
        if (!checkTorque(hand.amplitude) || !checkFrequency(hand.frequency))
            return std::nullopt;
        break;
    case Kind::Chirp:
        hand.amplitude = values.at(0);
        hand.frequency = values.at(1);
        hand.frequency1 = values.at(2);
        if (!checkTorque(hand.amplitude) || !checkFrequency(hand.frequency) ||
            !checkFrequency(hand.frequency1))
            return std::nullopt;
        break;
    case Kind::VirtualHand:
        hand.angle = values.at(0);
        if (std::abs(hand.angle) > kMaxAngle) {
            setError(error, QStringLiteral("Hand input angle %1 rad in \"%2\" is more than one "
                                           "turn (2π rad) from 0.")
                                .arg(compactNumberText(hand.angle), text));
            return std::nullopt;
        }
        break;
    case Kind::Pushes: {
        hand.amplitude = values.at(0);
        if (!checkTorque(hand.amplitude))
            return std::nullopt;
        const double n = values.at(1);
        if (n != std::floor(n) || n < 1 || n > kMaxPushes) {
            setError(error, QStringLiteral("Hand input push count %1 in \"%2\" must be a whole "
                                           "number from 1 to %3.")
                                .arg(compactNumberText(n), text, QString::number(kMaxPushes)));
            return std::nullopt;
        }
        hand.pushes = int(n);
        hand.pushTime = values.at(2);
        hand.releaseTime = values.at(3);
        if (!checkTime("push", hand.pushTime, kMaxPhase, false) ||
            !checkTime("release", hand.releaseTime, kMaxPhase, true))
            return std::nullopt;
        break;
    }
    }
    return hand;
}

QString HandInput::toSpec() const
{
    // Exact doubles (formatNumber), so the spec parses back to this very input.
    std::vector<double> values;
    switch (kind) {
    case Kind::Idle:
        break;
    case Kind::Constant:
        values = {amplitude};
        break;
    case Kind::Step:
        if (stepTime != kStepTime)
            values = {amplitude, offset, stepTime};
        else if (offset != 0.0)
            values = {amplitude, offset};
        else
            values = {amplitude};
        break;
    case Kind::Sine:
        values = {amplitude, frequency};
        break;
    case Kind::Chirp:
        values = {amplitude, frequency, frequency1};
        break;
    case Kind::VirtualHand:
        values = {angle};
        break;
    case Kind::Pushes:
        values = {amplitude, double(pushes), pushTime, releaseTime};
        break;
    }
    std::string spec(infoOf(kind).name.data(), static_cast<std::size_t>(infoOf(kind).name.size()));
    for (double value : values)
        spec += ':' + formatNumber(value);
    return QString::fromStdString(spec);
}

} // namespace hatpic
