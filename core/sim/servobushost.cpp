#include "servobushost.h"

#include "sim/emulatedsts3032.h"
#include "sim/servoplant.h"

#include <QSocketNotifier>
#include <QTimer>

#include <algorithm>

#include <cerrno>
#include <cmath>
#include <unistd.h>

namespace hatpic {

ServoBusHost::ServoBusHost(const Config &config, QObject *parent) : QObject(parent)
{
    // A config with more servos than ids gets the servos it can have (the program refuses it).
    const int count =
        std::clamp(config.servos, 1, std::min(kMaxAxes, int(fw::sts::kMaxId) - int(config.id) + 1));
    for (int k = 0; k < count; ++k) {
        m_plants.push_back(std::make_unique<ServoPlant>(config.tauLimit));
        EmulatedSts3032::Config servo;
        servo.id = std::uint8_t(config.id + k);
        servo.centerTick = config.centerTick;
        servo.tauLimit = config.tauLimit;
        servo.noise = config.noise;
        servo.seed = config.seed + std::uint64_t(k);
        m_servos.push_back(std::make_unique<EmulatedSts3032>(*m_plants.back(), servo));
        m_hands.push_back(k == 0 ? config.hand : config.otherHands[std::size_t(k - 1)]);
        m_torque.push_back(torqueEnabled(k));
    }
}

ServoBusHost::~ServoBusHost()
{
    stop();
}

bool ServoBusHost::torqueEnabled(int k) const
{
    return servo(k).reg(fw::sts::kRegTorqueEnable) != 0;
}

QString ServoBusHost::start()
{
    if (isRunning())
        return {};
    if (const QString error = m_pty.open(); !error.isEmpty())
        return error;
    m_notifier = new QSocketNotifier(qintptr(m_pty.master()), QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, [this] { serviceBus(); });
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(kTickMs);
    connect(m_timer, &QTimer::timeout, this, [this] {
        advanceToNow();
        m_notifier->setEnabled(true);
    });
    m_clock.start();
    m_lastNs = 0;
    m_timer->start();
    return {};
}

void ServoBusHost::stop()
{
    delete m_notifier;
    m_notifier = nullptr;
    delete m_timer;
    m_timer = nullptr;
    m_pty.close();
}

QString ServoBusHost::createLink(const QString &path)
{
    return m_pty.createLink(path);
}

void ServoBusHost::advanceToNow()
{
    const qint64 now = m_clock.nsecsElapsed();
    // After a long stall (suspend, debugger) emulated time falls behind instead of running
    // thousands of sub-steps at once.
    const double dt = std::min(double(now - m_lastNs) * 1e-9, kMaxCatchUp);
    m_lastNs = now;
    if (dt <= 0)
        return;
    const int steps = std::max(1, int(std::ceil(dt * ServoPlant::kMinSubStepRate)));
    const double h = dt / steps;
    for (int i = 0; i < steps; ++i) {
        for (std::size_t k = 0; k < m_plants.size(); ++k) {
            ServoPlant &plant = *m_plants[k];
            plant.step(h, m_hands[k].torque(m_time, plant.theta(), plant.omega()));
        }
        m_time += h;
    }
}

void ServoBusHost::serviceBus()
{
    // The plant first: a READ answers with the knob as it is now.
    advanceToNow();
    std::uint8_t buffer[256];
    for (;;) {
        const ssize_t n = ::read(m_pty.master(), buffer, sizeof buffer);
        if (n > 0) {
            // Every servo hears the bus; only the one addressed answers (broadcasts: none).
            for (const auto &servo : m_servos)
                servo->receive(std::span<const std::uint8_t>(buffer, std::size_t(n)));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK))
            m_notifier->setEnabled(false); // EOF/EIO would spin: wait for the next tick
        break;
    }
    // A servo answers at once or never: what the pty does not take now is dropped (the
    // master discards its input before each request anyway).
    for (const auto &servo : m_servos) {
        while (servo->pendingOutput() > 0) {
            const std::size_t size = servo->takeOutput(buffer);
            ssize_t n = 0;
            do {
                n = ::write(m_pty.master(), buffer, size);
            } while (n < 0 && errno == EINTR);
        }
    }
    for (int k = 0; k < servos(); ++k) {
        if (const bool torque = torqueEnabled(k); torque != m_torque[std::size_t(k)]) {
            m_torque[std::size_t(k)] = torque;
            Q_EMIT torqueEnableChanged(k, torque);
        }
    }
}

} // namespace hatpic
