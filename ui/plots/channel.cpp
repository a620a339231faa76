#include "plots/channel.h"

namespace hatpic {

double channelValue(const Sample &sample, Channel channel)
{
    switch (channel) {
    case Channel::Theta:
        return sample.theta;
    case Channel::Omega:
        return sample.omega;
    case Channel::Tau:
        return sample.tau;
    case Channel::TauRec:
        return sample.tau_rec;
    case Channel::TauExt:
        return sample.tau_ext;
    case Channel::TauTotal:
        return sample.tau_total;
    case Channel::VRef:
        return sample.v_ref;
    case Channel::PRef:
        return sample.p_ref;
    }
    return 0;
}

QString channelKey(Channel channel)
{
    switch (channel) {
    case Channel::Theta:
        return QStringLiteral("theta");
    case Channel::Omega:
        return QStringLiteral("omega");
    case Channel::Tau:
        return QStringLiteral("tau");
    case Channel::TauRec:
        return QStringLiteral("tau_rec");
    case Channel::TauExt:
        return QStringLiteral("tau_ext");
    case Channel::TauTotal:
        return QStringLiteral("tau_total");
    case Channel::VRef:
        return QStringLiteral("v_ref");
    case Channel::PRef:
        return QStringLiteral("p_ref");
    }
    return {};
}

QString channelLabel(Channel channel)
{
    switch (channel) {
    case Channel::Theta:
        return QStringLiteral("θ");
    case Channel::Omega:
        return QStringLiteral("ω");
    case Channel::Tau:
        return QStringLiteral("τ (measured)");
    case Channel::TauRec:
        return QStringLiteral("τ_rec");
    case Channel::TauExt:
        return QStringLiteral("τ_ext");
    case Channel::TauTotal:
        return QStringLiteral("τ_total");
    case Channel::VRef:
        return QStringLiteral("v_ref");
    case Channel::PRef:
        return QStringLiteral("p_ref");
    }
    return {};
}

bool isAngleChannel(Channel channel)
{
    return channel == Channel::Theta || channel == Channel::Omega;
}

} // namespace hatpic
