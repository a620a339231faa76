// fw::StsBus (the STS3032 bus master) fed arbitrary replies.
//
// Input: a sequence of transactions. Each takes an operation byte (PING, READ, WRITE,
// REG_WRITE, ACTION, SYNC_WRITE; the high bit picks a fuzzed servo id, else id 1), its
// arguments, and a reply description: whether the adapter echoes the request, whether a
// well-formed status packet (fuzzed error byte and params, size and id usually right) is
// sent, and raw bytes before and after it.
// Invariants:
// - every transaction is counted once: requests = replies + broadcasts + timeouts + short +
//   corrupt + foreign id + rejected; the call's result agrees with lastError();
// - READ writes its output only on success;
// - an echo plus a well-formed reply of the right id and size (and no junk before it) always
//   succeeds and delivers exactly its params;
// - every request on the wire is a well-formed packet for the id asked;
// - the bus reads a bounded number of bytes per transaction.
#include "firmware/ports.h"
#include "firmware/stsbus.h"
#include "fuzzcheck.h"

#include <algorithm>
#include <array>
#include <vector>

using namespace hatpic::fw;

namespace {

class Input
{
public:
    Input(const std::uint8_t *data, std::size_t size) : m_data(data), m_size(size) {}
    bool empty() const { return m_pos >= m_size; }
    std::uint8_t byte() { return m_pos < m_size ? m_data[m_pos++] : 0; }
    std::vector<std::uint8_t> bytes(std::size_t n)
    {
        n = std::min(n, m_size - std::min(m_pos, m_size));
        std::vector<std::uint8_t> out(m_data + m_pos, m_data + m_pos + n);
        m_pos += n;
        return out;
    }

private:
    const std::uint8_t *m_data;
    std::size_t m_size;
    std::size_t m_pos = 0;
};

//! Plays back the reply prepared for the next request; a short read is a timeout.
class ScriptedPort : public ServoPort
{
public:
    void discardInput() override { m_rx.clear(); }
    void write(std::span<const std::uint8_t> bytes) override
    {
        request.assign(bytes.begin(), bytes.end());
        m_rx.clear();
        if (echo)
            m_rx.insert(m_rx.end(), bytes.begin(), bytes.end());
        m_rx.insert(m_rx.end(), reply.begin(), reply.end());
        m_pos = 0;
        received = 0;
    }
    std::size_t read(std::span<std::uint8_t> out, std::uint32_t) override
    {
        const std::size_t n = std::min(out.size(), m_rx.size() - m_pos);
        std::copy_n(m_rx.begin() + std::ptrdiff_t(m_pos), n, out.begin());
        m_pos += n;
        received += n;
        return n;
    }

    bool echo = false;
    std::vector<std::uint8_t> reply;   //!< sent after the echo
    std::vector<std::uint8_t> request; //!< last request written
    std::size_t received = 0;          //!< bytes the bus read in this transaction

private:
    std::vector<std::uint8_t> m_rx;
    std::size_t m_pos = 0;
};

void checkRequest(const std::vector<std::uint8_t> &request, std::uint8_t id)
{
    StsPacketParser parser;
    bool have = false;
    for (const std::uint8_t b : request)
        have = parser.push(b);
    FUZZ_CHECK(have && parser.packetBytes().size() == request.size());
    FUZZ_CHECK(parser.packet().id == id);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    Input in(data, size);
    ScriptedPort port;
    StsBus bus(port, 1000);
    std::uint32_t transactions = 0;
    while (!in.empty() && transactions < 64) {
        ++transactions;
        const std::uint8_t op = in.byte();
        const std::uint8_t id = (op & 0x80) ? in.byte() : 1;
        const std::uint8_t addr = in.byte();
        const std::size_t count = in.byte(); // READ size or data length (may be out of range)
        const std::vector<std::uint8_t> payload = in.bytes(count % 140);

        // The reply.
        const std::uint8_t mode = in.byte();
        port.echo = mode & 1;
        port.reply = in.bytes((mode >> 1) & 3); // junk before
        const bool junkBefore = !port.reply.empty();
        std::vector<std::uint8_t> params;
        std::vector<std::uint8_t> replyPacket;
        bool wellFormed = false;
        std::uint8_t replyId = id;
        if (mode & 8) {
            const std::uint8_t shape = in.byte();
            const std::uint8_t code = in.byte();
            std::size_t n = (op % 6 == 1) ? count : 0;
            if (shape & 1)
                n = shape >> 1; // a wrong size, most likely
            if (shape & 0x80)
                replyId = in.byte();
            params = in.bytes(std::min<std::size_t>(n, sts::kMaxParams));
            std::array<std::uint8_t, sts::kMaxPacketBytes> packet{};
            const std::size_t m = sts::encodePacket(replyId, code, params, packet);
            replyPacket.assign(packet.begin(), packet.begin() + std::ptrdiff_t(m));
            port.reply.insert(port.reply.end(), replyPacket.begin(), replyPacket.end());
            wellFormed = m > 0;
        }
        const std::vector<std::uint8_t> after = in.bytes((mode >> 4) & 7);
        port.reply.insert(port.reply.end(), after.begin(), after.end());

        std::array<std::uint8_t, 256> out;
        out.fill(0xA5);
        bool ok = false;
        std::size_t expectedParams = 0;
        switch (op % 6) {
        case 0:
            ok = bus.ping(id);
            break;
        case 1:
            ok = bus.read(id, addr, std::span(out).first(count));
            expectedParams = count;
            break;
        case 2:
            ok = bus.write(id, addr, payload);
            break;
        case 3:
            ok = bus.regWrite(id, addr, payload);
            break;
        case 4:
            ok = bus.action(id);
            break;
        default:
            ok = bus.syncWrite(addr, std::uint8_t(count % 8), payload);
            break;
        }

        const StsBusStats &s = bus.stats();
        FUZZ_CHECK(s.requests == transactions);
        FUZZ_CHECK(s.requests == s.replies + s.broadcasts + s.errors() + s.rejected);
        FUZZ_CHECK(ok == (bus.lastError() == StsBusError::None));
        if (op % 6 == 1 && !ok)
            FUZZ_CHECK(
                std::all_of(out.begin(), out.end(), [](std::uint8_t b) { return b == 0xA5; }));
        if (bus.lastError() != StsBusError::Rejected) {
            checkRequest(port.request, op % 6 == 5 ? sts::kBroadcastId : id);
            const std::size_t budget =
                port.request.size() + expectedParams + sts::kPacketOverhead + sts::kMaxPacketBytes;
            FUZZ_CHECK(port.received <= budget + sts::kMaxPacketBytes);
        }
        const int kind = op % 6;
        const bool broadcast = kind == 5 || (id == sts::kBroadcastId && kind >= 2 && kind <= 4);
        // Without an echo, a reply identical to the request is taken for the echo (stsbus.h).
        const bool takenForEcho = !port.echo && replyPacket == port.request;
        if (wellFormed && !junkBefore && replyId == id && params.size() == expectedParams &&
            bus.lastError() != StsBusError::Rejected && !broadcast && !takenForEcho) {
            FUZZ_CHECK(ok);
            if (kind == 1)
                FUZZ_CHECK(std::equal(params.begin(), params.end(), out.begin()));
        }
    }
    return 0;
}
