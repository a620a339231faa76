// The columns of a Sample: one table that every sample CSV (recordings and their reader,
// hatpicctl's `simulate` and `stream`, the plots' export) and the plots' channels read.
// docs/recording.md describes the columns for people.
#pragma once

#include "telemetry/sample.h"

#include <QByteArray>

#include <array>
#include <cstddef>
#include <string_view>

namespace hatpic {

//! One column of the sample CSV: a quantity of Sample, in SI units.
struct SampleColumn
{
    std::string_view name;    //!< header name, e.g. "tau_rec"
    std::string_view unit;    //!< SI unit, e.g. "N·m"; empty for the flags
    std::string_view meaning; //!< what it is, in a few words
    double Sample::*value;    //!< the quantity; nullptr for the flags (Sample::flags, a bit set)
    //! Added after the first recordings: a file without it reads its values as empty, unremarked
    //! (other missing columns are named in a warning).
    bool addedLater = false;

    constexpr bool isFlags() const { return value == nullptr; }
};

//! The sample columns in the order every CSV writes them.
//! tau_fx (effects.md), then tau_pc and pc_reserve (passivity.md) came after the flags, so older
//! files and programs that read columns by position keep theirs: they are last in `simulate` and
//! `stream`, and before `event` in recordings.
inline constexpr std::array<SampleColumn, 13> kSampleColumns = {{
    {"t_s", "s", "session time: follows the device clock, monotonic", &Sample::t_s},
    {"theta", "rad", "knob angle, absolute", &Sample::theta},
    {"omega", "rad/s", "knob rate", &Sample::omega},
    {"tau", "N·m", "interaction torque of eq. (1); the operator's torque is -tau", &Sample::tau},
    {"tau_rec", "N·m", "re-centering torque", &Sample::tau_rec},
    {"tau_ext", "N·m", "external feedback torque", &Sample::tau_ext},
    {"tau_total", "N·m", "tau_rec + tau_fx + tau_ext as rendered, clamped to tau_limit",
     &Sample::tau_total},
    {"v_ref", "m/s or rad/s", "reference velocity", &Sample::v_ref},
    {"p_ref", "m or rad", "reference position", &Sample::p_ref},
    {"flags", "", "device flags (low byte) | host flags (kFlag*), a decimal integer", nullptr},
    {"tau_fx", "N·m",
     "effect torque tau_det + tau_wall + tau_vib; empty when the device does not send it",
     &Sample::tau_fx, true},
    {"tau_pc", "N·m",
     "passivity controller torque -beta*omega; empty when the device does not send it",
     &Sample::tau_pc, true},
    {"pc_reserve", "J",
     "passivity controller's energy reserve R; empty when the device does not send it",
     &Sample::pc_reserve, true},
}};

//! The quantities a plot shows (theta … p_ref) are the columns from this one on, in order;
//! the plots show tau_fx and tau_pc, after the flags, too.
inline constexpr std::size_t kFirstQuantityColumn = 1;
inline constexpr std::size_t kQuantityColumnCount = 8;

//! Position of the column called `name` in kSampleColumns; kSampleColumns.size() if none.
constexpr std::size_t sampleColumnIndex(std::string_view name)
{
    std::size_t i = 0;
    while (i < kSampleColumns.size() && kSampleColumns[i].name != name)
        ++i;
    return i;
}

static_assert(sampleColumnIndex("t_s") == 0 &&
              sampleColumnIndex("pc_reserve") + 1 == kSampleColumns.size());
static_assert(kFirstQuantityColumn + kQuantityColumnCount == sampleColumnIndex("flags"));

//! The header of the sample CSV, "t_s,theta,…,flags,tau_fx,tau_pc,pc_reserve", without line end.
QByteArray sampleCsvHeader();

//! Appends the fields of one row, in column order and without line end, to `row`: numbers as
//! compactNumberText() (the one number format), NaN (a quantity the protocol does not carry)
//! as an empty field, the flags as a decimal integer.
void appendSampleCsvRow(QByteArray &row, const Sample &sample);

} // namespace hatpic
