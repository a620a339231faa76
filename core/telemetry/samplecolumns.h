// The columns of a Sample: one table that every sample CSV (recordings and their reader,
// hatpicctl's `simulate` and `stream`, the plots' export) and the plots' channels read.
// docs/recording.md describes the columns for people.
#pragma once

#include "model/cyclequantities.h"
#include "telemetry/sample.h"

#include <QByteArray>
#include <QList>

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>

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

//! The sample columns in the order every CSV writes them: t_s, the cycle's quantities
//! (model/cyclequantities.h) with the host's tau_total, v_ref and p_ref before the flags.
//! tau_fx (effects.md), then tau_pc and pc_reserve (passivity.md) came after the flags, so older
//! files and programs that read columns by position keep theirs: they are last in `simulate` and
//! `stream`, and before `event` in recordings.
inline constexpr auto kSampleColumns = [] {
    // t_s stands for t_us; tau_total, v_ref, p_ref are added.
    std::array<SampleColumn, kCycleQuantityCount + 3> columns{};
    std::size_t n = 0;
    columns[n++] = {"t_s", "s", "session time: follows the device clock, monotonic", &Sample::t_s};
    forEachCycleQuantity<Sample>([&](const CycleQuantity &q, auto member) {
        if constexpr (std::is_same_v<decltype(member), double Sample::*>) {
            columns[n++] = {q.name, q.unit, q.meaning, member, q.optional()};
        } else if (q.name == "flags") {
            columns[n++] = {"tau_total", "N·m",
                            "tau_rec + tau_fx + tau_ext as rendered, clamped to tau_limit",
                            &Sample::tau_total};
            columns[n++] = {"v_ref", "m/s or rad/s", "reference velocity", &Sample::v_ref};
            columns[n++] = {"p_ref", "m or rad", "reference position", &Sample::p_ref};
            columns[n++] = {"flags", "",
                            "device flags (low byte) | host flags (kFlag*), a decimal integer",
                            nullptr};
        }
    });
    return columns;
}();

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

static_assert(sampleColumnIndex("t_s") == 0 && !kSampleColumns.back().name.empty());
static_assert(kFirstQuantityColumn + kQuantityColumnCount == sampleColumnIndex("flags"));

//! One quantity of each further axis of a multi-axis device (Sample::more): its column for axis
//! n (2…axes) is `<name>_<n>`, in the unit and meaning of the sample column `name` (axis 1's).
struct AxisColumn
{
    std::string_view name;
    double AxisSample::*value;
};

inline constexpr std::array<AxisColumn, 8> kAxisColumns{{
    {"theta", &AxisSample::theta},
    {"omega", &AxisSample::omega},
    {"tau", &AxisSample::tau},
    {"tau_rec", &AxisSample::tau_rec},
    {"tau_ext", &AxisSample::tau_ext},
    {"tau_total", &AxisSample::tau_total},
    {"v_ref", &AxisSample::v_ref},
    {"p_ref", &AxisSample::p_ref},
}};
static_assert([] {
    for (const AxisColumn &column : kAxisColumns) {
        if (sampleColumnIndex(column.name) == kSampleColumns.size())
            return false;
    }
    return true;
}());

//! The board's tilt (BoardSample::roll, ::pitch), after the further axes' columns.
struct TiltColumn
{
    std::string_view name;
    std::string_view unit;
    std::string_view meaning;
    double BoardSample::*value;
};

inline constexpr std::array<TiltColumn, 2> kTiltColumns{{
    {"roll", "rad", "the board's roll away from level", &BoardSample::roll},
    {"pitch", "rad", "the board's pitch", &BoardSample::pitch},
}};

//! The columns a device with `axes` axes and (or not) a tilt sensor adds after the sample
//! columns: theta_2 … p_ref_2, theta_3 …, …, then roll, pitch. None for a single knob.
QList<QByteArray> extraSampleColumns(int axes, bool tilt);

//! Appends `,value` for each of extraSampleColumns(axes, tilt) to `row`, as
//! appendSampleCsvRow writes its numbers (NaN, and axes the sample lacks, as empty fields).
void appendExtraCsvFields(QByteArray &row, const Sample &sample, int axes, bool tilt);

//! The header of the sample CSV, "t_s,theta,…,flags,tau_fx,tau_pc,pc_reserve", without line end.
QByteArray sampleCsvHeader();

//! Appends the fields of one row, in column order and without line end, to `row`: numbers as
//! compactNumberText() (the one number format), NaN (a quantity the protocol does not carry)
//! as an empty field, the flags as a decimal integer.
void appendSampleCsvRow(QByteArray &row, const Sample &sample);

} // namespace hatpic
