// The HATPIC device: protocol v2's device side (protocol.md § 3) around the control cycle,
// for one knob or several (1…kMaxAxes servos on one bus, the IMU branch's board: one
// Controller per knob, the same code N times, each with its own parameters, effects,
// passivity controller and feedback; docs/protocol.md § 2, Several knobs).
//
// Two contexts, as on the ESP32 (the paper's two threads):
// - the control context calls controlCycle() at the control rate;
// - the link context calls serviceHost() whenever host bytes may have arrived or telemetry
//   waits (the simulator calls both from one thread).
// They share nothing but lock-free single-producer queues and one atomic: parameter blocks,
// stream rate and feedback go to the control context; cycle records and log events come back.
//
// Plain C++20: no Qt, no OS calls, no exceptions, no RTTI, no allocation after construction.
#pragma once

#include "firmware/controller.h"
#include "firmware/paramstore.h"
#include "firmware/ports.h"
#include "firmware/spscqueue.h"
#include "model/axes.h"
#include "protocol/framecodec.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace hatpic::fw {

template<typename T> class DeviceCore
{
public:
    static constexpr double kMaxControlRate = 65535; //!< max_stream_hz is a u16 [Hz]
    //! Lowest control rate [Hz]: a period of at most half the feedback watchdog. A cycle
    //! renders τ_ext only if it is still younger than the watchdog at the next cycle, so at
    //! this rate feedback up to 100 ms old is rendered (hosts stream it at 20 Hz or more);
    //! with a period near the watchdog, fresh feedback would hardly ever be.
    static constexpr double kMinControlRate = 2e6 / Controller<T>::kFeedbackWatchdogUs;

    struct Config
    {
        typename Controller<T>::Config control;
        std::uint32_t deviceId = 0;       //!< HELLO_REPLY device_id
        std::string_view firmware;        //!< HELLO_REPLY firmware name (≤ 16 UTF-8 bytes)
        std::uint16_t linkLimitHz = 0;    //!< most TELEMETRY frames/s the link carries; 0 = any
        DeviceParams powerUp;             //!< used when the store has no valid block (every knob)
        PassivityParams powerUpPassivity; //!< the same for the passivity block (passivity.md)
    };

    //! Where the parameters in force at power-up came from.
    enum class PowerUp {
        Stored,     //!< the store's block
        Configured, //!< Config::powerUp (no store, nothing stored, or the stored block invalid)
        Defaults,   //!< the model's defaults (Config::powerUp was invalid too)
    };

    //! One knob per actuator, knob 1 first: 1…kMaxAxes of them (more are not used).
    DeviceCore(const Config &config, HostPort &host, std::span<Actuator<T> *const> actuators,
               Clock &clock, ParamStore *store);
    //! A single knob.
    DeviceCore(const Config &config, HostPort &host, Actuator<T> &actuator, Clock &clock,
               ParamStore *store);

    //! Loads each knob's power-up parameters: the store's block, else Config::powerUp, else
    //! the defaults, each rounded to f32 and validated. start() calls it when nobody has; call
    //! it first to place a simulated knob at the block's θ0 before the actuator starts.
    //! Returns knob 1's block.
    const DeviceParams &loadParams();
    //! Starts the control cycle with the loaded blocks. False when an actuator does not answer
    //! (then call it again: a knob that did start is simply started anew).
    bool start(std::uint32_t nowUs);

    // ---- link context ----
    //! Reads and answers host frames, then sends the telemetry and log events waiting.
    void serviceHost();

    // ---- control context ----
    //! Applies what the link context queued, runs one cycle of every knob at `nowUs`, queues
    //! their telemetry. Returns knob 1's record (controller(k).last() has the others).
    const CycleRecord<T> &controlCycle(std::uint32_t nowUs);

    // ---- observers (any context; values may lag by a cycle); `axis` 0 is knob 1 ----
    int axes() const { return m_axes; } //!< knobs, 1…kMaxAxes
    //! The knob (index) whose actuator did not answer at the last start(); −1 after a start
    //! that succeeded (or before any).
    int unstartedAxis() const { return m_unstarted; }
    PowerUp powerUpSource(int axis = 0) const { return m_knobs[index(axis)].powerUp; }
    //! Whether a knob's stored block was there but invalid (then ignored).
    bool storedBlockRejected() const;
    //! The block last accepted (in force from the next cycle).
    const DeviceParams &params(int axis = 0) const { return m_knobs[index(axis)].accepted; }
    //! The block SAVE_PARAMS saved last (or power-up's).
    const DeviceParams &savedParams(int axis = 0) const
    {
        return m_knobs[index(axis)].flash.params;
    }
    //! The effect block last accepted (in force from the next cycle).
    const EffectParams &effects(int axis = 0) const { return m_knobs[index(axis)].effects; }
    //! The passivity block last accepted (in force from the next cycle).
    const PassivityParams &passivity(int axis = 0) const { return m_knobs[index(axis)].passivity; }
    std::uint16_t streamRate() const { return m_streamHz; } //!< in force after SET_STREAM [Hz]
    std::uint16_t maxStreamHz() const { return m_maxStreamHz; }
    //! Telemetry frames lost because the host port or the queue to it was full (seq gaps).
    std::uint32_t telemetryDropped() const { return m_telemetryDropped.load(); }
    //! Commands that got no reply (link context): the queue to the control context was full,
    //! so the command was not applied, or the host port refused the reply. The host retries
    //! either way; a retry of an applied command is answered, not applied again.
    std::uint32_t unansweredCommands() const { return m_unanswered; }
    //! SET_PARAMS blocks accepted (link context); a retry answered again does not count.
    std::uint32_t paramsApplied() const { return m_paramsApplied; }
    const v2::DecoderStats &decoderStats() const { return m_decoder.stats(); }
    const Controller<T> &controller(int axis = 0) const { return *m_controllers[index(axis)]; }

private:
    //! What the link context keeps of each knob.
    struct Knob
    {
        DeviceParams accepted;     //!< latest accepted block
        EffectParams effects;      //!< latest accepted effect block
        PassivityParams passivity; //!< latest accepted passivity block
        StoredSettings flash;      //!< what SAVE_PARAMS saved (or power-up's blocks)
        PowerUp powerUp = PowerUp::Configured;
        bool storedRejected = false;
    };
    struct ControlInput
    {
        enum class Kind : std::uint8_t { Params, Stream, Effects, Vibrate, Passivity };
        Kind kind = Kind::Params;
        std::uint8_t axis = 0;
        DeviceParams params;
        EffectParams effects;
        PassivityParams passivity;
        Vibration cue;
        std::uint16_t rateHz = 0;
    };
    struct Feedback
    {
        std::array<T, kMaxAxes> tauExt{};
        std::uint8_t present = 0; //!< bit k: knob k's value came (and is finite)
        std::uint32_t atUs = 0;
    };
    struct Telemetry
    {
        std::uint8_t seq = 0;
        std::array<CycleRecord<T>, kMaxAxes> records;
    };

    //! `axis` clamped to the knobs there are (observers take any int).
    int index(int axis) const { return axis >= 0 && axis < m_axes ? axis : 0; }
    //! The knob a command names: its index, or none when it names no knob of this device.
    std::optional<int> knob(const v2::AxisIndex &axis) const;

    void handleFrame(const v2::Frame &frame);
    //! Encodes the reply to a command into m_reply; returns its length (0 = no reply).
    std::size_t answer(const v2::Frame &frame);
    std::size_t reply(const v2::Message &message);
    void sendTelemetry();
    //! A LOG frame of `text` followed by `detail`, cut to what a LOG carries (240 bytes).
    void sendLog(std::string_view text, std::string_view detail = {});

    Config m_config;
    HostPort &m_host;
    Clock &m_clock;
    ParamStore *m_store;
    int m_axes = 1;
    std::array<std::optional<Controller<T>>, kMaxAxes> m_controllers;
    std::uint16_t m_maxStreamHz = 0;

    // link context
    v2::WireDecoder m_decoder{v2::Direction::FromHost};
    std::array<Knob, kMaxAxes> m_knobs;
    std::uint16_t m_streamHz = 0;
    std::uint8_t m_replySeq = 0;
    std::uint32_t m_unanswered = 0;
    std::uint32_t m_paramsApplied = 0;
    bool m_haveLastCommand = false;
    std::uint8_t m_lastType = 0;
    std::uint8_t m_lastSeq = 0;
    v2::FrameBuffer m_reply{};
    std::size_t m_replyLength = 0;
    v2::FrameBuffer m_scratch{};
    bool m_loaded = false;
    int m_unstarted = -1;

    // control context
    std::uint16_t m_stream = 0;
    double m_streamPhase = 0;
    std::uint8_t m_telemetrySeq = 0;
    std::array<bool, kMaxAxes> m_faultReported{};

    // shared (lock-free)
    SpscQueue<ControlInput, 8> m_toControl;
    SpscQueue<Feedback, 16> m_feedback;
    SpscQueue<Telemetry, 64> m_toLink;
    SpscQueue<std::uint8_t, 8> m_busFaults; //!< the knob (index) whose torque went off
    //! θ of each knob's latest cycle, as ZERO stores it [rad]
    std::array<std::atomic<float>, kMaxAxes> m_lastTheta{};
    std::atomic<std::uint32_t> m_telemetryDropped{0}; // both contexts add
};

extern template class DeviceCore<float>;
extern template class DeviceCore<double>;

} // namespace hatpic::fw
