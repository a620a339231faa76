#include "servobushost.h"

#include "sim/emulatedsts3032.h"
#include "sim/servoplant.h"

#include <QSocketNotifier>
#include <QTimer>

#include <cerrno>
#include <cmath>
#include <unistd.h>

namespace hatpic {

ServoBusHost::ServoBusHost(const Config &config, QObject *parent)
    : QObject(parent), m_config(config), m_plant(std::make_unique<ServoPlant>(config.tauLimit))
{
    EmulatedSts3032::Config servo;
    servo.id = config.id;
    servo.centerTick = config.centerTick;
    servo.tauLimit = config.tauLimit;
    servo.noise = config.noise;
    servo.seed = config.seed;
    m_servo = std::make_unique<EmulatedSts3032>(*m_plant, servo);
    m_torque = torqueEnabled();
}

ServoBusHost::~ServoBusHost()
{
    stop();
}

bool ServoBusHost::torqueEnabled() const
{
    return m_servo->reg(fw::sts::kRegTorqueEnable) != 0;
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
        const double tauOp = m_config.hand.torque(m_time, m_plant->theta(), m_plant->omega());
        m_plant->step(h, tauOp);
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
            m_servo->receive(std::span<const std::uint8_t>(buffer, std::size_t(n)));
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
    while (m_servo->pendingOutput() > 0) {
        const std::size_t size = m_servo->takeOutput(buffer);
        ssize_t n = 0;
        do {
            n = ::write(m_pty.master(), buffer, size);
        } while (n < 0 && errno == EINTR);
    }
    if (const bool torque = torqueEnabled(); torque != m_torque) {
        m_torque = torque;
        Q_EMIT torqueEnableChanged(torque);
    }
}

} // namespace hatpic
