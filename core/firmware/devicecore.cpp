#include "devicecore.h"

#include "model/cyclequantities.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace hatpic::fw {

namespace {

bool valid(const DeviceParams &p)
{
    return firstViolatingField(p) < 0;
}

} // namespace

template<typename T>
DeviceCore<T>::DeviceCore(const Config &config, HostPort &host, Actuator<T> &actuator, Clock &clock,
                          ParamStore *store)
    : m_config(config), m_host(host), m_clock(clock), m_store(store),
      m_controller(config.control, actuator)
{
    m_maxStreamHz = std::uint16_t(std::floor(std::min(config.control.rateHz, kMaxControlRate)));
}

template<typename T> const DeviceParams &DeviceCore<T>::loadParams()
{
    m_loaded = true;
    m_storedRejected = false;
    DeviceParams params = roundedToFloat(m_config.powerUp);
    m_powerUp = PowerUp::Configured;
    if (!valid(params)) {
        params = roundedToFloat(DeviceParams{});
        m_powerUp = PowerUp::Defaults;
    }
    // The defaults' ±π are not floats: kept as the nearest floats inside the range.
    EffectParams effects = roundedForWire(EffectParams{}, m_config.control.tauLimit);
    PassivityParams passivity = roundedForWire(m_config.powerUpPassivity);
    if (firstViolatingField(passivity) >= 0)
        passivity = roundedForWire(PassivityParams{});
    StoredSettings stored;
    if (m_store && m_store->load(stored)) {
        const DeviceParams candidate = roundedToFloat(stored.params);
        const EffectParams candidateFx = roundedForWire(stored.effects, m_config.control.tauLimit);
        const PassivityParams candidatePc = roundedForWire(stored.passivity);
        if (valid(candidate) && firstViolatingField(candidateFx, m_config.control.tauLimit) < 0 &&
            firstViolatingField(candidatePc) < 0) {
            params = candidate;
            effects = candidateFx;
            passivity = candidatePc;
            m_powerUp = PowerUp::Stored;
        } else {
            m_storedRejected = true;
        }
    }
    m_accepted = params;
    m_effects = effects;
    m_passivity = passivity;
    m_flash = StoredSettings{params, effects, passivity};
    m_lastTheta.store(float(params.theta0));
    return m_accepted;
}

template<typename T> bool DeviceCore<T>::start(std::uint32_t nowUs)
{
    if (!m_loaded)
        loadParams();
    m_controller.setEffects(m_effects);
    m_controller.setPassivity(m_passivity);
    const bool ok = m_controller.start(m_accepted, nowUs);
    m_lastTheta.store(float(m_controller.last().theta));
    return ok;
}

// ---- link context ----

template<typename T> void DeviceCore<T>::serviceHost()
{
    std::array<std::uint8_t, 64> chunk;
    for (;;) {
        const std::size_t n = m_host.read(chunk);
        if (n == 0)
            break;
        m_decoder.feed(std::span<const std::uint8_t>(chunk.data(), n),
                       [this](const v2::Frame &frame) { handleFrame(frame); });
    }
    Event event;
    while (m_events.pop(event)) {
        if (event == Event::BusFault)
            sendLog("servo bus: 100 consecutive errors, torque disabled");
    }
    sendTelemetry();
}

template<typename T> void DeviceCore<T>::handleFrame(const v2::Frame &frame)
{
    if (const auto *fb = std::get_if<v2::SetFeedback>(&frame.message)) {
        // A stream, not a command: applied whatever its seq. A non-finite value is ignored
        // (it would poison the admittance state) and does not feed the watchdog.
        if (std::isfinite(fb->tauExt))
            m_feedback.push(Feedback{T(fb->tauExt), m_clock.micros()});
        return;
    }
    const std::uint8_t type = v2::messageType(frame.message);
    if (m_haveLastCommand && type == m_lastType && frame.seq == m_lastSeq) {
        // A retry: answer again with the very same bytes, apply nothing.
        if (!m_host.write({m_reply.data(), m_replyLength}, HostPort::Traffic::Reply))
            ++m_unanswered;
        return;
    }
    const std::size_t length = answer(frame);
    if (length == 0) {
        ++m_unanswered; // not applied: the control context is not draining; the host retries
        return;
    }
    std::copy_n(m_scratch.begin(), length, m_reply.begin());
    m_replyLength = length;
    m_haveLastCommand = true;
    m_lastType = type;
    m_lastSeq = frame.seq;
    if (!m_host.write({m_reply.data(), m_replyLength}, HostPort::Traffic::Reply))
        ++m_unanswered;
}

template<typename T> std::size_t DeviceCore<T>::reply(const v2::Message &message)
{
    return v2::encodeFrame(m_replySeq++, message, m_scratch);
}

template<typename T> std::size_t DeviceCore<T>::answer(const v2::Frame &frame)
{
    const auto ack = [&](v2::AckStatus status, std::uint8_t field = v2::kNoField) {
        return reply(v2::Ack{frame.seq, status, field});
    };
    const v2::Message &m = frame.message;
    if (std::holds_alternative<v2::Hello>(m)) {
        // HELLO stops the stream, as power-up does; unanswered when that cannot be queued.
        ControlInput stop;
        stop.kind = ControlInput::Kind::Stream;
        if (!m_toControl.push(stop))
            return 0;
        m_streamHz = 0;
        v2::HelloReply hello;
        hello.protocolVersion = v2::kProtocolVersion;
        hello.capabilities = v2::kCapabilityEffects | v2::kCapabilityPassivity;
        hello.maxStreamHz = m_maxStreamHz;
        hello.deviceId = m_config.deviceId;
        hello.tauLimit = float(m_config.control.tauLimit);
        hello.firmware.assign(m_config.firmware);
        return reply(hello);
    }
    if (std::holds_alternative<v2::GetParams>(m))
        return reply(v2::Params{m_accepted});
    if (const auto *set = std::get_if<v2::SetParams>(&m)) {
        const DeviceParams block = roundedToFloat(set->params);
        const int field = firstViolatingField(block);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.params = block;
        if (!m_toControl.push(input))
            return 0;       // the control context is not draining: no answer, the host retries
        m_accepted = block; // in force from the next control cycle
        ++m_paramsApplied;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *set = std::get_if<v2::SetStream>(&m)) {
        std::uint16_t hz = std::min(set->rateHz, m_maxStreamHz);
        if (m_config.linkLimitHz > 0)
            hz = std::min(hz, m_config.linkLimitHz);
        ControlInput input;
        input.kind = ControlInput::Kind::Stream;
        input.rateHz = hz;
        if (!m_toControl.push(input))
            return 0;
        m_streamHz = hz;
        return ack(v2::AckStatus::Ok);
    }
    if (std::holds_alternative<v2::SaveParams>(m)) {
        const StoredSettings settings{m_accepted, m_effects, m_passivity};
        if (m_store && !m_store->save(settings)) {
            // The reason first, so that a host that stops at the ACK has already read it.
            const std::string_view why = m_store->failure();
            sendLog("SAVE_PARAMS failed: ", why.empty() ? "the store gives no reason" : why);
            return ack(v2::AckStatus::StorageError);
        }
        m_flash = settings;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *set = std::get_if<v2::SetEffects>(&m)) {
        const EffectParams block = roundedForWire(set->effects, m_config.control.tauLimit);
        const int field = firstViolatingField(block, m_config.control.tauLimit);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.kind = ControlInput::Kind::Effects;
        input.effects = block;
        if (!m_toControl.push(input))
            return 0;
        m_effects = block;
        return ack(v2::AckStatus::Ok);
    }
    if (std::holds_alternative<v2::GetEffects>(m))
        return reply(v2::Effects{m_effects});
    if (const auto *set = std::get_if<v2::SetPassivity>(&m)) {
        const PassivityParams block = roundedForWire(set->passivity);
        const int field = firstViolatingField(block);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.kind = ControlInput::Kind::Passivity;
        input.passivity = block;
        if (!m_toControl.push(input))
            return 0;
        m_passivity = block;
        return ack(v2::AckStatus::Ok);
    }
    if (std::holds_alternative<v2::GetPassivity>(m))
        return reply(v2::Passivity{m_passivity});
    if (const auto *vib = std::get_if<v2::Vibrate>(&m)) {
        const Vibration cue{vib->amplitude, vib->frequency, vib->duration};
        // a = 0 stops a cue whatever f and d say.
        if (cue.amplitude != 0) {
            const int field =
                firstViolatingField(cue, m_config.control.tauLimit, m_config.control.rateHz);
            if (field >= 0)
                return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        }
        ControlInput input;
        input.kind = ControlInput::Kind::Vibrate;
        input.cue = cue;
        if (!m_toControl.push(input))
            return 0;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *ping = std::get_if<v2::Ping>(&m))
        return reply(v2::Pong{ping->token});
    if (std::holds_alternative<v2::Zero>(m)) {
        DeviceParams candidate = m_accepted;
        candidate.theta0 = double(float(m_lastTheta.load()));
        const int field = firstViolatingField(candidate);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.params = candidate;
        if (!m_toControl.push(input))
            return 0;
        m_accepted = candidate;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *refused = std::get_if<v2::Refused>(&m))
        return ack(refused->status);
    // A device → host message type cannot come out of a FromHost decoder; refuse it anyway.
    return ack(v2::AckStatus::UnknownType);
}

template<typename T> void DeviceCore<T>::sendTelemetry()
{
    Telemetry item;
    while (m_toLink.pop(item)) {
        v2::Telemetry tm; // with both capabilities: every quantity (37 bytes)
        forEachCycleQuantity<v2::Telemetry, CycleRecord<T>>(
            [&tm, &c = item.record](const CycleQuantity &, auto to, auto from) {
                if constexpr (std::is_same_v<std::remove_cvref_t<decltype(c.*from)>, T>)
                    tm.*to = float(c.*from); // the wire's f32
                else
                    tm.*to = c.*from;
            });
        const std::size_t n = v2::encodeFrame(item.seq, tm, m_scratch);
        if (!m_host.write({m_scratch.data(), n}, HostPort::Traffic::Stream))
            m_telemetryDropped.fetch_add(1);
    }
}

template<typename T> void DeviceCore<T>::sendLog(std::string_view text, std::string_view detail)
{
    // One byte more than a LOG carries, so that FixedText cuts at a character boundary.
    std::array<char, v2::kMaxPayload + 1> joined{};
    const std::size_t head = std::min(text.size(), joined.size());
    std::copy_n(text.data(), head, joined.data());
    const std::size_t tail = std::min(detail.size(), joined.size() - head);
    std::copy_n(detail.data(), tail, joined.data() + head);
    v2::Log log;
    log.text.assign({joined.data(), head + tail});
    const std::size_t n = reply(log);
    m_host.write({m_scratch.data(), n}, HostPort::Traffic::Reply);
}

// ---- control context ----

template<typename T> const CycleRecord<T> &DeviceCore<T>::controlCycle(std::uint32_t nowUs)
{
    ControlInput input;
    while (m_toControl.pop(input)) {
        switch (input.kind) {
        case ControlInput::Kind::Params:
            m_controller.setParams(input.params); // the newest block wins, whole
            break;
        case ControlInput::Kind::Effects:
            m_controller.setEffects(input.effects);
            break;
        case ControlInput::Kind::Vibrate:
            m_controller.vibrate(input.cue);
            break;
        case ControlInput::Kind::Passivity:
            m_controller.setPassivity(input.passivity);
            break;
        case ControlInput::Kind::Stream:
            m_stream = input.rateHz;
            m_streamPhase = m_config.control.rateHz - input.rateHz; // first frame next cycle
            break;
        }
    }
    Feedback feedback;
    while (m_feedback.pop(feedback))
        m_controller.setFeedback(feedback.tauExt, feedback.atUs);

    const CycleRecord<T> &record = m_controller.cycle(nowUs);
    m_lastTheta.store(float(record.theta));
    if (m_controller.faulted() && !m_faultReported) {
        m_faultReported = true;
        m_events.push(Event::BusFault);
    }
    if (m_stream > 0) {
        // Frames spread evenly over the cycles: a phase accumulator, so 333 Hz at 1 kHz gives
        // exactly 333 frames per second.
        m_streamPhase += m_stream;
        if (m_streamPhase >= m_config.control.rateHz) {
            m_streamPhase -= m_config.control.rateHz;
            const std::uint8_t seq = m_telemetrySeq++; // a dropped frame still uses its seq
            if (!m_toLink.push(Telemetry{seq, record}))
                m_telemetryDropped.fetch_add(1);
        }
    }
    return record;
}

template class DeviceCore<float>;
template class DeviceCore<double>;

} // namespace hatpic::fw
