// Validation against a field table (paramtable.h): the one implementation of model.md's and
// effects.md's range rules. Private to core/model.
#pragma once

#include "paramtable.h"

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace hatpic::detail {

inline std::string boundText(const FieldBound &b, double external)
{
    // The device's float32 by the decimal that names it: tau_limit (0.44), not
    // 0.4399999976158142.
    const double value = b.external ? shortestFloatDecimal(external) : b.value;
    if (b.symbol.empty())
        return formatNumber(value);
    return std::string(b.symbol) + " (" + formatNumber(value) + ")";
}

// `v` against a lower or upper bound; one given when validating is compared as the device's
// float32 (atMostAsDeviceFloat).
inline bool aboveLower(const FieldBound &b, double v, double external)
{
    if (b.external)
        return b.inclusive ? atMostAsDeviceFloat(external, v) : !atMostAsDeviceFloat(v, external);
    return b.inclusive ? v >= b.value : v > b.value;
}
inline bool belowUpper(const FieldBound &b, double v, double external)
{
    if (b.external)
        return b.inclusive ? atMostAsDeviceFloat(v, external) : !atMostAsDeviceFloat(external, v);
    return b.inclusive ? v <= b.value : v < b.value;
}

// Walks the table's rules (model.md § 1) for every field of `p`. `report(field, index, value,
// rule)` is called for each broken rule, where `rule()` makes its text: a caller that only
// needs the index never builds a string, so the device core validates without allocating.
// Device fields report their wire index, host fields -1.
template<typename Params, std::size_t N, typename Report>
void checkFields(const Params &p, const std::array<FieldSpec<Params>, N> &specs, bool wireIndex,
                 Report &&report, double external = 0)
{
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const FieldSpec<Params> &s = specs[i];
        const double v = p.*s.member;
        const int index = wireIndex ? int(i) : -1;
        if (!std::isfinite(v)) {
            // NaN and ±Inf break every later rule: report only this one.
            report(s.name, index, v, [] { return std::string("must be finite"); });
            continue;
        }
        const FieldBound &lo = s.lower;
        if (lo.present && !aboveLower(lo, v, external)) {
            report(s.name, index, v, [&lo, external] {
                return std::string(lo.inclusive ? "must be ≥ " : "must be > ") +
                       boundText(lo, external);
            });
        }
        const FieldBound &hi = s.upper;
        if (hi.present && !belowUpper(hi, v, external)) {
            report(s.name, index, v, [&hi, external] {
                return std::string(hi.inclusive ? "must be ≤ " : "must be < ") +
                       boundText(hi, external);
            });
        }
        if (s.cross.field >= 0) {
            const FieldSpec<Params> &other = specs[std::size_t(s.cross.field)];
            const double ov = p.*other.member;
            // Only meaningful when the other field itself is a number.
            if (std::isfinite(ov) && !(s.cross.strict ? v < ov : v <= ov)) {
                report(s.name, index, v, [&s, &other, ov] {
                    return std::string(s.cross.strict ? "must be < " : "must be ≤ ") +
                           std::string(other.name) + " (" + formatNumber(ov) + ")";
                });
            }
        }
    }
}

//! A report() that collects every violation with its text.
struct Collect
{
    std::vector<Violation> &out;
    template<typename Rule>
    void operator()(std::string_view field, int index, double value, const Rule &rule)
    {
        out.push_back(Violation{std::string(field), index, rule(), value});
    }
};

//! `value` rounded to float32, moved one float inward when it satisfied a bound that the
//! rounding alone would leave. Values already outside stay outside (the receiver refuses them).
inline double roundedInward(double value, const FieldBound &lower, const FieldBound &upper,
                            double external)
{
    float f = static_cast<float>(value);
    if (!std::isfinite(value))
        return f;
    if (lower.present) {
        const double low = lower.external ? external : lower.value;
        if (value >= low && f < low)
            f = std::nextafter(f, std::numeric_limits<float>::infinity());
        if (!lower.inclusive && value > low && f <= float(low))
            f = std::nextafter(float(low), std::numeric_limits<float>::infinity());
    }
    if (upper.present) {
        const double high = upper.external ? external : upper.value;
        if (value <= high && f > high)
            f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    }
    return f;
}

} // namespace hatpic::detail
