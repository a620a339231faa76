// The simulated robot of robot.md: one axis, a velocity-tracking controller, a unilateral
// wall, stepped with a fixed h by semi-implicit Euler. Plain C++20 with no middleware, no Qt
// and no clock: the caller steps it (hatpic-robot-sim on the host's monotonic clock, tests as
// fast as they like).
#pragma once

#include "model/params.h"

#include <vector>

namespace hatpic::robot {

//! The robot's constants, robot.md's defaults.
struct RobotParams
{
    double mass = 1.5;          //!< m [kg]
    double kv = 40;             //!< K_v, velocity gain [N·s/m]
    double fMax = 20;           //!< F_max, controller force limit [N]
    double wall = 0.05;         //!< x_w, where the wall starts [m]
    double wallStiffness = 200; //!< k_w [N/m]
    double wallDamping = 5;     //!< b_w [N·s/m]
    double start = 0;           //!< x at the start [m]

    friend bool operator==(const RobotParams &, const RobotParams &) = default;
};

//! Every broken rule (finite values, m > 0, K_v ≥ 0, F_max > 0, k_w ≥ 0, b_w ≥ 0, and the
//! step's stability: dampingBound() and stiffnessBound()), named by the field's option name
//! ("mass", "kv", "fmax", "wall", "wall-stiffness", "wall-damping", "start"). Empty means
//! valid.
std::vector<Violation> validate(const RobotParams &params);

//! The 1 ms semi-implicit Euler step is stable only while the damping and stiffness it
//! integrates are small enough for the mass (robot.md's integrator; docs/teleop.md § The
//! robot's limits). In the wall, with the controller unsaturated, the step maps (v, x) by a
//! matrix of determinant 1 − a and trace 2 − a − b, where a = h·(K_v + b_w)/m and
//! b = h²·k_w/m; Jury's test makes both eigenvalues lie inside the unit circle iff 0 ≤ a < 2
//! and b < 4 − 2a:
//!   K_v + b_w < 2·m/h                       (dampingBound)
//!   k_w < (4·m − 2·h·(K_v + b_w)) / h²      (stiffnessBound)
//! Outside the wall (b = 0) and with the controller saturated (K_v's term gone) the bounds are
//! looser, so these two cover every regime. [N·s/m], [N/m]
double dampingBound(const RobotParams &params);
double stiffnessBound(const RobotParams &params);

class RobotModel
{
public:
    static constexpr double kStep = 1e-3; //!< h [s]

    explicit RobotModel(const RobotParams &params = {});

    //! One step of h towards the reference velocity vRef [m/s].
    void step(double vRef);

    double position() const { return m_x; } //!< x [m]
    double velocity() const { return m_v; } //!< v [m/s]
    //! F_c of the last step [N].
    double controlForce() const { return m_controlForce; }
    //! F_e = max(0, k_w·d + b_w·v) for a penetration d = x − x_w > 0, else 0: the wall pushes,
    //! never pulls [N].
    double wallForce() const;
    //! What a wrench estimator on the robot reports: the external force, −F_e [N].
    double estimatedForce() const { return -wallForce(); }
    const RobotParams &params() const { return m_params; }

private:
    RobotParams m_params;
    double m_x = 0;
    double m_v = 0;
    double m_controlForce = 0;
};

//! F_c = clamp(K_v·(v_ref − v), −F_max, F_max) [N].
double controlForce(const RobotParams &params, double vRef, double v);
//! F_e at position x and velocity v [N].
double wallForce(const RobotParams &params, double x, double v);

} // namespace hatpic::robot
