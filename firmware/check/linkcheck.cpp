// A test image for scripts/check-firmware, never flashed: it wires the device core exactly as
// firmware/src/main.cpp does (DeviceCore<float> over StsActuators over StsBus, four of them as
// with HATPIC_AXES=4, the settings blob, the host link's TxQueue) but with stub ports, so that
// linking it for a bare-metal ARM target proves that everything the firmware reaches resolves
// without host-only symbols, and lets the script look for the heap.
#include "settingsblob.h"
#include "txqueue.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace {

using namespace hatpic;

//! Queues frames as UsbHostPort does; a "FIFO" takes 128 bytes a turn.
class StubHost final : public fw::HostPort
{
public:
    std::size_t read(std::span<std::uint8_t>) override { return 0; }
    bool write(std::span<const std::uint8_t> frame, Traffic traffic) override
    {
        return m_queue.push(frame, traffic);
    }
    void flush()
    {
        const std::size_t sent = std::min<std::size_t>(m_queue.front().size(), 128);
        m_bytes += sent;
        m_queue.pop(sent);
    }
    esp32::TxQueue m_queue;
    std::size_t m_bytes = 0;
};

class StubServo final : public fw::ServoPort
{
public:
    void discardInput() override {}
    void write(std::span<const std::uint8_t>) override {}
    std::size_t read(std::span<std::uint8_t>, std::uint32_t) override { return 0; }
};

class StubClock final : public fw::Clock
{
public:
    std::uint32_t micros() override { return m_now += 1000; }
    std::uint32_t m_now = 0;
};

//! Round-trips through the NVS blob, as NvsParamStore does.
class StubStore final : public fw::ParamStore
{
public:
    bool load(std::uint8_t axis, fw::StoredSettings &out) override
    {
        return axis == 0 && m_saved && esp32::decodeSettingsBlob(m_blob, out);
    }
    bool save(std::uint8_t axis, const fw::StoredSettings &settings) override
    {
        if (axis != 0)
            return true; // knob 1's blob is the round trip checked here
        m_blob = esp32::encodeSettingsBlob(settings);
        m_saved = true;
        return true;
    }
    esp32::SettingsBlob m_blob{};
    bool m_saved = false;
};

volatile int g_cycles = 1000; // volatile: the loop cannot be folded away

int runImage()
{
    // Locals, not globals: no static destructor to register, so the image needs no atexit()
    // (whose newlib implementation allocates) and any heap left in it comes from the core.
    StubHost host;
    StubServo servo;
    StubClock clock;
    StubStore store;
    fw::StsBus bus(servo);
    // Four knobs, as the IMU branch's board (HATPIC_AXES=4): ids 1…4 on the one bus.
    fw::StsActuator<float> knob1(bus, {1}), knob2(bus, {2}), knob3(bus, {3}), knob4(bus, {4});
    const std::array<fw::Actuator<float> *, 4> knobs{&knob1, &knob2, &knob3, &knob4};
    fw::DeviceCore<float> core({}, host, knobs, clock, &store);

    store.save(0, fw::StoredSettings{});
    core.start(clock.micros());
    for (int i = 0; i < g_cycles; ++i) {
        core.controlCycle(clock.micros());
        core.serviceHost();
        host.flush();
    }
    return static_cast<int>(host.m_bytes & 0x7F);
}

} // namespace

int main()
{
    return runImage();
}

//! The image's entry point: it is linked with -nostartfiles, so no C runtime start-up (whose
//! atexit() allocates in newlib) hides what the core itself pulls in.
extern "C" [[noreturn]] void _start()
{
    runImage();
    for (;;) {
    }
}
