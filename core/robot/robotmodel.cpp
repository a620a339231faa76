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
    return out;
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
