// A test image for scripts/check-firmware, never flashed: it wires the device core exactly as
// firmware/src/main.cpp does (DeviceCore<float> over StsActuator over StsBus, the settings blob,
// the host link's TxQueue) but with stub ports, so that linking it for a bare-metal ARM target
// proves that everything the firmware reaches resolves without host-only symbols, and lets the
// script look for the heap.
#include "settingsblob.h"
#include "txqueue.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"

#include <algorithm>
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
    bool load(fw::StoredSettings &out) override
    {
        return m_saved && esp32::decodeSettingsBlob(m_blob, out);
    }
    bool save(const fw::StoredSettings &settings) override
    {
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
    fw::StsActuator<float> actuator(bus, {});
    fw::DeviceCore<float> core({}, host, actuator, clock, &store);

    store.save(fw::StoredSettings{});
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
