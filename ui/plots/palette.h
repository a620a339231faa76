// One colour per quantity, in every view (time plots, legends, stiffness view): θ is blue
// wherever θ is drawn, the notch band amber wherever the notch band is shaded. Views pick a
// line style (solid, dashed) to tell variants of one quantity apart, never another colour.
#pragma once

#include "plots/channel.h"

#include <QColor>

namespace hatpic::palette {

//! The colour of a channel's series.
inline QColor channel(Channel c)
{
    switch (c) {
    case Channel::Theta:
        return {21, 101, 192}; // blue
    case Channel::Omega:
        return {0, 151, 167}; // cyan
    case Channel::Tau:
        return {97, 97, 97}; // grey
    case Channel::TauRec:
        return {173, 20, 87}; // crimson: also the stiffness view's τ_rec(θ) curves
    case Channel::TauExt:
        return {46, 125, 50}; // green
    case Channel::TauTotal:
        return {230, 81, 0}; // orange
    case Channel::VRef:
        return {123, 31, 162}; // purple
    case Channel::PRef:
        return {109, 76, 65}; // brown
    }
    return Qt::black;
}

inline const QColor kDeadZone(84, 110, 122, 90); //!< dead-zone band ±Q_dz (translucent)
inline const QColor kNotch(255, 160, 0, 60);     //!< notch band Q_dz … N (translucent)
inline const QColor kEvent(55, 71, 79);          //!< event markers (pushes, resets)
inline const QColor kLivePoint(33, 33, 33);      //!< the operating point (θ, τ_rec) now
inline const QColor kLimit(211, 47, 47);         //!< ±tau_limit
inline const QColor kMeasure(38, 50, 56);        //!< the measuring cursors A and B
inline const QColor kInertialTerm(158, 157, 36); //!< D_adm·ω̇ in the torque breakdown
inline const QColor kDampingTerm(57, 73, 171);   //!< M_adm·ω in the torque breakdown
inline const QColor kSaturated(211, 47, 47, 40); //!< samples where tau_limit clamped (shaded)

} // namespace hatpic::palette
