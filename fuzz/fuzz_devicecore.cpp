// fw::DeviceCore<double> fed arbitrary host bytes through a fixed-buffer host port (room for a
// few frames towards the host), with control cycles interleaved, on a canned STS3032 bus
// (tests/core/firmware/devicecoretest.h).
//
// Input: byte 0 seeds the schedule (chunk sizes, when the link and control contexts run, clock
// steps), byte 1 sets the knob's position and whether the parameter store fails, the rest is
// what the host sends.
// Invariants (checked after every link-context run):
// - every complete frame that passes the CRC and is a command gets exactly one reply, of the
//   kind the command asks for (HELLO_REPLY, PARAMS, PONG with the token, or an ACK of its seq
//   with the refusal's status), or is counted in unansweredCommands() (queue to the control
//   context full, or host port full), or is SET_FEEDBACK and gets none;
// - everything the device sends decodes without a single drop;
// - the device's decoder stats equal those of an independent decoder fed the same bytes.
// Crashes, sanitizer reports and hangs (libFuzzer's -timeout) fail the run.
#include "devicecoretest.h"
#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"
#include "fuzzcheck.h"

#include <array>
#include <vector>

using namespace hatpic;
using namespace devicecoretest;

namespace {

class FlakyStore : public fw::ParamStore
{
public:
    bool load(std::uint8_t, fw::StoredSettings &) override { return false; }
    bool save(std::uint8_t, const fw::StoredSettings &) override { return !failing; }
    bool failing = false;
};

//! Like FixedHostPort, but the device → host buffer holds only a few frames (it is drained
//! after every link-context run), so that a burst of replies meets a full port.
class TightHostPort : public fw::HostPort
{
public:
    std::size_t read(std::span<std::uint8_t> out) override { return toDevice.pop(out); }
    bool write(std::span<const std::uint8_t> frame, Traffic) override { return toHost.push(frame); }
    ByteRing<1024> toDevice;
    ByteRing<192> toHost;
};

struct Rig
{
    Rig() : bus(servo, 0), actuator(bus, {}), core(config(), host, actuator, clock, &store) {}
    static fw::DeviceCore<double>::Config config()
    {
        fw::DeviceCore<double>::Config c;
        c.deviceId = 0x46555A5A;
        c.firmware = "fuzz";
        c.linkLimitHz = 2000;
        return c;
    }
    CannedServo servo;
    TightHostPort host;
    ManualClock clock;
    FlakyStore store;
    fw::StsBus bus;
    fw::StsActuator<double> actuator;
    fw::DeviceCore<double> core;
};

bool isReply(const v2::Message &m)
{
    return std::holds_alternative<v2::HelloReply>(m) || std::holds_alternative<v2::Params>(m) ||
           std::holds_alternative<v2::Ack>(m) || std::holds_alternative<v2::Pong>(m);
}

//! Whether `reply` is the answer `command` asks for.
bool answers(const v2::Frame &command, const v2::Frame &reply)
{
    const v2::Message &c = command.message;
    const v2::Message &r = reply.message;
    if (std::holds_alternative<v2::Hello>(c))
        return std::holds_alternative<v2::HelloReply>(r);
    if (std::holds_alternative<v2::GetParams>(c))
        return std::holds_alternative<v2::Params>(r);
    if (const auto *ping = std::get_if<v2::Ping>(&c)) {
        const auto *pong = std::get_if<v2::Pong>(&r);
        return pong && pong->token == ping->token;
    }
    const auto *ack = std::get_if<v2::Ack>(&r);
    if (!ack || ack->ackedSeq != command.seq)
        return false;
    if (const auto *refused = std::get_if<v2::Refused>(&c))
        return ack->status == refused->status;
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    fuzzcheck::XorShift rng(data[0]);
    std::span<const std::uint8_t> rest(data + 2, size - 2);

    Rig rig;
    rig.servo.setPresent(900 + (data[1] & 0x7F) * 2, 0, 0);
    rig.store.failing = data[1] & 0x80;
    if (!rig.core.start(0))
        return 0;

    v2::WireDecoder shadow(v2::Direction::FromHost);       // what the device should have seen
    v2::WireDecoder fromDevice(v2::Direction::FromDevice); // what it said
    std::vector<std::uint8_t> unread;                      // pushed, not yet serviced
    std::vector<v2::Frame> commands;
    std::vector<v2::Frame> replies;
    std::array<std::uint8_t, 4096> drain;
    std::uint32_t unansweredBefore = 0;

    const auto service = [&] {
        rig.core.serviceHost();
        commands.clear();
        shadow.feed(unread, [&](const v2::Frame &f) {
            if (!std::holds_alternative<v2::SetFeedback>(f.message))
                commands.push_back(f);
        });
        unread.clear();
        replies.clear();
        for (std::size_t n; (n = rig.host.toHost.pop(drain)) > 0;) {
            fromDevice.feed(std::span<const std::uint8_t>(drain.data(), n),
                            [&](const v2::Frame &f) {
                                if (isReply(f.message))
                                    replies.push_back(f);
                            });
        }
        FUZZ_CHECK(fromDevice.stats().totalDropped() == 0);
        FUZZ_CHECK(rig.core.decoderStats() == shadow.stats());
        // Unanswered commands are counted (the queue to the control context was full); when
        // none was, replies pair with commands one to one, in order.
        const std::uint32_t unanswered = rig.core.unansweredCommands() - unansweredBefore;
        unansweredBefore = rig.core.unansweredCommands();
        FUZZ_CHECK(replies.size() + unanswered == commands.size());
        for (std::size_t i = 0; unanswered == 0 && i < commands.size(); ++i)
            FUZZ_CHECK(answers(commands[i], replies[i]));
    };

    while (!rest.empty()) {
        const std::uint32_t r = rng.next();
        // A chunk of host bytes; the ring holds 1024, so the link context runs when it is full.
        const std::size_t n = std::min(rest.size(), rng.chunk(r % 8 == 0 ? 400 : 40));
        if (rig.host.toDevice.size() + n > 1024)
            service();
        rig.host.toDevice.push(rest.first(n));
        unread.insert(unread.end(), rest.begin(), rest.begin() + std::ptrdiff_t(n));
        rest = rest.subspan(n);
        if ((r >> 8) % 4 != 0)
            service();
        for (std::uint32_t cycles = (r >> 12) % 4; cycles > 0; --cycles) {
            // Mostly 1 ms steps; now and then a jump, across the 2³² µs wrap too.
            rig.clock.now += (r >> 16) % 16 == 0 ? rng.next() : 1000;
            rig.core.controlCycle(rig.clock.now);
        }
    }
    service();
    return 0;
}
