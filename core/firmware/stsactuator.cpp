#include "firmware/stsactuator.h"

#include <array>

namespace hatpic::fw {

template<typename T>
StsActuator<T>::StsActuator(StsBus &bus, const Config &config) : m_bus(bus), m_config(config)
{
    m_bus.setTimeoutUs(config.timeoutUs);
}

template<typename T> bool StsActuator<T>::start(T &theta)
{
    const std::uint8_t id = m_config.id;
    if (!m_bus.ping(id))
        return false;
    std::array<std::uint8_t, 2> model{};
    m_modelNumber = m_bus.read(id, sts::kRegModelNumber, model) ? sts::word(model[0], model[1]) : 0;
    if (!writeByte(sts::kRegMode, sts::kModePosition))
        return false;
    std::array<std::uint8_t, 2> position{};
    if (!m_bus.read(id, sts::kRegPresentPosition, position))
        return false;
    const std::int32_t tick =
        sts::decodeSignMagnitude(sts::word(position[0], position[1]), sts::kPositionSignBit);
    const T present = static_cast<T>(sts::positionToTheta(tick, m_config.centerTick));
    // The goal register may still hold an old session's goal: torque on would jump to it.
    if (!command(present, T(0)))
        return false;
    if (!writeByte(sts::kRegTorqueEnable, 1))
        return false;
    theta = present;
    return true;
}

template<typename T> bool StsActuator<T>::measure(Measurement<T> &m)
{
    std::array<std::uint8_t, sts::kFeedbackBytes> raw{};
    if (!m_bus.read(m_config.id, sts::kRegPresentPosition, raw))
        return false;
    const std::int32_t position =
        sts::decodeSignMagnitude(sts::word(raw[0], raw[1]), sts::kPositionSignBit);
    const std::int32_t speed =
        sts::decodeSignMagnitude(sts::word(raw[2], raw[3]), sts::kSpeedSignBit);
    const std::int32_t load =
        sts::decodeSignMagnitude(sts::word(raw[4], raw[5]), sts::kLoadSignBit);
    m.theta = static_cast<T>(sts::positionToTheta(position, m_config.centerTick));
    m.omega = static_cast<T>(sts::speedToOmega(speed));
    m.tau = static_cast<T>(sts::loadToTorque(load, static_cast<double>(m_config.tauLimit)));
    return true;
}

template<typename T> bool StsActuator<T>::command(T theta, T /*omega*/)
{
    const std::int32_t goal = sts::thetaToGoalTick(static_cast<double>(theta), m_config.centerTick);
    const std::array<std::uint8_t, 2> bytes =
        sts::wordBytes(sts::encodeSignMagnitude(goal, sts::kPositionSignBit));
    return m_bus.write(m_config.id, sts::kRegGoalPosition, bytes);
}

template<typename T> void StsActuator<T>::disable()
{
    writeByte(sts::kRegTorqueEnable, 0);
}

template<typename T> bool StsActuator<T>::writeByte(std::uint8_t addr, std::uint8_t value)
{
    const std::array<std::uint8_t, 1> data{value};
    return m_bus.write(m_config.id, addr, data);
}

template class StsActuator<float>;
template class StsActuator<double>;

} // namespace hatpic::fw
