#include "robot/robotmodel.h"

#include <algorithm>
#include <cmath>

namespace hatpic::robot {

std::vector<Violation> validate(const RobotParams &params)
{
    std::vector<Violation> out;
    const auto check = [&](const char *field, double value, bool ok, const char *rule) {
        if (!std::isfinite(value))
            out.push_back({field, -1, "must be a finite number", value});
        else if (!ok)
            out.push_back({field, -1, rule, value});
    };
    check("mass", params.mass, params.mass > 0, "must be > 0");
    check("kv", params.kv, params.kv >= 0, "must be ≥ 0");
    check("fmax", params.fMax, params.fMax > 0, "must be > 0");
    check("wall", params.wall, true, "");
    check("wall-stiffness", params.wallStiffness, params.wallStiffness >= 0, "must be ≥ 0");
    check("wall-damping", params.wallDamping, params.wallDamping >= 0, "must be ≥ 0");
    check("start", params.start, true, "");
    if (!out.empty())
        return out;
    // The step's stability (robotmodel.h), once each value is valid on its own.
    const auto bound = [](const char *what, double value, const char *unit) {
        return std::string("must be below ") + what + " = " + formatNumber(value) + " " + unit +
               " for the 1 ms step to be stable";
    };
    const double damping = dampingBound(params);
    if (!(params.kv + params.wallDamping < damping))
        out.push_back({"kv", -1, "plus wall-damping " + bound("2·m/h", damping, "N·s/m"),
                       params.kv + params.wallDamping});
    else if (!(params.wallStiffness < stiffnessBound(params)))
        out.push_back({"wall-stiffness", -1,
                       bound("(4·m − 2·h·(K_v + b_w))/h²", stiffnessBound(params), "N/m"),
                       params.wallStiffness});
    return out;
}

double dampingBound(const RobotParams &params)
{
    return 2 * params.mass / RobotModel::kStep;
}

double stiffnessBound(const RobotParams &params)
{
    const double h = RobotModel::kStep;
    return (4 * params.mass - 2 * h * (params.kv + params.wallDamping)) / (h * h);
}

double controlForce(const RobotParams &params, double vRef, double v)
{
    return std::clamp(params.kv * (vRef - v), -params.fMax, params.fMax);
}

double wallForce(const RobotParams &params, double x, double v)
{
    const double d = x - params.wall;
    if (d <= 0)
        return 0;
    return std::max(0.0, params.wallStiffness * d + params.wallDamping * v);
}

RobotModel::RobotModel(const RobotParams &params) : m_params(params), m_x(params.start) {}

void RobotModel::step(double vRef)
{
    m_controlForce = robot::controlForce(m_params, vRef, m_v);
    m_v += kStep * (m_controlForce - wallForce()) / m_params.mass;
    m_x += kStep * m_v;
}

double RobotModel::wallForce() const
{
    return robot::wallForce(m_params, m_x, m_v);
}

} // namespace hatpic::robot
