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

// Collects violations for one field; every check records its own rule text.
class Checker
{
public:
    Checker(std::vector<Violation> &out, std::string_view field, int index, double value)
        : m_out(out), m_field(field), m_index(index), m_value(value)
    {}

    // Returns false (and records "must be finite") for NaN/Inf so later rules are skipped.
    bool finite()
    {
        if (std::isfinite(m_value))
            return true;
        add("must be finite");
        return false;
    }
    void require(bool ok, std::string rule)
    {
        if (!ok)
            add(std::move(rule));
    }

private:
    void add(std::string rule)
    {
        m_out.push_back(Violation{std::string(m_field), m_index, std::move(rule), m_value});
    }

    std::vector<Violation> &m_out;
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

std::vector<Violation> validate(const DeviceParams &p)
{
    std::vector<Violation> out;
    constexpr double halfPi = std::numbers::pi / 2;
    constexpr double pi = std::numbers::pi;

    if (Checker c(out, "D_adm", 0, p.D_adm); c.finite()) {
        c.require(p.D_adm >= 1e-6, "must be ≥ 1e-06");
        c.require(p.D_adm <= 1.0, "must be ≤ 1");
    }
    if (Checker c(out, "M_adm", 1, p.M_adm); c.finite()) {
        c.require(p.M_adm > 0.0, "must be > 0");
        c.require(p.M_adm <= 10.0, "must be ≤ 10");
    }
    if (Checker c(out, "K_min", 2, p.K_min); c.finite()) {
        c.require(p.K_min >= 0.0, "must be ≥ 0");
        // Cross-field rule; only meaningful when K_max itself is a number.
        if (std::isfinite(p.K_max))
            c.require(p.K_min <= p.K_max, "must be ≤ K_max (" + numberText(p.K_max) + ")");
    }
    if (Checker c(out, "K_max", 3, p.K_max); c.finite()) {
        c.require(p.K_max >= 0.0, "must be ≥ 0");
        c.require(p.K_max <= 50.0, "must be ≤ 50");
    }
    if (Checker c(out, "N", 4, p.N); c.finite()) {
        c.require(p.N > 0.0, "must be > 0");
        c.require(p.N <= halfPi, "must be ≤ π/2 (" + numberText(halfPi) + ")");
    }
    if (Checker c(out, "Q_dz", 5, p.Q_dz); c.finite()) {
        c.require(p.Q_dz >= 0.0, "must be ≥ 0");
        if (std::isfinite(p.N))
            c.require(p.Q_dz < p.N, "must be < N (" + numberText(p.N) + ")");
    }
    if (Checker c(out, "theta0", 6, p.theta0); c.finite()) {
        c.require(p.theta0 >= -pi, "must be ≥ −π (" + numberText(-pi) + ")");
        c.require(p.theta0 <= pi, "must be ≤ π (" + numberText(pi) + ")");
    }
    return out;
}

std::vector<Violation> validate(const HostParams &p)
{
    std::vector<Violation> out;
    if (Checker c(out, "v_max", -1, p.v_max); c.finite()) {
        c.require(p.v_max > 0.0, "must be > 0");
        c.require(p.v_max <= 100.0, "must be ≤ 100");
    }
    if (Checker c(out, "tau_limit", -1, p.tau_limit); c.finite()) {
        c.require(p.tau_limit > 0.0, "must be > 0");
        c.require(p.tau_limit <= 10.0, "must be ≤ 10");
    }
    return out;
}

int firstViolatingField(const DeviceParams &params)
{
    const auto violations = validate(params);
    return violations.empty() ? -1 : violations.front().index;
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
