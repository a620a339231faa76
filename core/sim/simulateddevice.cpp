#include "simulateddevice.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"
#include "fwhost/profileparamstore.h"
#include "model/cyclequantities.h"
#include "sim/emulatedservoport.h"
#include "sim/emulatedsts3032.h"
#include "sim/emulateduart.h"
#include "sim/servoplant.h"

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

namespace hatpic {

namespace {

constexpr double kDefaultControlRate = 1000; //!< [Hz]
constexpr qint64 kLegacyPeriodUs = 200000;   //!< legacy frame period [µs]
constexpr int kLegacyMaxFrameBytes = 64;     //!< bytes kept while waiting for 'o'
constexpr int kTicksPerRev = legacy::Conversion::kTicksPerRev;
constexpr int kLegacyCenterTicks = 1000;
constexpr char kFirmware[] = "hatpic-sim 0.1";

using Traffic = fw::HostPort::Traffic;

QString violationsText(const DeviceParams &p)
{
    QStringList parts;
    for (const Violation &v : validate(p))
        parts.append(QString::fromStdString(v.message()));
    return parts.join(QStringLiteral("; "));
}

//! The clock as the device core reads it between cycles (it stamps SET_FEEDBACK with it):
//! whole µs, wrapping at 2³².
class SimClock : public fw::Clock
{
public:
    explicit SimClock(std::function<std::int64_t()> microseconds)
        : m_microseconds(std::move(microseconds))
    {}
    std::uint32_t micros() override
    {
        return std::uint32_t(std::uint64_t(m_microseconds()) & 0xFFFFFFFFu);
    }

private:
    std::function<std::int64_t()> m_microseconds;
};

//! Ideal mode's actuator: no servo, no quantisation, no noise. The knob *is* the admittance
//! state the control cycle commands, and τ = −τ_op of the hand at that state.
class IdealActuator : public fw::Actuator<double>
{
public:
    explicit IdealActuator(std::function<double(double, double)> operatorTorque)
        : m_operatorTorque(std::move(operatorTorque))
    {}
    void place(double theta) { m_state = {theta, 0.0}; }

    bool start(double &theta) override
    {
        theta = m_state.theta;
        return true;
    }
    bool measure(fw::Measurement<double> &m) override
    {
        m = {m_state.theta, m_state.omega, -m_operatorTorque(m_state.theta, m_state.omega)};
        return true;
    }
    bool command(double theta, double omega) override
    {
        m_state = {theta, omega};
        return true;
    }
    void disable() override {}

private:
    std::function<double(double, double)> m_operatorTorque;
    AdmittanceState m_state;
};

} // namespace

class SimulatedDevice::Private
{
public:
    explicit Private(const Config &c);

    void receive(QByteArrayView bytes);
    void receiveLegacy(QByteArrayView bytes);
    //! The knob's frame: the master firmware's, or the IMU branch's with every knob (knob 1's
    //! servo read `knob1` [rad] this cycle) and the tilt.
    QByteArray legacyDeviceFrame(double knob1) const;
    //! Passes the host's frame on to knobs 2–4 of an IMU-branch board, as each one's field A.
    void forwardToOtherKnobs(QByteArrayView bytes);
    Cycle runCycle();
    void runPlant(double t);

    qint64 cycleMicros(quint64 n) const { return std::llround(double(n) * 1e6 / rate); }
    int legacyTicks() const;
    quint16 linkLimitedRate() const;
    double handTorque(double theta, double omega) const
    {
        return hand.torque(cycleTime - handStart, theta, omega);
    }

    Config config;
    std::function<void(const Cycle &)> cycleObserver;
    double rate = kDefaultControlRate; //!< control rate [Hz]
    double period = 1e-3;              //!< control period h [s]
    int subSteps = 10;                 //!< plant sub-steps per control cycle
    double tauLimit = 0.44;            //!< [N·m]

    quint64 cycles = 0;   //!< control cycles run (cycle n happens at n·h)
    double clock = 0;     //!< simulated time [s]
    double cycleTime = 0; //!< time of the cycle running now [s]
    HandInput hand;
    double handStart = 0; //!< simulated time at which the hand input's t = 0 [s]
    Cycle last;

    // The hardware around the device core: knob and servo (or the ideal model), the bus,
    // the USB link, the clock and the flash.
    ServoPlant plant;
    std::optional<EmulatedSts3032> servo;
    std::optional<EmulatedServoPort> servoPort;
    std::optional<fw::StsBus> bus;
    std::optional<fw::StsActuator<double>> stsActuator;
    std::optional<IdealActuator> idealActuator;
    EmulatedUart uart;
    // The start of the next cycle to run, not the simulated time: cycle n runs once the clock
    // has passed its end, (n+1)·h, but renders from n·h on. A SET_FEEDBACK that arrives
    // meanwhile is rendered from cycle n on, so it is stamped n·h; stamped with the clock, the
    // watchdog held τ_ext up to one period longer than its 200 ms (issue 27).
    SimClock simClock{[this] { return cycleMicros(cycles); }};
    std::optional<ProfileParamStore> store; //!< SAVE_PARAMS into a profile (simulator.md § 7)

    // v2: our firmware's device core. Legacy: the published firmware's protocol around the
    // same control cycle.
    std::optional<fw::DeviceCore<double>> core;
    std::optional<fw::Controller<double>> legacyController;

    bool legacyWaiting = false; //!< an 'i' is unmatched: the firmware's loop is stuck
    QByteArray legacyFrame;
    qint64 nextLegacyUs = kLegacyPeriodUs;
    legacy::Conversion legacyConversion;
    quint64 legacyDropped = 0;
    //! The IMU branch's knobs 2–4, each the published firmware's spring on its own servo: a
    //! single legacy knob of its own, stepped with this one (empty for a single knob).
    std::vector<std::unique_ptr<SimulatedDevice>> otherKnobs;
    std::vector<double> otherAngles; //!< their servos' last readings [rad]
    double roll = 0;                 //!< the board's tilt [rad]
    double pitch = 0;
    QString stateWarning;
    QString saveWarning;
};

SimulatedDevice::Private::Private(const Config &c)
    : config(c), plant(0.44), uart(c.baud > 0 ? c.baud : defaultBaud(c.wireProtocol()), c.throttle)
{
    config.protocol = c.wireProtocol();
    if (c.board == Board::ImuBranch) {
        for (const HandInput &other : c.otherHands) {
            Config knob = c;
            knob.board = Board::Knob;
            knob.protocol = WireProtocol::Legacy;
            knob.hand = other;
            knob.faults = {};
            knob.throttle = false; // its own frames are not sent: this board's are
            knob.seed = c.seed + otherKnobs.size() + 1;
            otherKnobs.push_back(std::make_unique<SimulatedDevice>(knob));
        }
        otherAngles.assign(otherKnobs.size(), 0.0);
        roll = c.roll;
        pitch = c.pitch;
    }
    if (std::isfinite(c.controlRateHz) && c.controlRateHz > 0)
        rate = std::clamp(c.controlRateHz, fw::DeviceCore<double>::kMinControlRate,
                          fw::DeviceCore<double>::kMaxControlRate);
    period = 1.0 / rate;
    subSteps = std::max(1, int(std::ceil(ServoPlant::kMinSubStepRate * period - 1e-9)));
    if (std::isfinite(c.tauLimit) && c.tauLimit > 0)
        tauLimit = c.tauLimit;
    legacyConversion.centerTicks = kLegacyCenterTicks;
    legacyConversion.tauLimit = tauLimit;
    hand = c.hand;

    fw::Actuator<double> *actuator = nullptr;
    if (c.ideal) {
        idealActuator.emplace(
            [this](double theta, double omega) { return handTorque(theta, omega); });
        actuator = &*idealActuator;
    } else {
        EmulatedSts3032::Config sc;
        sc.centerTick = kLegacyCenterTicks;
        sc.tauLimit = tauLimit;
        sc.noise = c.noise;
        sc.seed = c.seed;
        servo.emplace(plant, sc);
        servoPort.emplace(*servo);
        bus.emplace(*servoPort);
        fw::StsActuator<double>::Config ac;
        ac.centerTick = kLegacyCenterTicks;
        ac.tauLimit = tauLimit;
        stsActuator.emplace(*bus, ac);
        actuator = &*stsActuator;
    }

    fw::Controller<double>::Config control;
    control.rateHz = rate;
    control.tauLimit = tauLimit;

    const DeviceParams configured = roundedToFloat(c.params);
    if (firstViolatingField(configured) >= 0)
        stateWarning = QStringLiteral("The power-up parameters are invalid (%1); using the "
                                      "defaults.")
                           .arg(violationsText(configured));

    DeviceParams powerUp;
    if (config.protocol == WireProtocol::V2) {
        if (!c.stateFile.isEmpty()) {
            store.emplace(c.stateFile, QStringLiteral("hatpic-sim"), tauLimit);
            saveWarning = store->saveProblem();
        }
        fw::DeviceCore<double>::Config dc;
        dc.control = control;
        dc.deviceId = c.deviceId;
        dc.firmware = kFirmware;
        dc.linkLimitHz = c.throttle ? linkLimitedRate() : 0;
        dc.powerUp = c.params;
        dc.powerUpPassivity = c.passivity;
        core.emplace(dc, uart, *actuator, simClock, store ? &*store : nullptr);
        powerUp = core->loadParams();
        if (store && !store->warning().isEmpty())
            stateWarning = store->warning();
        if (core->storedBlockRejected()) {
            fw::StoredSettings stored;
            store->load(stored);
            stateWarning = QStringLiteral("State file %1 ignored: %2")
                               .arg(store->path(), violationsText(roundedToFloat(stored.params)));
        }
    } else {
        control.watchdogUs = 0; // the published firmware has no watchdog
        powerUp =
            firstViolatingField(configured) >= 0 ? roundedToFloat(DeviceParams{}) : configured;
        legacyController.emplace(control, *actuator);
    }

    // The knob rests at θ0 at power-up; the firmware then finds it there.
    plant = ServoPlant(tauLimit, powerUp.theta0);
    if (idealActuator)
        idealActuator->place(powerUp.theta0);
    if (core)
        core->start(0);
    else
        legacyController->start(powerUp, 0);
    last.theta = core ? core->controller().last().theta : legacyController->last().theta;

    if (config.protocol == WireProtocol::Legacy) {
        const QByteArray pos = QByteArray::number(legacyTicks());
        uart.write(QByteArray("STS3032 Torque control\r\nCurrent pos motor : " + pos + "\r\n" +
                              pos + "\r\n"),
                   Traffic::Reply);
    }
}

int SimulatedDevice::Private::legacyTicks() const
{
    const long long ticks =
        std::llround(plant.theta() * kTicksPerRev / (2.0 * std::numbers::pi)) + kLegacyCenterTicks;
    return int(((ticks % kTicksPerRev) + kTicksPerRev) % kTicksPerRev);
}

quint16 SimulatedDevice::Private::linkLimitedRate() const
{
    // The device core has the effects and passivity capabilities: its TELEMETRY carries τ_fx,
    // τ_pc and R (43 bytes).
    const double frames = double(uart.baud()) / 10.0 / double(v2::telemetryWireBytes(true, true));
    return quint16(std::clamp(std::floor(frames), 0.0, 65535.0));
}

void SimulatedDevice::Private::receive(QByteArrayView bytes)
{
    if (config.protocol == WireProtocol::Legacy) {
        receiveLegacy(bytes);
        return;
    }
    uart.fromHost(bytes);
    core->serviceHost();
}

void SimulatedDevice::Private::receiveLegacy(QByteArrayView bytes)
{
    // The published firmware ignores bytes until an 'i', then reads until an 'o' and parses
    // what it collected. While it waits for the 'o' its loop does nothing else.
    for (const char c : bytes) {
        if (!legacyWaiting) {
            if (c == 'i') {
                legacyWaiting = true;
                legacyFrame = QByteArray(1, c);
                forwardToOtherKnobs("i"); // the whole board's loop waits
            }
            continue;
        }
        if (legacyFrame.size() < kLegacyMaxFrameBytes)
            legacyFrame.append(c);
        if (c != 'o')
            continue;
        legacyWaiting = false;
        legacy::Decoder parser;
        QList<legacy::Frame> frames;
        if (legacyFrame.endsWith('o'))
            parser.feed(legacyFrame, frames);
        if (frames.size() == 1) {
            const legacy::Frame &frame = frames.first();
            const double tauExt = legacyConversion.fieldToFeedback(frame.a);
            if (std::isfinite(tauExt))
                legacyController->setFeedback(tauExt, 0);
            // The branch adds field n − 1000 to servo n's torque: knob n's field A.
            const std::array<int, 4> fields = frame.fields();
            for (std::size_t k = 0; k < otherKnobs.size(); ++k) {
                const QByteArray rest = legacy::encodeFrame({fields[k + 1], 0, 0, 0}).mid(1);
                otherKnobs[k]->receive(rest);
            }
        } else {
            forwardToOtherKnobs("o"); // "io": nothing they act on, and they go on
        }
        legacyFrame.clear();
    }
}

void SimulatedDevice::Private::forwardToOtherKnobs(QByteArrayView bytes)
{
    for (const auto &knob : otherKnobs)
        knob->receive(bytes);
}

QByteArray SimulatedDevice::Private::legacyDeviceFrame(double knob1) const
{
    if (otherKnobs.empty())
        return legacy::encodeFrame({legacyTicks(), 1000, 1000, 1000});
    // The branch's P1…P4: each servo's reading minus its offset (the centre tick here).
    legacy::Frame frame{legacy::imuBranchField(knob1), legacy::imuBranchField(otherAngles[0]),
                        legacy::imuBranchField(otherAngles[1]),
                        legacy::imuBranchField(otherAngles[2])};
    frame.tilt = legacy::Tilt{legacy::TiltConversion::rollToField(roll),
                              legacy::TiltConversion::pitchToField(pitch)};
    return legacy::encodeFrame(frame);
}

void SimulatedDevice::Private::runPlant(double t)
{
    if (config.ideal)
        return;
    const double dt = period / subSteps;
    for (int i = 0; i < subSteps; ++i) {
        const double tauOp = hand.torque(t + i * dt - handStart, plant.theta(), plant.omega());
        plant.step(dt, tauOp);
    }
}

SimulatedDevice::Cycle SimulatedDevice::Private::runCycle()
{
    const quint64 n = cycles++;
    const double t = double(n) * period;
    const qint64 tUs = cycleMicros(n);
    cycleTime = t;

    for (std::size_t k = 0; k < otherKnobs.size(); ++k) {
        otherAngles[k] = otherKnobs[k]->step().theta;
        otherKnobs[k]->takeOutput(); // its own frames: this board sends the branch's
    }
    if (legacyController && legacyWaiting) {
        // The firmware is stuck waiting for 'o': no control, no frames. The servo keeps
        // holding its last position command on its own.
        runPlant(t);
        uart.transfer(period);
        return last;
    }

    const auto now = std::uint32_t(quint64(tUs) & 0xFFFFFFFFu);
    const fw::CycleRecord<double> &r =
        core ? core->controlCycle(now) : legacyController->cycle(now);
    const Cycle c{r, t};

    if (core) {
        core->serviceHost(); // the link context sends this cycle's telemetry
    } else if (tUs >= nextLegacyUs) {
        nextLegacyUs += kLegacyPeriodUs;
        if (nextLegacyUs <= tUs)
            nextLegacyUs = tUs + kLegacyPeriodUs;
        if (!uart.write(QByteArray(legacyDeviceFrame(r.theta) + "\r\n"), Traffic::Stream))
            ++legacyDropped;
    }

    runPlant(t);
    uart.transfer(period);
    last = c;
    if (cycleObserver)
        cycleObserver(c);
    return c;
}

// ---- public API ----

Sample SimulatedDevice::Cycle::toSample() const
{
    Sample sample;
    sample.t_s = t;
    sample.tau_total = tau_total;
    forEachCycleQuantity<Sample, Cycle>(
        [&](const CycleQuantity &, auto to, auto from) { sample.*to = this->*from; });
    return sample;
}

SimulatedDevice::SimulatedDevice(const Config &config) : d(std::make_unique<Private>(config)) {}

SimulatedDevice::~SimulatedDevice() = default;

void SimulatedDevice::receive(QByteArrayView bytes)
{
    d->receive(bytes);
}

void SimulatedDevice::advance(double dt)
{
    if (!(dt > 0) || !std::isfinite(dt))
        return;
    d->clock += dt;
    // Cycle n covers [n·h, (n+1)·h); it has run once the clock has passed its end.
    while (double(d->cycles + 1) * d->period <= d->clock * (1.0 + 1e-12))
        d->runCycle();
}

SimulatedDevice::Cycle SimulatedDevice::step()
{
    const Cycle c = d->runCycle();
    d->clock = std::max(d->clock, double(d->cycles) * d->period);
    return c;
}

QByteArray SimulatedDevice::takeOutput()
{
    return d->uart.take();
}

void SimulatedDevice::setCycleObserver(std::function<void(const Cycle &)> observer)
{
    d->cycleObserver = std::move(observer);
}

void SimulatedDevice::setHand(const HandInput &hand)
{
    d->hand = hand;
    d->handStart = double(d->cycles) * d->period; // t = 0 at the next control cycle
}

HandInput SimulatedDevice::hand() const
{
    return d->hand;
}

void SimulatedDevice::setHand(int knob, const HandInput &hand)
{
    if (knob == 1)
        setHand(hand);
    else if (knob >= 2 && knob <= knobs())
        d->otherKnobs[std::size_t(knob - 2)]->setHand(hand);
}

void SimulatedDevice::setTilt(double roll, double pitch)
{
    if (d->otherKnobs.empty())
        return;
    d->roll = roll;
    d->pitch = pitch;
}

int SimulatedDevice::knobs() const
{
    return 1 + int(d->otherKnobs.size());
}

std::vector<double> SimulatedDevice::knobAngles() const
{
    std::vector<double> angles{d->last.theta};
    angles.insert(angles.end(), d->otherAngles.begin(), d->otherAngles.end());
    return angles;
}

const SimulatedDevice::Config &SimulatedDevice::config() const
{
    return d->config;
}

DeviceParams SimulatedDevice::params() const
{
    return d->core ? d->core->params() : d->legacyController->params();
}

double SimulatedDevice::time() const
{
    return d->clock;
}

qint32 SimulatedDevice::baud() const
{
    return d->uart.baud();
}

quint16 SimulatedDevice::streamRate() const
{
    return d->core ? d->core->streamRate() : 0;
}

bool SimulatedDevice::feedbackStale() const
{
    return d->last.flags & v2::kFlagFeedbackStale;
}

quint16 SimulatedDevice::linkLimitedRate() const
{
    return d->linkLimitedRate();
}

quint64 SimulatedDevice::telemetryDropped() const
{
    return d->core ? d->core->telemetryDropped() : d->legacyDropped;
}

quint64 SimulatedDevice::paramsApplied() const
{
    return d->core ? d->core->paramsApplied() : 0;
}

QString SimulatedDevice::stateWarning() const
{
    return d->stateWarning;
}

QString SimulatedDevice::saveWarning() const
{
    return d->saveWarning;
}

std::unique_ptr<FaultInjector> makeFaultInjector(const SimulatedDevice::Config &config)
{
    if (config.faults.isEmpty())
        return nullptr;
    return std::make_unique<FaultInjector>(config.faults, config.seed,
                                           config.wireProtocol() == WireProtocol::Legacy
                                               ? FaultInjector::Framing::Legacy
                                               : FaultInjector::Framing::V2);
}

} // namespace hatpic
