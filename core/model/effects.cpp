#include "effects.h"

#include "fieldcheck.h"
#include "paramtable.h"
#include "servo.h"
#include "staticcurve.h"

#include <limits>

namespace hatpic {

double EffectParams::field(int index) const
{
    if (index < 0 || index >= kFieldCount)
        return std::nan("");
    return this->*kEffectFields[static_cast<std::size_t>(index)].member;
}

void EffectParams::setField(int index, double value)
{
    if (index >= 0 && index < kFieldCount)
        this->*kEffectFields[static_cast<std::size_t>(index)].member = value;
}

std::string_view effectFieldName(int index)
{
    if (index < 0 || index >= EffectParams::kFieldCount)
        return {};
    return kEffectFields[static_cast<std::size_t>(index)].name;
}

int effectFieldIndex(std::string_view name)
{
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        if (kEffectFields[static_cast<std::size_t>(i)].name == name)
            return i;
    }
    return -1;
}

std::vector<Violation> validate(const EffectParams &effects, double tauLimit)
{
    std::vector<Violation> out;
    detail::checkFields(effects, kEffectFields, true, detail::Collect{out}, tauLimit);
    return out;
}

int firstViolatingField(const EffectParams &effects, double tauLimit)
{
    int first = -1;
    detail::checkFields(
        effects, kEffectFields, true,
        [&first](std::string_view, int index, double, const auto &) {
            if (first < 0)
                first = index;
        },
        tauLimit);
    return first;
}

EffectParams roundedForWire(const EffectParams &effects, double tauLimit)
{
    EffectParams out;
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        const EffectFieldSpec &s = kEffectFields[static_cast<std::size_t>(i)];
        out.setField(i, detail::roundedInward(effects.field(i), s.lower, s.upper, tauLimit));
    }
    return out;
}

EffectParams tidyEffectParams(const EffectParams &effects)
{
    EffectParams tidy = effects;
    for (int i = 0; i < EffectParams::kFieldCount; ++i)
        tidy.setField(i, shortestFloatDecimal(effects.field(i)));
    return tidy;
}

bool sameOnWire(const EffectParams &a, const EffectParams &b)
{
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        if (static_cast<float>(a.field(i)) != static_cast<float>(b.field(i)))
            return false;
    }
    return true;
}

namespace {

//! The table's rules plus f < controlRate/2 (a cue above Nyquist would alias).
template<typename Report>
void checkVibration(const Vibration &v, double tauLimit, double controlRate, Report &&report)
{
    detail::checkFields(v, kVibrationFields, true, report, tauLimit);
    // VIBRATE carries float32: an amplitude below half the smallest float above 0 travels as 0,
    // which the device reads as "stop" — not the cue that was asked for.
    if (v.amplitude > 0 && static_cast<float>(v.amplitude) == 0.0f) {
        report(kVibrationFields[0].name, 0, v.amplitude, [] {
            return "must be 0 (stop) or at least " +
                   formatNumber(std::numeric_limits<float>::denorm_min()) +
                   ", the smallest 32-bit float above 0: a smaller one travels as 0, which stops "
                   "the cue";
        });
    }
    const double nyquist = controlRate / 2;
    if (std::isfinite(v.frequency) && !(v.frequency < nyquist)) {
        report(kVibrationFields[1].name, 1, v.frequency, [nyquist] {
            return "must be < half the control rate (" + formatNumber(nyquist) + ")";
        });
    }
}

} // namespace

std::vector<Violation> validate(const Vibration &vibration, double tauLimit, double controlRate)
{
    std::vector<Violation> out;
    checkVibration(vibration, tauLimit, controlRate, detail::Collect{out});
    return out;
}

int firstViolatingField(const Vibration &vibration, double tauLimit, double controlRate)
{
    int first = -1;
    checkVibration(vibration, tauLimit, controlRate,
                   [&first](std::string_view, int index, double, const auto &) {
                       if (first < 0 || index < first)
                           first = index;
                   });
    return first;
}

EffectFigures deriveEffectFigures(const EffectParams &effects, const DeviceParams &device,
                                  double physicalDamping, double period)
{
    EffectFigures f;
    f.detentPeakStiffness =
        effects.detent_strength * 2.0 * std::numbers::pi / effects.detent_spacing;
    f.wallPassivityMargin = physicalDamping - effects.wall_stiffness * period / 2.0;
    f.detentsStifferThanNotch = effects.detent_range > 0 && f.detentPeakStiffness > device.K_max;
    f.detentPassivityMargin = physicalDamping - f.detentPeakStiffness * period / 2.0;
    f.servoLimit = servoStiffnessLimit(device, servo::kPositionLoopHz);

    const bool detents = detentsActive(effects);
    const bool walls = effects.wall_stiffness > 0 && (effects.wall_min > -std::numbers::pi ||
                                                      effects.wall_max < std::numbers::pi);
    const auto add = [&f](bool broken, EffectWarning w) {
        if (broken)
            f.warnings.push_back(w);
    };
    add(walls && f.wallPassivityMargin < 0, EffectWarning::WallNotPassive);
    add(detents && f.detentPassivityMargin < 0, EffectWarning::DetentsNotPassive);
    add(walls && effects.wall_stiffness > f.servoLimit, EffectWarning::WallAboveServo);
    add(detents && f.detentPeakStiffness > f.servoLimit, EffectWarning::DetentsAboveServo);
    add(f.detentsStifferThanNotch && effects.detent_strength > 0,
        EffectWarning::DetentsStifferThanNotch);
    return f;
}

double servoStiffnessLimit(const DeviceParams &device, double servoBandwidthHz)
{
    const double omega = 2.0 * std::numbers::pi * servoBandwidthHz;
    return device.D_adm * omega * omega;
}

} // namespace hatpic
