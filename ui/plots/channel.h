// The plotted quantities: those of a Sample (the columns theta … p_ref of the sample column
// table, telemetry/samplecolumns.h, and tau_fx and tau_pc after its flags), so buffers and plots
// can address them as columns, then τ_fx's parts, which a SampleBuffer computes from them.
#pragma once

#include "telemetry/samplecolumns.h"

#include <QString>

#include <array>
#include <limits>

namespace hatpic {

enum class Channel {
    Theta,
    Omega,
    Tau,
    TauRec,
    TauExt,
    TauTotal,
    VRef,
    PRef,
    TauFx,
    TauPc,
    TauDet,
    TauWall,
    TauVib
};

//! The quantity columns theta … p_ref, then tau_fx and tau_pc (NaN where the device does not
//! send them): the channels a Sample carries.
inline constexpr int kSampleChannelCount = 10;
static_assert(kSampleChannelCount == kQuantityColumnCount + 2);
//! Then τ_det, τ_wall and τ_vib, τ_fx's parts (SampleBuffer::setEffects computes them).
inline constexpr int kChannelCount = kSampleChannelCount + 3;

inline constexpr std::array<Channel, kChannelCount> kAllChannels{
    Channel::Theta,    Channel::Omega,   Channel::Tau,   Channel::TauRec, Channel::TauExt,
    Channel::TauTotal, Channel::VRef,    Channel::PRef,  Channel::TauFx,  Channel::TauPc,
    Channel::TauDet,   Channel::TauWall, Channel::TauVib};

//! Column of a channel, 0…kChannelCount−1.
constexpr int channelIndex(Channel channel)
{
    return static_cast<int>(channel);
}

//! Whether a Sample carries the channel (else it is one of τ_fx's parts).
constexpr bool isSampleChannel(Channel channel)
{
    return channelIndex(channel) < kSampleChannelCount;
}

//! The channel's column in the sample column table: its name, unit and value. τ_fx's parts
//! have none of their own: theirs is the column they are computed from, tau_fx.
constexpr const SampleColumn &channelColumn(Channel channel)
{
    if (!isSampleChannel(channel) || channel == Channel::TauFx)
        return kSampleColumns[sampleColumnIndex("tau_fx")];
    if (channel == Channel::TauPc)
        return kSampleColumns[sampleColumnIndex("tau_pc")];
    return kSampleColumns[kFirstQuantityColumn + static_cast<std::size_t>(channelIndex(channel))];
}

//! The channel's value in a sample (SI; NaN where the protocol does not carry it, and for τ_fx's
//! parts, which a sample does not hold).
inline double channelValue(const Sample &sample, Channel channel)
{
    if (!isSampleChannel(channel))
        return std::numeric_limits<double>::quiet_NaN();
    return sample.*channelColumn(channel).value;
}

//! The sample columns no channel shows (the passivity reserve, in J): a buffer keeps them all the
//! same, so that what it exports is what came.
inline constexpr std::array<std::size_t, 1> kUnplottedColumns{sampleColumnIndex("pc_reserve")};

//! Whether some sample channel shows the column `column`.
constexpr bool columnHasChannel(std::size_t column)
{
    for (int i = 0; i < kSampleChannelCount; ++i) {
        if (channelColumn(kAllChannels[std::size_t(i)]).name == kSampleColumns[column].name)
            return true;
    }
    return false;
}

//! Every quantity column is a channel's or an unplotted one: none is lost on its way through
//! the plots.
constexpr bool everyColumnIsKept()
{
    for (std::size_t c = 0; c < kSampleColumns.size(); ++c) {
        bool unplotted = false;
        for (const std::size_t u : kUnplottedColumns)
            unplotted = unplotted || u == c;
        if (!kSampleColumns[c].isFlags() && c != sampleColumnIndex("t_s") &&
            columnHasChannel(c) == unplotted)
            return false;
    }
    return true;
}
static_assert(everyColumnIsKept());

//! Name a person reads in a legend: "θ", "τ_rec", "p_ref", …
QString channelLabel(Channel channel);

//! True for the channels measured in radians (θ) or rad/s (ω).
bool isAngleChannel(Channel channel);

} // namespace hatpic
