#include "robot/loopequilibrium.h"

#include "model/reference.h"
#include "model/stiffness.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic::robot {

std::optional<LoopEquilibrium> loopEquilibrium(const DeviceParams &device, const HostParams &host,
                                               double tauHand, double gain, double limit,
                                               const RobotParams &robot)
{
    const auto at = [&](double theta) {
        LoopEquilibrium e;
        e.theta = theta;
        e.vRef = referenceVelocity(host, device, theta);
        e.wallForce = std::min(robot.kv * std::max(e.vRef, 0.0), robot.fMax);
        e.tauExt = std::clamp(gain * -e.wallForce, -limit, limit);
        e.robotPosition =
            robot.wall + (robot.wallStiffness > 0 ? e.wallForce / robot.wallStiffness : 0.0);
        return e;
    };
    const auto balance = [&](double theta) {
        return recenteringTorque(device, theta) + tauHand + at(theta).tauExt;
    };
    // Walk from the centre towards the push in small steps, then bisect the first sign change.
    const double direction = tauHand >= 0 ? 1.0 : -1.0;
    constexpr int kSteps = 20000;
    const double step = std::numbers::pi / kSteps;
    double lo = device.theta0;
    double fLo = balance(lo);
    for (int i = 1; i <= kSteps; ++i) {
        const double hi = device.theta0 + direction * step * i;
        const double fHi = balance(hi);
        if ((fLo > 0) != (fHi > 0) || fHi == 0) {
            double a = lo, b = hi, fa = fLo;
            for (int k = 0; k < 100; ++k) {
                const double m = 0.5 * (a + b);
                const double fm = balance(m);
                if ((fm > 0) == (fa > 0)) {
                    a = m;
                    fa = fm;
                } else {
                    b = m;
                }
            }
            const LoopEquilibrium e = at(0.5 * (a + b));
            if (!(e.vRef > 0))
                return std::nullopt;
            return e;
        }
        lo = hi;
        fLo = fHi;
    }
    return std::nullopt;
}

} // namespace hatpic::robot
