#include "passivity.h"

#include "fieldcheck.h"
#include "paramtable.h"

#include <cmath>

namespace hatpic {

double PassivityParams::field(int index) const
{
    if (index < 0 || index >= kFieldCount)
        return std::nan("");
    return this->*kPassivityFields[static_cast<std::size_t>(index)].member;
}

void PassivityParams::setField(int index, double value)
{
    if (index >= 0 && index < kFieldCount)
        this->*kPassivityFields[static_cast<std::size_t>(index)].member = value;
}

std::string_view passivityFieldName(int index)
{
    if (index < 0 || index >= PassivityParams::kFieldCount)
        return {};
    return kPassivityFields[static_cast<std::size_t>(index)].name;
}

int passivityFieldIndex(std::string_view name)
{
    for (int i = 0; i < PassivityParams::kFieldCount; ++i) {
        if (kPassivityFields[static_cast<std::size_t>(i)].name == name)
            return i;
    }
    return -1;
}

std::vector<Violation> validate(const PassivityParams &params)
{
    std::vector<Violation> out;
    detail::checkFields(params, kPassivityFields, true, detail::Collect{out});
    return out;
}

int firstViolatingField(const PassivityParams &params)
{
    int first = -1;
    detail::checkFields(params, kPassivityFields, true,
                        [&first](std::string_view, int index, double, const auto &) {
                            if (first < 0)
                                first = index;
                        });
    return first;
}

PassivityParams roundedForWire(const PassivityParams &params)
{
    PassivityParams out;
    for (int i = 0; i < PassivityParams::kFieldCount; ++i) {
        const PassivityFieldSpec &s = kPassivityFields[static_cast<std::size_t>(i)];
        out.setField(i, detail::roundedInward(params.field(i), s.lower, s.upper, 0));
    }
    return out;
}

PassivityParams tidyPassivityParams(const PassivityParams &params)
{
    PassivityParams tidy = params;
    for (int i = 0; i < PassivityParams::kFieldCount; ++i)
        tidy.setField(i, shortestFloatDecimal(params.field(i)));
    return tidy;
}

bool sameOnWire(const PassivityParams &a, const PassivityParams &b)
{
    for (int i = 0; i < PassivityParams::kFieldCount; ++i) {
        if (static_cast<float>(a.field(i)) != static_cast<float>(b.field(i)))
            return false;
    }
    return true;
}

} // namespace hatpic
