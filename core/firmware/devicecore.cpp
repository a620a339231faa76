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
DeviceCore<T>::DeviceCore(const Config &config, HostPort &host,
                          std::span<Actuator<T> *const> actuators, Clock &clock, ParamStore *store)
    : m_config(config), m_host(host), m_clock(clock), m_store(store),
      m_axes(int(std::clamp<std::size_t>(actuators.size(), 1, kMaxAxes)))
{
    for (int k = 0; k < m_axes; ++k)
        m_controllers[k].emplace(config.control, *actuators[k]);
    m_maxStreamHz = std::uint16_t(std::floor(std::min(config.control.rateHz, kMaxControlRate)));
}

template<typename T>
DeviceCore<T>::DeviceCore(const Config &config, HostPort &host, Actuator<T> &actuator, Clock &clock,
                          ParamStore *store)
    : DeviceCore(config, host, std::array<Actuator<T> *, 1>{&actuator}, clock, store)
{}

template<typename T> const DeviceParams &DeviceCore<T>::loadParams()
{
    m_loaded = true;
    DeviceParams configured = roundedToFloat(m_config.powerUp);
    PowerUp fallback = PowerUp::Configured;
    if (!valid(configured)) {
        configured = roundedToFloat(DeviceParams{});
        fallback = PowerUp::Defaults;
    }
    // The defaults' ±π are not floats: kept as the nearest floats inside the range.
    const EffectParams configuredFx = roundedForWire(EffectParams{}, m_config.control.tauLimit);
    PassivityParams configuredPc = roundedForWire(m_config.powerUpPassivity);
    if (firstViolatingField(configuredPc) >= 0)
        configuredPc = roundedForWire(PassivityParams{});
    for (int k = 0; k < m_axes; ++k) {
        Knob &knob = m_knobs[k];
        knob = Knob{};
        StoredSettings settings{configured, configuredFx, configuredPc};
        knob.powerUp = fallback;
        StoredSettings stored;
        if (m_store && m_store->load(std::uint8_t(k), stored)) {
            const StoredSettings candidate{
                roundedToFloat(stored.params),
                roundedForWire(stored.effects, m_config.control.tauLimit),
                roundedForWire(stored.passivity)};
            if (valid(candidate.params) &&
                firstViolatingField(candidate.effects, m_config.control.tauLimit) < 0 &&
                firstViolatingField(candidate.passivity) < 0) {
                settings = candidate;
                knob.powerUp = PowerUp::Stored;
            } else {
                knob.storedRejected = true;
            }
        }
        knob.accepted = settings.params;
        knob.effects = settings.effects;
        knob.passivity = settings.passivity;
        knob.flash = settings;
        m_lastTheta[k].store(float(settings.params.theta0));
    }
    return m_knobs[0].accepted;
}

template<typename T> bool DeviceCore<T>::storedBlockRejected() const
{
    return std::any_of(m_knobs.begin(), m_knobs.begin() + m_axes,
                       [](const Knob &knob) { return knob.storedRejected; });
}

template<typename T> bool DeviceCore<T>::start(std::uint32_t nowUs)
{
    if (!m_loaded)
        loadParams();
    for (int k = 0; k < m_axes; ++k) {
        Controller<T> &controller = *m_controllers[k];
        controller.setEffects(m_knobs[k].effects);
        controller.setPassivity(m_knobs[k].passivity);
        if (!controller.start(m_knobs[k].accepted, nowUs)) {
            m_unstarted = k;
            return false;
        }
        m_lastTheta[k].store(float(controller.last().theta));
    }
    m_unstarted = -1;
    return true;
}

template<typename T> std::optional<int> DeviceCore<T>::knob(const v2::AxisIndex &axis) const
{
    const int k = v2::knobIndex(axis);
    if (k >= m_axes)
        return std::nullopt;
    return k;
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
    std::uint8_t faulted = 0;
    while (m_busFaults.pop(faulted)) {
        constexpr std::string_view kWhat = "servo bus: 100 consecutive errors, torque disabled";
        if (m_axes == 1) {
            sendLog(kWhat);
        } else {
            const char prefix[] = {'k', 'n', 'o', 'b', ' ', char('1' + faulted), ':', ' '};
            sendLog({prefix, sizeof prefix}, kWhat);
        }
    }
    sendTelemetry();
}

template<typename T> void DeviceCore<T>::handleFrame(const v2::Frame &frame)
{
    if (const auto *fb = std::get_if<v2::SetFeedback>(&frame.message)) {
        // A stream, not a command: applied whatever its seq. A non-finite value is ignored
        // (it would poison the admittance state) and does not feed that knob's watchdog;
        // values for knobs the device does not have are ignored.
        Feedback feedback;
        for (int k = 0; k < m_axes; ++k) {
            const std::optional<float> tau = k == 0 ? std::optional(fb->tauExt) : fb->more[k - 1];
            if (tau && std::isfinite(*tau)) {
                feedback.tauExt[k] = T(*tau);
                feedback.present |= std::uint8_t(1u << k);
            }
        }
        if (feedback.present != 0) {
            feedback.atUs = m_clock.micros();
            m_feedback.push(feedback);
        }
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
    const auto noSuchKnob = [&] { return ack(v2::AckStatus::OutOfRange, v2::kAxisField); };
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
        if (m_axes > 1) {
            hello.capabilities |= v2::kCapabilityAxes;
            hello.axes = std::uint8_t(m_axes);
        }
        hello.maxStreamHz = m_maxStreamHz;
        hello.deviceId = m_config.deviceId;
        hello.tauLimit = float(m_config.control.tauLimit);
        hello.firmware.assign(m_config.firmware);
        return reply(hello);
    }
    if (const auto *get = std::get_if<v2::GetParams>(&m)) {
        const std::optional<int> k = knob(get->axis);
        return k ? reply(v2::Params{m_knobs[*k].accepted, get->axis}) : noSuchKnob();
    }
    if (const auto *set = std::get_if<v2::SetParams>(&m)) {
        const std::optional<int> k = knob(set->axis);
        if (!k)
            return noSuchKnob();
        const DeviceParams block = roundedToFloat(set->params);
        const int field = firstViolatingField(block);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.axis = std::uint8_t(*k);
        input.params = block;
        if (!m_toControl.push(input))
            return 0; // the control context is not draining: no answer, the host retries
        m_knobs[*k].accepted = block; // in force from the next control cycle
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
        // Every knob, each its own block; the first that fails stops the save.
        for (int k = 0; k < m_axes; ++k) {
            Knob &knob = m_knobs[k];
            const StoredSettings settings{knob.accepted, knob.effects, knob.passivity};
            if (m_store && !m_store->save(std::uint8_t(k), settings)) {
                // The reason first, so that a host that stops at the ACK has already read it.
                const std::string_view why = m_store->failure();
                sendLog("SAVE_PARAMS failed: ", why.empty() ? "the store gives no reason" : why);
                return ack(v2::AckStatus::StorageError);
            }
            knob.flash = settings;
        }
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *set = std::get_if<v2::SetEffects>(&m)) {
        const std::optional<int> k = knob(set->axis);
        if (!k)
            return noSuchKnob();
        const EffectParams block = roundedForWire(set->effects, m_config.control.tauLimit);
        const int field = firstViolatingField(block, m_config.control.tauLimit);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.kind = ControlInput::Kind::Effects;
        input.axis = std::uint8_t(*k);
        input.effects = block;
        if (!m_toControl.push(input))
            return 0;
        m_knobs[*k].effects = block;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *get = std::get_if<v2::GetEffects>(&m)) {
        const std::optional<int> k = knob(get->axis);
        return k ? reply(v2::Effects{m_knobs[*k].effects, get->axis}) : noSuchKnob();
    }
    if (const auto *set = std::get_if<v2::SetPassivity>(&m)) {
        const std::optional<int> k = knob(set->axis);
        if (!k)
            return noSuchKnob();
        const PassivityParams block = roundedForWire(set->passivity);
        const int field = firstViolatingField(block);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.kind = ControlInput::Kind::Passivity;
        input.axis = std::uint8_t(*k);
        input.passivity = block;
        if (!m_toControl.push(input))
            return 0;
        m_knobs[*k].passivity = block;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *get = std::get_if<v2::GetPassivity>(&m)) {
        const std::optional<int> k = knob(get->axis);
        return k ? reply(v2::Passivity{m_knobs[*k].passivity, get->axis}) : noSuchKnob();
    }
    if (const auto *vib = std::get_if<v2::Vibrate>(&m)) {
        const std::optional<int> k = knob(vib->axis);
        if (!k)
            return noSuchKnob();
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
        input.axis = std::uint8_t(*k);
        input.cue = cue;
        if (!m_toControl.push(input))
            return 0;
        return ack(v2::AckStatus::Ok);
    }
    if (const auto *ping = std::get_if<v2::Ping>(&m))
        return reply(v2::Pong{ping->token});
    if (const auto *zero = std::get_if<v2::Zero>(&m)) {
        const std::optional<int> k = knob(zero->axis);
        if (!k)
            return noSuchKnob();
        DeviceParams candidate = m_knobs[*k].accepted;
        candidate.theta0 = double(float(m_lastTheta[*k].load()));
        const int field = firstViolatingField(candidate);
        if (field >= 0)
            return ack(v2::AckStatus::OutOfRange, std::uint8_t(field));
        ControlInput input;
        input.axis = std::uint8_t(*k);
        input.params = candidate;
        if (!m_toControl.push(input))
            return 0;
        m_knobs[*k].accepted = candidate;
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
        // With both capabilities: every quantity (37 bytes), then 33 per further knob.
        const auto copy = [](auto &to, const auto &from) {
            if constexpr (std::is_same_v<std::remove_cvref_t<decltype(from)>, T>)
                to = float(from); // the wire's f32
            else
                to = from;
        };
        v2::Telemetry tm;
        forEachCycleQuantity<v2::Telemetry, CycleRecord<T>>(
            [&](const CycleQuantity &, auto to, auto from) {
                copy(tm.*to, item.records[0].*from);
            });
        for (int k = 1; k < m_axes; ++k) {
            v2::KnobTelemetry &knob = tm.more[k - 1].emplace();
            forEachKnobQuantity<v2::KnobTelemetry, CycleRecord<T>>(
                [&](const CycleQuantity &, auto to, auto from) {
                    copy(knob.*to, item.records[k].*from);
                });
        }
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
        Controller<T> &controller = *m_controllers[index(input.axis)];
        switch (input.kind) {
        case ControlInput::Kind::Params:
            controller.setParams(input.params); // the newest block wins, whole
            break;
        case ControlInput::Kind::Effects:
            controller.setEffects(input.effects);
            break;
        case ControlInput::Kind::Vibrate:
            controller.vibrate(input.cue);
            break;
        case ControlInput::Kind::Passivity:
            controller.setPassivity(input.passivity);
            break;
        case ControlInput::Kind::Stream:
            m_stream = input.rateHz;
            m_streamPhase = m_config.control.rateHz - input.rateHz; // first frame next cycle
            break;
        }
    }
    Feedback feedback;
    while (m_feedback.pop(feedback)) {
        for (int k = 0; k < m_axes; ++k) {
            if (feedback.present & (1u << k))
                m_controllers[k]->setFeedback(feedback.tauExt[k], feedback.atUs);
        }
    }

    for (int k = 0; k < m_axes; ++k) {
        Controller<T> &controller = *m_controllers[k];
        m_lastTheta[k].store(float(controller.cycle(nowUs).theta));
        if (controller.faulted() && !m_faultReported[k]) {
            m_faultReported[k] = true;
            m_busFaults.push(std::uint8_t(k));
        }
    }
    if (m_stream > 0) {
        // Frames spread evenly over the cycles: a phase accumulator, so 333 Hz at 1 kHz gives
        // exactly 333 frames per second.
        m_streamPhase += m_stream;
        if (m_streamPhase >= m_config.control.rateHz) {
            m_streamPhase -= m_config.control.rateHz;
            Telemetry item;
            item.seq = m_telemetrySeq++; // a dropped frame still uses its seq
            for (int k = 0; k < m_axes; ++k)
                item.records[k] = m_controllers[k]->last();
            if (!m_toLink.push(item))
                m_telemetryDropped.fetch_add(1);
        }
    }
    return m_controllers[0]->last();
}

template class DeviceCore<float>;
template class DeviceCore<double>;

} // namespace hatpic::fw
