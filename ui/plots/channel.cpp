#include "plots/channel.h"

#include <QCoreApplication>

namespace hatpic {

QString channelLabel(Channel channel)
{
    switch (channel) {
    case Channel::Theta:
        return QStringLiteral("θ");
    case Channel::Omega:
        return QStringLiteral("ω");
    case Channel::Tau:
        return QCoreApplication::translate("hatpic::Channel", "τ (measured)");
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
    case Channel::TauFx:
        return QStringLiteral("τ_fx");
    case Channel::TauPc:
        return QStringLiteral("τ_pc");
    case Channel::TauDet:
        return QStringLiteral("τ_det");
    case Channel::TauWall:
        return QStringLiteral("τ_wall");
    case Channel::TauVib:
        return QStringLiteral("τ_vib");
    }
    return {};
}

bool isAngleChannel(Channel channel)
{
    const std::string_view unit = channelColumn(channel).unit;
    return unit == "rad" || unit == "rad/s";
}

} // namespace hatpic
