// One colour per quantity, in every view (time plots, legends, stiffness view): θ is blue
// wherever θ is drawn, the notch band amber wherever the notch band is shaded. Views pick a
// line style (solid, dashed) to tell variants of one quantity apart, never another colour; τ_fx's
// parts (τ_det, τ_wall, τ_vib) are drawn in τ_fx's colour, each in its own line style.
// Every colour reads on the light and on the dark theme's plot background alike (contrast at
// least 3:1 against white and against the dark base, tests/ui/window/tst_theme.cpp), so no
// colour changes with the theme.
#pragma once

#include "plots/channel.h"

#include <QColor>

namespace hatpic::palette {

//! The colour of a channel's series.
inline QColor channel(Channel c)
{
    switch (c) {
    case Channel::Theta:
        return {22, 105, 199}; // blue
    case Channel::Omega:
        return {0, 151, 167}; // cyan
    case Channel::Tau:
        return {106, 106, 106}; // grey
    case Channel::TauRec:
        return {203, 23, 102}; // crimson: also the stiffness view's τ_rec(θ) curves
    case Channel::TauExt:
        return {46, 125, 50}; // green
    case Channel::TauTotal:
        return {230, 81, 0}; // orange
    case Channel::VRef:
        return {163, 41, 214}; // purple
    case Channel::PRef:
        return {137, 96, 82}; // brown
    case Channel::TauFx:
        return {184, 134, 11}; // goldenrod: also the effects' marks (detent rest positions, walls)
    case Channel::TauPc:
        return {92, 107, 192}; // indigo: the passivity controller, apart from the torques' hues
    case Channel::TauDet:      // τ_fx's parts: τ_fx's colour, each in its own line style
    case Channel::TauWall:     // (plots/plotframe.cpp)
    case Channel::TauVib:
        return channel(Channel::TauFx);
    }
    return Qt::black;
}

//! Dead-zone band ±Q_dz (translucent): 1.9:1 against either theme's plot background once
//! composited (it was 1.4:1 on the dark one, barely seen).
inline const QColor kDeadZone(96, 125, 139, 128);
inline const QColor kNotch(255, 160, 0, 60);   //!< notch band Q_dz … N (translucent)
inline const QColor kEvent(85, 109, 122);      //!< event markers (pushes, resets)
inline const QColor kLivePoint(117, 117, 117); //!< the operating point (θ, τ_rec) now
inline const QColor kLimit(211, 47, 47);       //!< ±tau_limit
//! Profile slot B's curves beside slot A's when the two are compared (slot A keeps τ_rec's
//! crimson): olive, unlike every quantity's colour.
inline const QColor kSlotB(128, 118, 0);
inline const QColor kMeasure(170, 90, 210);      //!< the measuring cursors A and B (violet)
inline const QColor kInertialTerm(140, 140, 20); //!< D_adm·ω̇ in the torque breakdown
inline const QColor kDampingTerm(83, 109, 254);  //!< M_adm·ω in the torque breakdown
inline const QColor kSaturated(211, 47, 47, 40); //!< samples where tau_limit clamped (shaded)

// Status text in the editor, on the window's background of either theme (3:1 or more).
inline const QColor kProblemText(229, 57, 53); //!< a rejected value, ringing, a failed push
inline const QColor kCautionText(170, 122, 0); //!< a value clamped to its range
inline const QColor kEditedMark(230, 81, 0);   //!< a field edited but not pushed
//! The frame of the derived figures' warnings (saturates, rings, chatters), and the tint of
//! their background on the window's colour.
inline const QColor kWarningFrame(245, 124, 0);

} // namespace hatpic::palette
