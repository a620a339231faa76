#include "params.h"

#include "printabletext.h"

#include "fieldcheck.h"
#include "paramtable.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <utility>

namespace hatpic {

double DeviceParams::field(int index) const
{
    if (index < 0 || index >= kFieldCount)
        return std::nan("");
    return this->*kDeviceFields[static_cast<std::size_t>(index)].member;
}

void DeviceParams::setField(int index, double value)
{
    if (index >= 0 && index < kFieldCount)
        this->*kDeviceFields[static_cast<std::size_t>(index)].member = value;
}

std::string_view deviceFieldName(int index)
{
    if (index < 0 || index >= DeviceParams::kFieldCount)
        return {};
    return kDeviceFields[static_cast<std::size_t>(index)].name;
}

int deviceFieldIndex(std::string_view name)
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        if (kDeviceFields[static_cast<std::size_t>(i)].name == name)
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
    detail::checkFields(p, kDeviceFields, true, detail::Collect{out});
    return out;
}

std::vector<Violation> validate(const HostParams &p)
{
    std::vector<Violation> out;
    detail::checkFields(p, kHostFields, false, detail::Collect{out});
    return out;
}

int firstViolatingField(const DeviceParams &params)
{
    int first = -1;
    detail::checkFields(params, kDeviceFields, true,
                        [&first](std::string_view, int index, double, const auto &) {
                            if (first < 0)
                                first = index;
                        });
    return first;
}

template<typename Params> std::string rangeText(const FieldSpec<Params> &s)
{
    std::string text;
    if (s.lower.present) {
        text += s.lower.symbol.empty() ? formatNumber(s.lower.value) : std::string(s.lower.symbol);
        text += s.lower.inclusive ? " ≤ " : " < ";
    }
    text += s.symbol;
    if (s.upper.present) {
        text += s.upper.inclusive ? " ≤ " : " < ";
        text += s.upper.symbol.empty() ? formatNumber(s.upper.value) : std::string(s.upper.symbol);
    } else if (s.cross.field >= 0) {
        text += s.cross.strict ? " < " : " ≤ ";
        text += kDeviceFields[std::size_t(s.cross.field)].symbol;
    }
    return text;
}
template std::string rangeText(const DeviceFieldSpec &);
template std::string rangeText(const HostFieldSpec &);
template std::string rangeText(const EffectFieldSpec &);
template std::string rangeText(const VibrationFieldSpec &);
template std::string rangeText(const PassivityFieldSpec &);

double roundedForWire(int index, double value)
{
    // Single-field bounds per ParamBlock index; cross-field rules are left alone.
    float f = static_cast<float>(value);
    if (index < 0 || index >= DeviceParams::kFieldCount || !std::isfinite(value))
        return f;
    const auto [low, high] = numericRange(index);
    if (value >= low && f < low)
        f = std::nextafter(f, std::numeric_limits<float>::infinity());
    if (value <= high && f > high)
        f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    // An exclusive lower bound of 0 (M_adm, N) is reached when rounding flushes to zero.
    const FieldBound &lower = kDeviceFields[static_cast<std::size_t>(index)].lower;
    if (!lower.inclusive && value > lower.value && f <= float(lower.value))
        f = std::nextafter(float(lower.value), std::numeric_limits<float>::infinity());
    return f;
}

DeviceParams roundedToFloat(const DeviceParams &params)
{
    DeviceParams out;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        out.setField(i, static_cast<double>(static_cast<float>(params.field(i))));
    return out;
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

DeviceParams tidyDeviceParams(const DeviceParams &params)
{
    DeviceParams tidy = params;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        tidy.setField(i, shortestFloatDecimal(params.field(i)));
    return tidy;
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

std::string echoedText(std::string_view text)
{
    if (text.size() <= kMaxEchoedBytes)
        return printableText(text);
    std::size_t n = kMaxEchoedBytes;
    while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80)
        --n; // never half a character
    return printableText(text.substr(0, n)) + "… (" + std::to_string(text.size()) + " bytes)";
}

} // namespace hatpic
