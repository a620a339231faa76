#include "params.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace hatpic {

namespace {

constexpr std::array<std::string_view, DeviceParams::kFieldCount> kDeviceFieldNames = {
    "D_adm", "M_adm", "K_min", "K_max", "N", "Q_dz", "theta0"};

// Walks model.md § 1's rules for one field. `report(field, index, value, rule)` is called for
// each broken rule, where `rule()` makes its text: a caller that only needs the index never
// builds a string, so the device core can validate without allocating.
template<typename Report> class Checker
{
public:
    Checker(Report &report, std::string_view field, int index, double value)
        : m_report(report), m_field(field), m_index(index), m_value(value)
    {}

    // Returns false (and reports "must be finite") for NaN/Inf so later rules are skipped.
    bool finite()
    {
        if (std::isfinite(m_value))
            return true;
        m_report(m_field, m_index, m_value, [] { return std::string("must be finite"); });
        return false;
    }
    template<typename Rule> void require(bool ok, Rule rule)
    {
        if (!ok)
            m_report(m_field, m_index, m_value, rule);
    }

private:
    Report &m_report;
    std::string_view m_field;
    int m_index;
    double m_value;
};

std::string numberText(double v)
{
    return formatNumber(v);
}

} // namespace

double DeviceParams::field(int index) const
{
    switch (index) {
    case 0:
        return D_adm;
    case 1:
        return M_adm;
    case 2:
        return K_min;
    case 3:
        return K_max;
    case 4:
        return N;
    case 5:
        return Q_dz;
    case 6:
        return theta0;
    default:
        return std::nan("");
    }
}

void DeviceParams::setField(int index, double value)
{
    switch (index) {
    case 0:
        D_adm = value;
        break;
    case 1:
        M_adm = value;
        break;
    case 2:
        K_min = value;
        break;
    case 3:
        K_max = value;
        break;
    case 4:
        N = value;
        break;
    case 5:
        Q_dz = value;
        break;
    case 6:
        theta0 = value;
        break;
    default:
        break;
    }
}

std::string_view deviceFieldName(int index)
{
    if (index < 0 || index >= DeviceParams::kFieldCount)
        return {};
    return kDeviceFieldNames[static_cast<std::size_t>(index)];
}

int deviceFieldIndex(std::string_view name)
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        if (kDeviceFieldNames[static_cast<std::size_t>(i)] == name)
            return i;
    }
    return -1;
}

std::string_view referenceModeName(ReferenceMode mode)
{
    return mode == ReferenceMode::Rotation ? "rotation" : "translation";
}

std::string Violation::message() const
{
    return field + ": " + rule + ", got " + formatNumber(value);
}

namespace {

template<typename Report> void checkDevice(const DeviceParams &p, Report &&report)
{
    constexpr double halfPi = std::numbers::pi / 2;
    constexpr double pi = std::numbers::pi;
    const auto text = [](const char *rule) { return [rule] { return std::string(rule); }; };
    const auto withNumber = [](const char *rule, double bound) {
        return [rule, bound] { return std::string(rule) + " (" + numberText(bound) + ")"; };
    };

    if (Checker c(report, "D_adm", 0, p.D_adm); c.finite()) {
        c.require(p.D_adm >= 1e-6, text("must be ≥ 1e-06"));
        c.require(p.D_adm <= 1.0, text("must be ≤ 1"));
    }
    if (Checker c(report, "M_adm", 1, p.M_adm); c.finite()) {
        c.require(p.M_adm > 0.0, text("must be > 0"));
        c.require(p.M_adm <= 10.0, text("must be ≤ 10"));
    }
    if (Checker c(report, "K_min", 2, p.K_min); c.finite()) {
        c.require(p.K_min >= 0.0, text("must be ≥ 0"));
        // Cross-field rule; only meaningful when K_max itself is a number.
        if (std::isfinite(p.K_max))
            c.require(p.K_min <= p.K_max, withNumber("must be ≤ K_max", p.K_max));
    }
    if (Checker c(report, "K_max", 3, p.K_max); c.finite()) {
        c.require(p.K_max >= 0.0, text("must be ≥ 0"));
        c.require(p.K_max <= 50.0, text("must be ≤ 50"));
    }
    if (Checker c(report, "N", 4, p.N); c.finite()) {
        c.require(p.N > 0.0, text("must be > 0"));
        c.require(p.N <= halfPi, withNumber("must be ≤ π/2", halfPi));
    }
    if (Checker c(report, "Q_dz", 5, p.Q_dz); c.finite()) {
        c.require(p.Q_dz >= 0.0, text("must be ≥ 0"));
        if (std::isfinite(p.N))
            c.require(p.Q_dz < p.N, withNumber("must be < N", p.N));
    }
    if (Checker c(report, "theta0", 6, p.theta0); c.finite()) {
        c.require(p.theta0 >= -pi, withNumber("must be ≥ −π", -pi));
        c.require(p.theta0 <= pi, withNumber("must be ≤ π", pi));
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

} // namespace

std::vector<Violation> validate(const DeviceParams &p)
{
    std::vector<Violation> out;
    checkDevice(p, Collect{out});
    return out;
}

std::vector<Violation> validate(const HostParams &p)
{
    std::vector<Violation> out;
    Collect report{out};
    const auto text = [](const char *rule) { return [rule] { return std::string(rule); }; };
    if (Checker c(report, "v_max", -1, p.v_max); c.finite()) {
        c.require(p.v_max > 0.0, text("must be > 0"));
        c.require(p.v_max <= 100.0, text("must be ≤ 100"));
    }
    if (Checker c(report, "tau_limit", -1, p.tau_limit); c.finite()) {
        c.require(p.tau_limit > 0.0, text("must be > 0"));
        c.require(p.tau_limit <= 10.0, text("must be ≤ 10"));
    }
    return out;
}

int firstViolatingField(const DeviceParams &params)
{
    int first = -1;
    checkDevice(params, [&first](std::string_view, int index, double, const auto &) {
        if (first < 0)
            first = index;
    });
    return first;
}

double roundedForWire(int index, double value)
{
    // Single-field bounds [low, high] per ParamBlock index; cross-field rules are left alone.
    constexpr double pi = std::numbers::pi;
    constexpr std::array<std::pair<double, double>, DeviceParams::kFieldCount> bounds = {{
        {1e-6, 1.0},
        {0.0, 10.0},
        {0.0, 50.0},
        {0.0, 50.0},
        {0.0, pi / 2},
        {0.0, pi / 2},
        {-pi, pi},
    }};
    float f = static_cast<float>(value);
    if (index < 0 || index >= DeviceParams::kFieldCount || !std::isfinite(value))
        return f;
    const auto [low, high] = bounds[static_cast<std::size_t>(index)];
    if (value >= low && f < low)
        f = std::nextafter(f, std::numeric_limits<float>::infinity());
    if (value <= high && f > high)
        f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    // M_adm is the one exclusive lower bound that rounding can reach (> 0).
    if (index == 1 && value > 0.0 && f <= 0.0f)
        f = std::numeric_limits<float>::denorm_min();
    return f;
}

DeviceParams roundedForWire(const DeviceParams &params)
{
    DeviceParams out;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        out.setField(i, roundedForWire(i, params.field(i)));
    return out;
}

bool sameOnWire(const DeviceParams &a, const DeviceParams &b)
{
    return roundedForWire(a) == roundedForWire(b);
}

double shortestFloatDecimal(double value)
{
    const auto single = static_cast<float>(value);
    if (!std::isfinite(value) || static_cast<double>(single) != value)
        return value;
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, single).ptr;
    double out = value;
    std::from_chars(buffer, end, out);
    return out;
}

std::string formatNumber(double value)
{
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

} // namespace hatpic
