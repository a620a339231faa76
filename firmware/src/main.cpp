// HATPIC firmware for the ESP32 board: the device core (core/firmware, the same files the host
// builds) on two FreeRTOS tasks, the paper's two threads. docs/firmware.md explains it.
//
// Who owns what:
// - setup() (Arduino's loopTask) opens the ports, loads the parameters and starts the servo,
//   retrying every second; then it starts the two tasks and loopTask deletes itself.
// - control task, core 1, high priority: DeviceCore::controlCycle() every 1 ms (2 ms with three
//   or four knobs). Owns Serial2 (the servo bus), the StsBus and the actuators. Subscribed to
//   the task watchdog.
// - link task, core 0: DeviceCore::serviceHost() about every 1 ms, then moves queued output
//   into the UART (UsbHostPort::flush()). Owns Serial (the host link) and the NVS store
//   (SAVE_PARAMS).
// The two tasks share only what DeviceCore shares: lock-free queues and atomics.

#include "espclock.h"
#include "nvsparamstore.h"
#include "uartservoport.h"
#include "usbhostport.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"
#include "protocol/framecodec.h"

#include <Arduino.h>
#include <esp_log.h>
#include <esp_task_wdt.h>

#include <array>
#include <charconv>
#include <cstdint>
#include <string_view>
#include <utility>

// Knobs on the board: servos with ids 1 … HATPIC_AXES on the one bus (1: the single-knob
// HATPIC; 4: the IMU branch's board). Set in platformio.ini (env esp32dev-4axes).
#ifndef HATPIC_AXES
#define HATPIC_AXES 1
#endif

#if __cplusplus != 202002L
#error "the firmware is C++20: see build_flags/build_unflags in firmware/platformio.ini"
#endif
#if defined(__cpp_exceptions) || defined(__GXX_RTTI)
#error "the firmware is built without exceptions and RTTI: see build_src_flags in platformio.ini"
#endif
static_assert(configTICK_RATE_HZ == 1000, "the control task paces itself on a 1 kHz tick");

namespace {

using namespace hatpic;

constexpr int kAxes = HATPIC_AXES;
static_assert(kAxes >= 1 && kAxes <= kMaxAxes, "HATPIC_AXES: 1 to 4 knobs");
//! Ticks between cycles: each knob costs a READ and a WRITE on the 1 Mbaud bus, about 0.35 ms
//! with the servos' replies (docs/firmware.md § Several servos on one bus), so three or four
//! knobs run every other tick.
constexpr TickType_t kControlPeriodTicks = kAxes <= 2 ? 1 : 2;
constexpr double kControlRateHz = 1000.0 / kControlPeriodTicks; //!< [Hz]
constexpr BaseType_t kControlCore = 1;
constexpr BaseType_t kLinkCore = 0;          //!< with the Wi-Fi/BT stacks, were they used
constexpr UBaseType_t kControlPriority = 20; //!< above everything on core 1 but ESP-IDF's IPC (24)
constexpr UBaseType_t kLinkPriority = 5;
constexpr std::uint32_t kControlStackBytes = 4096;
constexpr std::uint32_t kLinkStackBytes = 6144;
//! Task watchdog timeout: longer than an NVS sector erase, which stalls the control task [ms].
constexpr std::uint32_t kWatchdogMs = 1000;
constexpr std::uint32_t kBootRetryMs = 1000;
constexpr std::uint32_t kBootLogDrainMs = 20; //!< longest wait for a boot LOG to leave [ms]
constexpr std::string_view kFirmwareName = "hatpic-esp32 1.0"; //!< ≤ 16 bytes (HELLO_REPLY)
static_assert(kFirmwareName.size() <= v2::kFirmwareBytes);
static_assert(kControlRateHz >= fw::DeviceCore<float>::kMinControlRate);

//! TELEMETRY frames per second the USB link carries: 43 bytes a frame with one knob (the
//! device has the effects and passivity capabilities), 33 more per further knob, 10 bits a byte.
constexpr std::uint16_t kLinkLimitHz = static_cast<std::uint16_t>(
    esp32::UsbHostPort::kBaud /
    (10 * v2::telemetryWireBytes(/*withEffects=*/true, /*withPassivity=*/true, kAxes)));

fw::StsActuator<float>::Config actuatorConfig(std::uint8_t id)
{
    fw::StsActuator<float>::Config config;
    config.id = id;
    config.centerTick = fw::sts::kDefaultCenterTick; // 1000: docs/firmware.md "First start"
    config.tauLimit = static_cast<float>(fw::sts::kDefaultTauLimit);
    return config;
}

fw::DeviceCore<float>::Config coreConfig()
{
    fw::DeviceCore<float>::Config config;
    config.control.rateHz = kControlRateHz;
    config.control.tauLimit = fw::sts::kDefaultTauLimit;
    config.control.watchdogUs = fw::Controller<float>::kFeedbackWatchdogUs; // protocol.md
    // getEfuseMac() holds the MAC's bytes 0…5 from its low end (byte 0 lowest); >> 16 and the
    // 32-bit cast keep bytes 2…5: the OUI's last byte and the three that are the board's own.
    config.deviceId = static_cast<std::uint32_t>(ESP.getEfuseMac() >> 16);
    config.firmware = kFirmwareName;
    config.linkLimitHz = kLinkLimitHz;
    config.powerUp = DeviceParams{}; // the spec defaults when NVS holds no valid block
    return config;
}

//! Knob k's actuator is servo id k + 1.
template<std::size_t... K>
std::array<fw::StsActuator<float>, sizeof...(K)> makeActuators(fw::StsBus &bus,
                                                               std::index_sequence<K...>)
{
    return {fw::StsActuator<float>(bus, actuatorConfig(std::uint8_t(K + 1)))...};
}

template<std::size_t N>
std::array<fw::Actuator<float> *, N> pointersTo(std::array<fw::StsActuator<float>, N> &actuators)
{
    std::array<fw::Actuator<float> *, N> pointers{};
    for (std::size_t k = 0; k < N; ++k)
        pointers[k] = &actuators[k];
    return pointers;
}

//! Everything the firmware is made of, built once in setup() (static storage, no heap).
struct Board
{
    esp32::EspClock clock;
    esp32::UsbHostPort host{Serial};
    esp32::UartServoPort servo{Serial2};
    fw::StsBus bus{servo};
    std::array<fw::StsActuator<float>, kAxes> actuators =
        makeActuators(bus, std::make_index_sequence<kAxes>{});
    std::array<fw::Actuator<float> *, kAxes> knobs = pointersTo(actuators);
    esp32::NvsParamStore store;
    fw::DeviceCore<float> core{coreConfig(), host, knobs, clock, &store};
    std::uint8_t bootLogSeq = 0; //!< seq of setup()'s own LOG frames
};

//! A LOG frame from setup(), before the link task owns the port; sent before it returns.
void bootLog(Board &board, std::string_view text)
{
    v2::Log log;
    log.text.assign(text);
    v2::FrameBuffer frame;
    const std::size_t length = v2::encodeFrame(board.bootLogSeq++, log, frame);
    board.host.write({frame.data(), length}, fw::HostPort::Traffic::Reply);
    board.host.drain(kBootLogDrainMs);
}

//! A LOG's text put together without allocating.
class LogText
{
public:
    void append(std::string_view part)
    {
        for (char c : part)
            if (m_size < m_text.size())
                m_text[m_size++] = c;
    }
    void append(char c) { append(std::string_view(&c, 1)); }
    std::string_view view() const { return {m_text.data(), m_size}; }

private:
    std::array<char, 128> m_text{};
    std::size_t m_size = 0;
};

//! "servo ready: model 0x…, parameters …" without allocating.
void logReady(Board &board)
{
    LogText text;
    const auto append = [&](std::string_view part) { text.append(part); };
    append(kAxes == 1 ? "servo ready: model 0x" : "servos ready: model 0x");
    std::array<char, 8> hex{};
    const auto end =
        std::to_chars(hex.begin(), hex.end(), board.actuators[0].modelNumber(), 16).ptr;
    append({hex.data(), static_cast<std::size_t>(end - hex.data())});
    using PowerUp = fw::DeviceCore<float>::PowerUp;
    switch (board.core.powerUpSource()) {
    case PowerUp::Stored:
        append(", parameters from NVS");
        break;
    case PowerUp::Configured:
    case PowerUp::Defaults:
        append(board.core.storedBlockRejected() ? ", NVS block invalid: default parameters"
                                                : ", default parameters");
        break;
    }
    bootLog(board, text.view());
}

void configureWatchdog()
{
    esp_task_wdt_config_t config{};
    config.timeout_ms = kWatchdogMs;
    config.idle_core_mask = 1u << 0; // IDLE0 as before; core 1 belongs to the control task
    config.trigger_panic = true;     // a hung control task reboots the board
    if (esp_task_wdt_reconfigure(&config) != ESP_OK)
        esp_task_wdt_init(&config); // not initialised by the framework's sdkconfig
}

void controlTask(void *arg)
{
    Board &board = *static_cast<Board *>(arg);
    esp_task_wdt_add(nullptr);
    TickType_t wake = xTaskGetTickCount();
    for (;;) {
        // An overrun (bus timeouts, a flash write) restarts the schedule instead of running
        // the missed cycles back to back.
        if (xTaskDelayUntil(&wake, kControlPeriodTicks) == pdFALSE)
            wake = xTaskGetTickCount();
        board.core.controlCycle(board.clock.micros());
        esp_task_wdt_reset();
    }
}

void linkTask(void *arg)
{
    Board &board = *static_cast<Board *>(arg);
    for (;;) {
        board.core.serviceHost();
        board.host.flush(); // what the UART's FIFO did not take yet
        vTaskDelay(1);
    }
}

} // namespace

void setup()
{
    esp_log_level_set("*", ESP_LOG_NONE); // UART0 carries protocol v2 frames only
    static Board board;
    board.host.begin();
    board.servo.begin();
    // The device core reports LOG only for bus faults; a servo missing at boot is reported here.
    while (!board.core.start(board.clock.micros())) {
        LogText text;
        text.append("servo id ");
        text.append(char('1' + (board.core.unstartedAxis() > 0 ? board.core.unstartedAxis() : 0)));
        text.append(" does not answer (Serial2, RX 16, TX 17, 1 Mbaud): check its power; "
                    "retrying every second");
        bootLog(board, text.view());
        delay(kBootRetryMs);
    }
    logReady(board);
    configureWatchdog();
    xTaskCreatePinnedToCore(controlTask, "hatpic-control", kControlStackBytes, &board,
                            kControlPriority, nullptr, kControlCore);
    xTaskCreatePinnedToCore(linkTask, "hatpic-link", kLinkStackBytes, &board, kLinkPriority,
                            nullptr, kLinkCore);
}

void loop()
{
    vTaskDelete(nullptr); // the two tasks do the work; free loopTask's core-1 time and stack
}
