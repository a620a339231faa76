// The plotted quantities of a Sample (the columns theta … p_ref of the sample column table,
// telemetry/samplecolumns.h, and tau_fx after its flags), so buffers and plots can address them
// as columns.
#pragma once

#include "telemetry/samplecolumns.h"

#include <QString>

#include <array>

namespace hatpic {

enum class Channel { Theta, Omega, Tau, TauRec, TauExt, TauTotal, VRef, PRef, TauFx };

//! The quantity columns theta … p_ref, then tau_fx (NaN where the device does not send it).
inline constexpr int kChannelCount = 9;
static_assert(kChannelCount == kQuantityColumnCount + 1);

inline constexpr std::array<Channel, kChannelCount> kAllChannels{
    Channel::Theta,    Channel::Omega, Channel::Tau,  Channel::TauRec, Channel::TauExt,
    Channel::TauTotal, Channel::VRef,  Channel::PRef, Channel::TauFx};

//! Column of a channel, 0…kChannelCount−1.
constexpr int channelIndex(Channel channel)
{
    return static_cast<int>(channel);
}

//! The channel's column in the sample column table: its name, unit and value.
constexpr const SampleColumn &channelColumn(Channel channel)
{
    if (channel == Channel::TauFx)
        return kSampleColumns[sampleColumnIndex("tau_fx")];
    return kSampleColumns[kFirstQuantityColumn + static_cast<std::size_t>(channelIndex(channel))];
}

//! The channel's value in a sample (SI; NaN where the protocol does not carry it).
inline double channelValue(const Sample &sample, Channel channel)
{
    return sample.*channelColumn(channel).value;
}

//! Name a person reads in a legend: "θ", "τ_rec", "p_ref", …
QString channelLabel(Channel channel);

//! True for the channels measured in radians (θ) or rad/s (ω).
bool isAngleChannel(Channel channel);

} // namespace hatpic
