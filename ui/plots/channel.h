// The plotted quantities: those of a Sample (the columns theta … p_ref of the sample column
// table, telemetry/samplecolumns.h, and tau_fx after its flags), so buffers and plots can
// address them as columns, then τ_fx's parts, which a SampleBuffer computes from them.
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
    TauDet,
    TauWall,
    TauVib
};

//! The quantity columns theta … p_ref, then tau_fx (NaN where the device does not send it):
//! the channels a Sample carries.
inline constexpr int kSampleChannelCount = 9;
static_assert(kSampleChannelCount == kQuantityColumnCount + 1);
//! Then τ_det, τ_wall and τ_vib, τ_fx's parts (SampleBuffer::setEffects computes them).
inline constexpr int kChannelCount = kSampleChannelCount + 3;

inline constexpr std::array<Channel, kChannelCount> kAllChannels{
    Channel::Theta,  Channel::Omega,    Channel::Tau,     Channel::TauRec,
    Channel::TauExt, Channel::TauTotal, Channel::VRef,    Channel::PRef,
    Channel::TauFx,  Channel::TauDet,   Channel::TauWall, Channel::TauVib};

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

//! Name a person reads in a legend: "θ", "τ_rec", "p_ref", …
QString channelLabel(Channel channel);

//! True for the channels measured in radians (θ) or rad/s (ω).
bool isAngleChannel(Channel channel);

} // namespace hatpic
