#include "plots/displayunits.h"

#include <cmath>
#include <numbers>

namespace hatpic {

bool DisplayUnits::isAngular(Channel channel) const
{
    if (isAngleChannel(channel))
        return true;
    return (channel == Channel::VRef || channel == Channel::PRef) &&
           m_mode == ReferenceMode::Rotation;
}

double DisplayUnits::scale(Channel channel) const
{
    return m_degrees && isAngular(channel) ? 180.0 / std::numbers::pi : 1.0;
}

QString DisplayUnits::unit(Channel channel) const
{
    const bool rate = channel == Channel::Omega || channel == Channel::VRef;
    switch (channel) {
    case Channel::Tau:
    case Channel::TauRec:
    case Channel::TauExt:
    case Channel::TauTotal:
    case Channel::TauFx:
    case Channel::TauPc:
    case Channel::TauDet:
    case Channel::TauWall:
    case Channel::TauVib:
        return QStringLiteral("N·m");
    default:
        break;
    }
    if (!isAngular(channel))
        return rate ? QStringLiteral("m/s") : QStringLiteral("m");
    if (m_degrees)
        return rate ? QStringLiteral("°/s") : QStringLiteral("°");
    return rate ? QStringLiteral("rad/s") : QStringLiteral("rad");
}

QString DisplayUnits::format(Channel channel, double siValue) const
{
    if (std::isnan(siValue))
        return QStringLiteral("—");
    int decimals = 4; // rad and N·m: 0.1 mrad, 0.1 mN·m
    if (m_degrees && isAngular(channel))
        decimals = 2;
    else if (channel == Channel::VRef || channel == Channel::PRef)
        decimals = 3;
    QString text = QString::number(siValue * scale(channel), 'f', decimals);
    if (text.startsWith(u'-'))
        text.replace(0, 1, u'−');
    return text % u'\u2009' % unit(channel);
}

} // namespace hatpic
