#include "simulateddevice.h"

#include "device/servoplant.h"
#include "model/stiffness.h"
#include "profile/profile.h"

#include <QFileInfo>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace hatpic {

QString wireProtocolName(WireProtocol protocol)
{
    return protocol == WireProtocol::Legacy ? QStringLiteral("legacy") : QStringLiteral("v2");
}

namespace {

constexpr qint32 kDefaultBaudV2 = 921600;
constexpr qint32 kDefaultBaudLegacy = 115200;
constexpr double kDefaultControlRate = 1000;     //!< [Hz]
constexpr double kMaxControlRate = 65535;        //!< max_stream_hz is a u16 [Hz]
constexpr qint64 kWatchdogUs = 200000;           //!< feedback watchdog [µs]
constexpr qint64 kLegacyPeriodUs = 200000;       //!< legacy frame period [µs]
constexpr int kTelemetryWireBytes = 31;          //!< 29-byte packet + COBS + delimiter
constexpr qsizetype kTxQueueBytes = 8 * 1024;    //!< the UART TX buffer
constexpr qsizetype kReplyReserveBytes = 512;    //!< extra room only replies may use
constexpr qsizetype kDeliveredBytes = 64 * 1024; //!< carried but not yet taken
constexpr int kLegacyMaxFrameBytes = 64;         //!< bytes kept while waiting for 'o'
constexpr int kTicksPerRev = legacy::Conversion::kTicksPerRev;
constexpr int kLegacyCenterTicks = 1000;
const char kFirmware[] = "hatpic-sim 0.1";

double f32(double v)
{
    return double(float(v));
}

DeviceParams roundedToF32(DeviceParams p)
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        p.setField(i, f32(p.field(i)));
    return p;
}

QString violationsText(const DeviceParams &p)
{
    QStringList parts;
    for (const Violation &v : validate(p))
        parts.append(QString::fromStdString(v.message()));
    return parts.join(QStringLiteral("; "));
}

} // namespace

class SimulatedDevice::Private
{
public:
    explicit Private(const Config &c);

    void receive(QByteArrayView bytes);
    void handleFrame(const v2::Frame &frame);
    QByteArray replyTo(const v2::Frame &frame);
    void receiveLegacy(QByteArrayView bytes);

    Cycle runCycle();
    void runPlant(double t);
    void transferLink(double dt);
    void enqueue(const QByteArray &bytes, bool telemetry);
    QByteArray reply(const v2::Message &message);

    qint64 cycleMicros(quint64 n) const { return std::llround(double(n) * 1e6 / rate); }
    double measureTheta() const;
    double measureOmega() const;
    double measureTau();
    int legacyTicks() const;
    quint16 maxStreamHz() const { return quint16(std::floor(rate)); }
    quint16 linkLimitedRate() const;

    Config config;
    double rate = kDefaultControlRate; //!< control rate [Hz]
    double period = 1e-3;              //!< control period h [s]
    int subSteps = 10;                 //!< plant sub-steps per control cycle
    qint32 baud = kDefaultBaudV2;
    double tauLimit = 0.44; //!< [N·m]

    quint64 cycles = 0; //!< control cycles run (cycle n happens at n·h)
    double clock = 0;   //!< simulated time [s]

    DeviceParams params;   //!< in force during the current cycle
    DeviceParams accepted; //!< latest accepted block; in force from the next cycle
    DeviceParams flash;    //!< saved block (the state file's content when there is one)
    AdmittanceState admittance;
    ServoPlant plant;
    Cycle last;
    double lastTheta = 0; //!< angle measured by the latest cycle [rad]

    HandInput hand;
    double handStart = 0; //!< simulated time at which the hand input's t = 0 [s]

    double feedback = 0;       //!< latest τ_ext received [N·m]
    qint64 lastFeedbackUs = 0; //!< when it arrived (power-up counts as one) [µs]
    bool stale = false;

    quint16 stream = 0;
    double streamPhase = 0;
    quint8 telemetrySeq = 0;
    quint8 replySeq = 0;
    quint64 dropped = 0;

    bool haveLastCommand = false;
    quint8 lastType = 0;
    quint8 lastSeq = 0;
    QByteArray lastReply;
    v2::FrameDecoder decoder{v2::Direction::FromHost};

    bool legacyWaiting = false; //!< an 'i' is unmatched: the firmware's loop is stuck
    QByteArray legacyFrame;
    qint64 nextLegacyUs = kLegacyPeriodUs;
    legacy::Conversion legacyConversion;

    QByteArray txQueue;
    QByteArray delivered;
    double credit = 0; //!< bytes the link may still carry in the current cycle

    std::mt19937_64 rng;
    std::normal_distribution<double> noise{0.0, 1.0};
    QString stateWarning;
};

SimulatedDevice::Private::Private(const Config &c) : config(c), plant(0.44), rng(c.seed)
{
    if (std::isfinite(c.controlRateHz) && c.controlRateHz > 0)
        rate = std::min(c.controlRateHz, kMaxControlRate);
    period = 1.0 / rate;
    subSteps = std::max(1, int(std::ceil(ServoPlant::kMinSubStepRate * period - 1e-9)));
    baud = c.baud > 0 ? c.baud
                      : (c.protocol == WireProtocol::Legacy ? kDefaultBaudLegacy : kDefaultBaudV2);
    if (std::isfinite(c.tauLimit) && c.tauLimit > 0)
        tauLimit = c.tauLimit;
    legacyConversion.centerTicks = kLegacyCenterTicks;
    legacyConversion.tauLimit = tauLimit;

    params = roundedToF32(c.params);
    if (firstViolatingField(params) >= 0) {
        stateWarning = QStringLiteral("The power-up parameters are invalid (%1); using the "
                                      "defaults.")
                           .arg(violationsText(params));
        params = roundedToF32(DeviceParams{});
    }
    if (c.protocol == WireProtocol::V2 && !c.stateFile.isEmpty() &&
        QFileInfo::exists(c.stateFile)) {
        const ProfileReadResult read = readProfile(c.stateFile);
        if (!read.ok()) {
            stateWarning = QStringLiteral("State file %1 ignored: %2")
                               .arg(c.stateFile, read.errors.join(QStringLiteral("; ")));
        } else {
            const DeviceParams stored = roundedToF32(read.profile->device);
            if (firstViolatingField(stored) >= 0) {
                stateWarning = QStringLiteral("State file %1 ignored: %2")
                                   .arg(c.stateFile, violationsText(stored));
            } else {
                params = stored;
            }
        }
    }
    accepted = params;
    flash = params;

    admittance.theta = params.theta0;
    admittance.omega = 0;
    plant = ServoPlant(tauLimit, params.theta0);
    hand = c.hand;
    lastTheta = measureTheta();
    last.theta = lastTheta;

    if (c.protocol == WireProtocol::Legacy) {
        const QByteArray pos = QByteArray::number(legacyTicks());
        enqueue("STS3032 Torque control\r\nCurrent pos motor : " + pos + "\r\n" + pos + "\r\n",
                false);
    }
}

// ---- measurement ----

double SimulatedDevice::Private::measureTheta() const
{
    if (config.ideal)
        return admittance.theta;
    // Multi-turn tick count as the firmware keeps it, converted in single precision.
    const double ticks = std::round(plant.theta() * kTicksPerRev / (2.0 * std::numbers::pi));
    return f32(ticks * (2.0 * std::numbers::pi / kTicksPerRev));
}

double SimulatedDevice::Private::measureOmega() const
{
    if (config.ideal)
        return admittance.omega;
    // The servo reports its speed in ticks/s.
    const double tickRate = std::round(plant.omega() * kTicksPerRev / (2.0 * std::numbers::pi));
    return f32(tickRate * (2.0 * std::numbers::pi / kTicksPerRev));
}

double SimulatedDevice::Private::measureTau()
{
    double load = plant.motorTorque();
    if (config.noise > 0 && std::isfinite(config.noise))
        load += config.noise * noise(rng);
    // The load register counts 0.1 % of the rated torque and saturates at ±100 %.
    const double quantum = tauLimit * 1e-3;
    load = std::clamp(std::round(load / quantum) * quantum, -tauLimit, tauLimit);
    return f32(load);
}

int SimulatedDevice::Private::legacyTicks() const
{
    const long long ticks =
        std::llround(plant.theta() * kTicksPerRev / (2.0 * std::numbers::pi)) + kLegacyCenterTicks;
    return int(((ticks % kTicksPerRev) + kTicksPerRev) % kTicksPerRev);
}

quint16 SimulatedDevice::Private::linkLimitedRate() const
{
    const double frames = double(baud) / 10.0 / kTelemetryWireBytes;
    return quint16(std::clamp(std::floor(frames), 0.0, 65535.0));
}

// ---- link ----

void SimulatedDevice::Private::enqueue(const QByteArray &bytes, bool telemetry)
{
    const qsizetype room = kTxQueueBytes + (telemetry ? 0 : kReplyReserveBytes);
    if (txQueue.size() + bytes.size() > room) {
        if (telemetry)
            ++dropped;
        return;
    }
    txQueue.append(bytes);
    if (!config.throttle)
        transferLink(0);
}

void SimulatedDevice::Private::transferLink(double dt)
{
    const qsizetype space = kDeliveredBytes - delivered.size();
    qsizetype n = 0;
    if (!config.throttle) {
        n = std::min(txQueue.size(), space);
    } else {
        credit += dt * baud / 10.0;
        n = std::min({qsizetype(std::floor(credit)), txQueue.size(), space});
        credit -= double(n);
    }
    if (n > 0) {
        delivered.append(txQueue.left(n));
        txQueue.remove(0, n);
    }
    // An idle UART cannot send bytes later for time it spent idle.
    if (txQueue.isEmpty() || delivered.size() >= kDeliveredBytes)
        credit = std::min(credit, 1.0);
}

QByteArray SimulatedDevice::Private::reply(const v2::Message &message)
{
    return v2::encodeFrame(replySeq++, message);
}

// ---- host input ----

void SimulatedDevice::Private::receive(QByteArrayView bytes)
{
    if (config.protocol == WireProtocol::Legacy) {
        receiveLegacy(bytes);
        return;
    }
    QList<v2::Frame> frames;
    decoder.feed(bytes, frames);
    for (const v2::Frame &frame : std::as_const(frames))
        handleFrame(frame);
}

void SimulatedDevice::Private::handleFrame(const v2::Frame &frame)
{
    if (const auto *fb = std::get_if<v2::SetFeedback>(&frame.message)) {
        // A stream, not a command: applied whatever its seq. A non-finite value is ignored
        // (it would poison the admittance state) and does not feed the watchdog.
        if (std::isfinite(fb->tauExt)) {
            feedback = fb->tauExt;
            lastFeedbackUs = std::llround(clock * 1e6);
        }
        return;
    }
    const quint8 type = v2::messageType(frame.message);
    if (haveLastCommand && type == lastType && frame.seq == lastSeq) {
        enqueue(lastReply, false); // a retry: answer again, apply nothing
        return;
    }
    const QByteArray answer = replyTo(frame);
    if (answer.isEmpty())
        return;
    haveLastCommand = true;
    lastType = type;
    lastSeq = frame.seq;
    lastReply = answer;
    enqueue(answer, false);
}

QByteArray SimulatedDevice::Private::replyTo(const v2::Frame &frame)
{
    const auto ack = [&](v2::AckStatus status, quint8 field = v2::kNoField) {
        return reply(v2::Ack{frame.seq, status, field});
    };
    const v2::Message &m = frame.message;
    if (std::holds_alternative<v2::Hello>(m)) {
        stream = 0;
        v2::HelloReply hello;
        hello.protocolVersion = v2::kProtocolVersion;
        hello.maxStreamHz = maxStreamHz();
        hello.deviceId = config.deviceId;
        hello.tauLimit = float(tauLimit);
        hello.firmware.assign(kFirmware);
        return reply(hello);
    }
    if (std::holds_alternative<v2::GetParams>(m))
        return reply(v2::Params{accepted});
    if (const auto *set = std::get_if<v2::SetParams>(&m)) {
        const DeviceParams block = roundedToF32(set->params);
        const int field = firstViolatingField(block);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, quint8(field));
        accepted = block; // in force from the next control cycle
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *set = std::get_if<v2::SetStream>(&m)) {
        quint16 hz = std::min(set->rateHz, maxStreamHz());
        if (config.throttle)
            hz = std::min(hz, linkLimitedRate());
        stream = hz;
        streamPhase = rate - hz; // the next cycle sends the first frame
        return ack(v2::AckStatus::Ok);
    }
    if (std::holds_alternative<v2::SaveParams>(m)) {
        if (!config.stateFile.isEmpty()) {
            Profile profile;
            profile.name = QStringLiteral("hatpic-sim state");
            profile.notes = QStringLiteral("Parameters saved by the simulated device "
                                           "(SAVE_PARAMS).");
            profile.device = accepted;
            profile.host.tau_limit = tauLimit;
            if (!writeProfile(profile, config.stateFile).isEmpty())
                return ack(v2::AckStatus::StorageError);
        }
        flash = accepted;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *ping = std::get_if<v2::Ping>(&m))
        return reply(v2::Pong{ping->token});
    if (std::holds_alternative<v2::Zero>(m)) {
        DeviceParams candidate = accepted;
        candidate.theta0 = f32(lastTheta);
        const int field = firstViolatingField(candidate);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, quint8(field));
        accepted = candidate;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *refused = std::get_if<v2::Refused>(&m))
        return ack(refused->status);
    // A device → host message type cannot come out of a FromHost decoder; refuse it anyway.
    return ack(v2::AckStatus::UnknownType);
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
            }
            continue;
        }
        if (legacyFrame.size() < kLegacyMaxFrameBytes)
            legacyFrame.append(c);
        if (c != 'o')
            continue;
        legacyWaiting = false;
        if (legacyFrame.endsWith('o')) {
            legacy::Decoder parser;
            QList<legacy::Frame> frames;
            parser.feed(legacyFrame, frames);
            if (frames.size() == 1) {
                const double tauExt = legacyConversion.fieldToFeedback(frames.first().a);
                if (std::isfinite(tauExt))
                    feedback = tauExt;
            }
        }
        legacyFrame.clear();
    }
}

// ---- control loop ----

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

    if (config.protocol == WireProtocol::Legacy && legacyWaiting) {
        // The firmware is stuck waiting for 'o': no control, no frames. The servo keeps
        // holding its last position command on its own.
        runPlant(t);
        transferLink(period);
        return last;
    }

    params = accepted; // a new block takes effect here, whole
    if (config.protocol == WireProtocol::V2) {
        stale = tUs - lastFeedbackUs >= kWatchdogUs;
    } else {
        stale = false; // the published firmware has no watchdog
    }
    const double tauExt = stale ? 0.0 : feedback;

    Cycle c;
    c.t = t;
    c.theta = measureTheta();
    c.omega = measureOmega();
    c.tau = config.ideal ? -hand.torque(t - handStart, c.theta, c.omega) : measureTau();
    c.tau_rec = recenteringTorque(params, c.theta);
    c.tau_ext = tauExt;
    const double sum = c.tau_rec + tauExt;
    c.tau_total = std::clamp(sum, -tauLimit, tauLimit);
    switch (stiffnessZone(params, c.theta)) {
    case StiffnessZone::DeadZone:
        c.flags |= v2::kFlagDeadZone;
        break;
    case StiffnessZone::Notch:
        c.flags |= v2::kFlagNotch;
        break;
    case StiffnessZone::Outer:
        break;
    }
    if (std::abs(sum) > tauLimit)
        c.flags |= v2::kFlagSaturated;
    if (stale)
        c.flags |= v2::kFlagFeedbackStale;
    lastTheta = c.theta;

    // Admittance step (exact ZOH); its position is the servo's next command.
    const double u = -c.tau + c.tau_total;
    admittance = admittanceStep(params, admittance, u, period);
    plant.setCommand(admittance.theta);

    if (config.protocol == WireProtocol::V2) {
        if (stream > 0) {
            streamPhase += stream;
            if (streamPhase >= rate) {
                streamPhase -= rate;
                v2::Telemetry tm;
                tm.t_us = quint32(quint64(tUs) & 0xFFFFFFFFu);
                tm.theta = float(c.theta);
                tm.omega = float(c.omega);
                tm.tau = float(c.tau);
                tm.tau_rec = float(c.tau_rec);
                tm.tau_ext = float(c.tau_ext);
                tm.flags = c.flags;
                const quint8 seq = telemetrySeq++; // a dropped frame still uses its seq
                enqueue(v2::encodeFrame(seq, tm), true);
            }
        }
    } else if (tUs >= nextLegacyUs) {
        nextLegacyUs += kLegacyPeriodUs;
        if (nextLegacyUs <= tUs)
            nextLegacyUs = tUs + kLegacyPeriodUs;
        const legacy::Frame frame{legacyTicks(), 1000, 1000, 1000};
        enqueue(legacy::encodeFrame(frame) + "\r\n", true);
    }

    runPlant(t);
    transferLink(period);
    last = c;
    return c;
}

// ---- public API ----

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
    QByteArray out;
    out.swap(d->delivered);
    return out;
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

const SimulatedDevice::Config &SimulatedDevice::config() const
{
    return d->config;
}

DeviceParams SimulatedDevice::params() const
{
    return d->accepted;
}

double SimulatedDevice::time() const
{
    return d->clock;
}

qint32 SimulatedDevice::baud() const
{
    return d->baud;
}

quint16 SimulatedDevice::streamRate() const
{
    return d->stream;
}

bool SimulatedDevice::feedbackStale() const
{
    return d->stale;
}

quint16 SimulatedDevice::linkLimitedRate() const
{
    return d->linkLimitedRate();
}

quint64 SimulatedDevice::telemetryDropped() const
{
    return d->dropped;
}

QString SimulatedDevice::stateWarning() const
{
    return d->stateWarning;
}

} // namespace hatpic
