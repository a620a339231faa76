#include "firmwarehost.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "fwhost/fdhostport.h"
#include "fwhost/profileparamstore.h"
#include "fwhost/serialservoport.h"

#include <QSocketNotifier>
#include <QTimer>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <ctime>
#include <pthread.h>
#include <sched.h>

namespace hatpic {

namespace {

constexpr std::uint32_t kDeviceId = 0x46574831;              //!< "FWH1"
constexpr std::string_view kFirmwareName = "hatpic-fw-host"; //!< ≤ 16 bytes (HELLO_REPLY)
constexpr int kControlPriority = 50;                         //!< SCHED_FIFO priority, 1…99
//! Longest wait of emergencyStop() for the control thread: a period (≤ 0.1 s) and two bus
//! timeouts (≤ 0.1 s each) with room to spare [ms].
constexpr int kEmergencyWaitMs = 500;

std::int64_t monotonicNs()
{
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return std::int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

timespec toTimespec(std::int64_t ns)
{
    return timespec{time_t(ns / 1000000000), long(ns % 1000000000)};
}

} // namespace

//! fw::Clock on CLOCK_MONOTONIC: stateless, so both contexts may call it.
class MonotonicClock : public fw::Clock
{
public:
    std::uint32_t micros() override { return std::uint32_t(monotonicNs() / 1000); }
};

struct FirmwareHost::Shared
{
    std::mutex mutex;
    PeriodHistogram windowPeriod, totalPeriod, windowBusy, totalBusy;
    std::int64_t windowStartNs = 0;
    std::int64_t totalStartNs = 0;
    std::uint64_t windowLate = 0;
    std::uint64_t totalLate = 0;
    std::uint32_t windowErrorBase = 0; //!< bus.errors() when the window began
    fw::StsBusStats bus;
    bool faulted = false;
};

FirmwareHost::FirmwareHost(const Config &config, QObject *parent)
    : QObject(parent), m_config(config), m_shared(std::make_unique<Shared>())
{}

FirmwareHost::~FirmwareHost()
{
    stop();
}

QString FirmwareHost::servoStartFailure(fw::StsBusError error) const
{
    const int id = m_config.servoId + std::max(0, m_core->unstartedAxis());
    const QString servo = QStringLiteral("The servo (id %1) on %2").arg(id).arg(m_config.servoPath);
    const QString baud = QString::number(m_config.servoBaud) + u" baud";
    switch (error) {
    case fw::StsBusError::Timeout:
        return servo + u" does not answer at " + baud + u'.';
    case fw::StsBusError::Short:
        return servo + u" answers at " + baud +
               u", but its replies stop short of a status packet (another baud rate, or a "
               u"noisy line?).";
    case fw::StsBusError::Corrupt:
        return servo + u" answers at " + baud +
               u", but not with valid status packets (bad checksum or length: another baud "
               u"rate, or not an STS3032?).";
    case fw::StsBusError::ForeignId:
        return servo + u" does not answer at " + baud +
               u", but a servo with another id does (see --servo-id).";
    case fw::StsBusError::Rejected:
        return servo + u": the request could not be sent (id " + QString::number(id) + u").";
    case fw::StsBusError::None:
        break;
    }
    // Every transaction answered, yet start() failed: the servo refused the set-up.
    return servo + u" answers at " + baud + u" but did not take the position-mode set-up.";
}

QString FirmwareHost::start()
{
    if (isRunning())
        return {};
    m_servoPort = std::make_unique<SerialServoPort>();
    if (const QString error = m_servoPort->open(m_config.servoPath, m_config.servoBaud);
        !error.isEmpty())
        return error;
    if (const QString error = m_pty.open(); !error.isEmpty())
        return error;

    m_bus = std::make_unique<fw::StsBus>(*m_servoPort);
    m_actuators.clear();
    std::array<fw::Actuator<double> *, kMaxAxes> actuators{};
    const int servos = std::clamp(m_config.servos, 1, kMaxAxes);
    for (int k = 0; k < servos; ++k) {
        fw::StsActuator<double>::Config actuator;
        actuator.id = std::uint8_t(m_config.servoId + k);
        actuator.centerTick = m_config.centerTick;
        actuator.tauLimit = m_config.tauLimit;
        actuator.timeoutUs = m_config.servoTimeoutUs;
        m_actuators.push_back(std::make_unique<fw::StsActuator<double>>(*m_bus, actuator));
        actuators[std::size_t(k)] = m_actuators.back().get();
        const std::array<std::uint8_t, 2> torqueOff{fw::sts::kRegTorqueEnable, 0};
        TorqueOff &off = m_torqueOff[std::size_t(k)];
        off.size = fw::sts::encodePacket(actuator.id, fw::sts::kWrite, torqueOff, off.bytes);
    }
    m_clock = std::make_unique<MonotonicClock>();
    if (!m_config.stateFile.isEmpty())
        m_store = std::make_unique<ProfileParamStore>(
            m_config.stateFile, QString::fromLatin1(kFirmwareName), m_config.tauLimit);
    m_hostPort = std::make_unique<FdHostPort>(m_pty.master());
    if (!m_config.faults.isEmpty()) {
        m_hostPort->setFaults(std::make_unique<FaultInjector>(m_config.faults, m_config.faultSeed,
                                                              FaultInjector::Framing::V2));
    }

    fw::DeviceCore<double>::Config core;
    core.control.rateHz = m_config.rateHz;
    core.control.tauLimit = m_config.tauLimit;
    core.deviceId = kDeviceId;
    core.firmware = kFirmwareName;
    core.linkLimitHz = 0; // a pty has no baud rate
    m_core = std::make_unique<fw::DeviceCore<double>>(
        core, *m_hostPort, std::span(actuators.data(), std::size_t(servos)), *m_clock,
        m_store.get());
    bool started = false;
    for (int attempt = 0, pauseMs = kServoStartPauseMs; attempt < kServoStartAttempts;
         ++attempt, pauseMs *= 2) {
        if (attempt > 0) {
            // A late reply lands in the pause and is discarded by the next request.
            const timespec pause{0, long(pauseMs) * 1000000L};
            nanosleep(&pause, nullptr);
        }
        started = m_core->start(m_clock->micros());
        if (started)
            break;
    }
    if (!started) {
        m_pty.close();
        return servoStartFailure(m_bus->lastError());
    }
    m_warnings.clear();
    if (m_store && !m_store->warning().isEmpty())
        m_warnings << m_store->warning() + QStringLiteral("; using the defaults.");
    if (m_core->storedBlockRejected())
        m_warnings << QStringLiteral("State file %1 ignored: its parameters are invalid; "
                                     "using the defaults.")
                          .arg(m_config.stateFile);
    if (m_store && !m_store->saveProblem().isEmpty())
        m_warnings << m_store->saveProblem();

    const std::int64_t now = monotonicNs();
    m_shared->windowStartNs = now;
    m_shared->totalStartNs = now;
    m_stopping.store(false);
    m_controlRunning.store(true);
    m_thread = std::thread([this] { controlLoop(); });

    m_notifier = new QSocketNotifier(qintptr(m_pty.master()), QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, [this] { serviceLink(); });
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(kLinkTickMs);
    connect(m_timer, &QTimer::timeout, this, [this] {
        serviceLink();
        m_notifier->setEnabled(true);
    });
    m_timer->start();
    return {};
}

void FirmwareHost::stop()
{
    if (!isRunning())
        return;
    m_stopping.store(true);
    m_thread.join();
    // The control context is gone: the bus is ours now. Torque off, whatever state it is in.
    for (const auto &actuator : m_actuators)
        actuator->disable();
    delete m_notifier;
    m_notifier = nullptr;
    delete m_timer;
    m_timer = nullptr;
    m_pty.close(); // and the link, if still ours
}

void FirmwareHost::emergencyStop() noexcept
{
    m_stopping.store(true);
    // Let the control thread end its cycle, so that no goal follows the torque-off. It never
    // does when the signal hit that very thread: the wait then ends at its bound.
    const timespec millisecond{0, 1000000};
    for (int i = 0; i < kEmergencyWaitMs && m_controlRunning.load(); ++i)
        ::nanosleep(&millisecond, nullptr);
    if (m_servoPort) {
        // Each servo's, twice, 2 ms apart: a packet a dying thread left half-written swallows
        // the first.
        const timespec gap{0, 2000000};
        for (int round = 0; round < 2; ++round) {
            if (round > 0)
                ::nanosleep(&gap, nullptr);
            for (const TorqueOff &off : m_torqueOff) {
                if (off.size > 0)
                    m_servoPort->write({off.bytes.data(), off.size});
            }
        }
    }
    m_pty.removeLinkNow();
}

QString FirmwareHost::createLink(const QString &path)
{
    return m_pty.createLink(path);
}

const FaultInjector *FirmwareHost::faults() const
{
    return m_hostPort ? m_hostPort->faults() : nullptr;
}

void FirmwareHost::serviceLink()
{
    m_core->serviceHost();
    m_hostPort->flush();
    // EOF/EIO keeps the master readable: pause until the next tick instead of spinning.
    if (m_hostPort->takeHangUp())
        m_notifier->setEnabled(false);
}

void FirmwareHost::controlLoop()
{
    sched_param param{};
    param.sched_priority = kControlPriority;
    m_realtime.store(::pthread_setschedparam(::pthread_self(), SCHED_FIFO, &param) == 0);

    const auto periodNs = std::int64_t(std::llround(1e9 / m_config.rateHz));
    std::int64_t next = monotonicNs();
    std::int64_t previousStart = -1;
    while (!m_stopping.load(std::memory_order_relaxed)) {
        next += periodNs;
        const timespec wake = toTimespec(next);
        while (::clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &wake, nullptr) == EINTR) {
        }
        const std::int64_t start = monotonicNs();
        m_core->controlCycle(std::uint32_t(start / 1000));
        const std::int64_t end = monotonicNs();
        // More than a whole period behind (a bus timeout, a preempted thread): start afresh
        // from now rather than running the missed cycles back to back.
        const bool late = end - next > periodNs;
        if (late)
            next = end;
        std::lock_guard lock(m_shared->mutex);
        Shared &s = *m_shared;
        if (previousStart >= 0) {
            s.windowPeriod.add((start - previousStart) / 1000);
            s.totalPeriod.add((start - previousStart) / 1000);
        }
        s.windowBusy.add((end - start) / 1000);
        s.totalBusy.add((end - start) / 1000);
        s.windowLate += late;
        s.totalLate += late;
        s.bus = m_bus->stats();
        s.faulted = false;
        for (int k = 0; k < m_core->axes(); ++k)
            s.faulted = s.faulted || m_core->controller(k).faulted();
        previousStart = start;
    }
    m_controlRunning.store(false);
}

FirmwareHost::Report FirmwareHost::takeReport()
{
    std::lock_guard lock(m_shared->mutex);
    Shared &s = *m_shared;
    const std::int64_t now = monotonicNs();
    Report r;
    r.seconds = double(now - s.windowStartNs) * 1e-9;
    r.cycles = s.windowBusy.count();
    r.periodP50Us = s.windowPeriod.percentileUs(0.5);
    r.periodP99Us = s.windowPeriod.percentileUs(0.99);
    r.periodMaxUs = s.windowPeriod.maxUs();
    r.busyP99Us = s.windowBusy.percentileUs(0.99);
    r.busyMaxUs = s.windowBusy.maxUs();
    r.late = s.windowLate;
    r.busErrors = s.bus.errors() - s.windowErrorBase;
    r.bus = s.bus;
    r.faulted = s.faulted;
    s.windowPeriod.clear();
    s.windowBusy.clear();
    s.windowLate = 0;
    s.windowErrorBase = s.bus.errors();
    s.windowStartNs = now;
    return r;
}

FirmwareHost::Report FirmwareHost::totalReport()
{
    std::lock_guard lock(m_shared->mutex);
    const Shared &s = *m_shared;
    Report r;
    r.seconds = double(monotonicNs() - s.totalStartNs) * 1e-9;
    r.cycles = s.totalBusy.count();
    r.periodP50Us = s.totalPeriod.percentileUs(0.5);
    r.periodP99Us = s.totalPeriod.percentileUs(0.99);
    r.periodMaxUs = s.totalPeriod.maxUs();
    r.busyP99Us = s.totalBusy.percentileUs(0.99);
    r.busyMaxUs = s.totalBusy.maxUs();
    r.late = s.totalLate;
    r.busErrors = s.bus.errors();
    r.bus = s.bus;
    r.faulted = s.faulted;
    return r;
}

} // namespace hatpic
