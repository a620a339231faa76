// The static torque a knob at rest feels (ω = 0, so no wall damping and no vibration):
// τ_rec + τ_det + τ_wall over θ (model.md, effects.md § 1), where its detents hold the knob and
// where its walls stand, and the angles at which a plot must sample it to draw every detent;
// and how a measured τ_fx splits into its parts.
#pragma once

#include "model/effects.h"
#include "model/params.h"

#include <optional>
#include <vector>

namespace hatpic {

//! Samples per detent period s in effectSampleAngles(): fine enough to draw the sine.
inline constexpr int kSamplesPerDetent = 16;
//! At most this many detent samples over a view, whatever s and R are (fewer per period then).
inline constexpr int kMaxDetentSamples = 8192;

//! τ_rec(θ) + τ_det(θ − θ0) + τ_wall(θ − θ0, ω = 0) [N·m]; θ [rad].
double staticTorque(const DeviceParams &params, const EffectParams &effects, double theta);

//! Detents act somewhere: A > 0, R > 0 and a finite s > 0.
bool detentsActive(const EffectParams &effects);
//! The walls push back: K_w > 0.
bool wallsActive(const EffectParams &effects);
//! The block changes the static torque somewhere (detents or walls); the defaults do not.
bool shapesStaticTorque(const EffectParams &effects);

//! The stable rest positions of the detents: θ0 + i·s with |i·s| ≤ R (where τ_det crosses zero
//! going down), those within [lo, hi], sorted [rad]. Empty when detents are off.
std::vector<double> detentRestPositions(const EffectParams &effects, double theta0, double lo,
                                        double hi);

//! The walls' angles θ0 + wall_min and θ0 + wall_max when the walls act, each only when it lies
//! within [lo, hi] [rad].
struct WallAngles
{
    std::optional<double> low;
    std::optional<double> high;
};
WallAngles wallAngles(const EffectParams &effects, double theta0, double lo, double hi);

//! Half-width around θ0 that shows the effects: the detent range plus half a period, the walls
//! with a quarter of their distance beyond them (walls at ±π, the ends of travel, excepted);
//! 0 for the defaults, at most π [rad].
double effectsHalfRange(const EffectParams &effects);

//! Angles within [lo, hi] at which to sample the static torque so that the effects are drawn
//! right (unsorted, to merge with the curve's own grid) [rad]: inside the detent range a grid
//! aligned on the detents' phase, kSamplesPerDetent per period, evenly thinned to
//! kMaxDetentSamples when the range holds too many periods; the range's edges ±R with the
//! adjacent angles beyond them (τ_det stops there, so the jump is drawn vertical); the walls.
std::vector<double> effectSampleAngles(const EffectParams &effects, double theta0, double lo,
                                       double hi);

//! A measured τ_fx split into its parts (effects.md § 1) [N·m].
struct EffectTorques
{
    double det = 0;  //!< τ_det at the sample's θ
    double wall = 0; //!< τ_wall at the sample's θ and ω (with the walls' damping)
    double vib = 0;  //!< τ_vib = τ_fx − τ_det − τ_wall: what the host cannot compute
};

//! τ_det and τ_wall from the sample's θ [rad] and ω [rad/s] with the block and θ0 [rad], and
//! τ_vib = τ_fx − τ_det − τ_wall; all NaN when τ_fx is NaN (unknown, not zero). The device
//! renders in float32, so τ_vib carries its rounding (~1e-7 N·m) where no cue runs.
EffectTorques splitEffectTorque(const EffectParams &effects, double theta0, double theta,
                                double omega, double tauFx);

} // namespace hatpic
