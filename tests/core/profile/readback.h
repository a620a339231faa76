// What a profile written and read back must give, to the bit (a file's bytes: testfiles.h): the
// profile tests share them (tst_profile, tst_profilerules, tst_profilepresets).
#pragma once

#include "profile/profile.h"
#include "testfiles.h"

#include <QByteArray>
#include <QFile>
#include <QString>

#include <bit>
#include <cstdint>

namespace hatpic::test {

inline bool sameBits(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// What reading back a written number must give, to the bit: the number itself, except that
// −0.0 is written as 0.0 (documented in docs/profile.md).
inline bool readsBackAs(double read, double written)
{
    return sameBits(read, written == 0.0 ? 0.0 : written);
}

// Every field of a read-back profile identical to the bit to what was written.
inline bool identical(const Profile &read, const Profile &written)
{
    for (int i = 0; i < hatpic::DeviceParams::kFieldCount; ++i) {
        if (!readsBackAs(read.device.field(i), written.device.field(i)))
            return false;
    }
    return read.name == written.name && read.notes == written.notes &&
           read.host.mode == written.host.mode &&
           read.host.ref_deadzone == written.host.ref_deadzone &&
           readsBackAs(read.host.v_max, written.host.v_max) &&
           readsBackAs(read.host.tau_limit, written.host.tau_limit);
}

} // namespace hatpic::test
