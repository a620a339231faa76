#include "protocoldetector.h"

#include "link/bytelink.h"
#include "session/commandqueue.h"
#include "session/linkstatistics.h"

#include <algorithm>
#include <utility>

namespace hatpic {

namespace {

constexpr qint32 kDefaultV2Baud = defaultBaud(WireProtocol::V2);
constexpr qint32 kDefaultLegacyBaud = defaultBaud(WireProtocol::Legacy);

//! First HELLO seq at or after `from` whose frame has no 0x69 ('i') byte (protocol.md § 4).
quint8 safeHelloSeq(quint8 from)
{
    for (int k = 0; k < 256; ++k) {
        const auto seq = static_cast<quint8>(from + k);
        if (!v2::encodeFrame(seq, v2::Hello{}).contains('i'))
            return seq;
    }
    return 0; // seq 0 encodes as 02 01 03 3e 2e 00
}

} // namespace

StateDetail stateDetail(StateDetail::Why why, const ConnectOptions &options, const ByteLink *link)
{
    StateDetail d;
    d.why = std::move(why);
    d.port = options.port;
    d.simulated = options.link && options.link->simulated();
    d.baud = link ? link->baud() : requestedBaud(options);
    return d;
}

qint32 requestedBaud(const ConnectOptions &options)
{
    if (options.baud > 0)
        return options.baud;
    // Auto with no baud given listens at the published firmware's rate first, then asks for
    // HELLO at v2's rate (see onListenTimeout), so both kinds of device are found unaided.
    return options.protocol == ProtocolChoice::V2 ? kDefaultV2Baud : kDefaultLegacyBaud;
}

ProtocolDetector::ProtocolDetector(CommandQueue &queue, LinkStatistics &statistics, QObject *parent)
    : QObject(parent), m_queue(queue), m_statistics(statistics), m_timer(this)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &ProtocolDetector::onTimeout);
    connect(&m_queue, &CommandQueue::helloUnanswered, this, &ProtocolDetector::onHelloUnanswered);
}

StateDetail ProtocolDetector::detail(StateDetail::Why why) const
{
    return stateDetail(std::move(why), m_options, m_link);
}

bool ProtocolDetector::detectsAtTwoRates() const
{
    return m_options.protocol == ProtocolChoice::Auto && m_options.baud <= 0;
}

void ProtocolDetector::start(ByteLink *link, const ConnectOptions &options)
{
    m_link = link;
    m_options = options;
    m_helloSeq.reset();
    m_giveUp = QDeadlineTimer(std::max(0, options.detectForMs));
    switch (m_options.protocol) {
    case ProtocolChoice::Legacy:
        Q_EMIT progress(detail(state::UsingLegacy{}));
        Q_EMIT foundLegacy();
        return;
    case ProtocolChoice::V2: {
        Q_EMIT progress(detail(state::AskingHello{}));
        m_phase = Phase::Hello;
        m_queue.enqueueHello();
        return;
    }
    case ProtocolChoice::Auto:
        break;
    }
    listen();
}

void ProtocolDetector::listen()
{
    // Step 1: listen for the published firmware's frames, at its rate.
    m_legacy = legacy::Decoder();
    m_legacyFrames = 0;
    Q_EMIT progress(detail(state::Listening{}));
    m_phase = Phase::Listening;
    m_timer.start(kListenMs);
}

void ProtocolDetector::stop()
{
    m_timer.stop();
    m_phase = Phase::Idle;
    m_helloSeq.reset();
    m_link = nullptr;
    // Keep the drop counts of this link; the decoder starts over on the next one.
    m_statistics.absorb(m_v2.stats());
    m_v2.clear();
    m_v2.resetStats();
}

v2::FrameDecoder ProtocolDetector::takeDecoder()
{
    m_timer.stop();
    m_phase = Phase::Idle;
    m_link = nullptr;
    return std::exchange(m_v2, v2::FrameDecoder(v2::Direction::FromDevice));
}

void ProtocolDetector::feed(const QByteArray &bytes)
{
    switch (m_phase) {
    case Phase::Idle:
        return;
    case Phase::Listening: {
        QList<legacy::Frame> frames;
        m_legacy.feed(bytes, frames, nullptr);
        m_legacyFrames += static_cast<int>(frames.size());
        // The decision cannot change once two frames are in, so it need not wait 500 ms.
        if (m_legacyFrames >= kLegacyFramesNeeded) {
            m_timer.stop();
            m_phase = Phase::Idle;
            Q_EMIT foundLegacy();
        }
        return;
    }
    case Phase::Hello:
        break;
    }
    QList<v2::Frame> frames;
    m_v2.feed(bytes, frames);
    for (qsizetype i = 0; i < frames.size(); ++i) {
        if (const auto *reply = std::get_if<v2::HelloReply>(&frames[i].message)) {
            m_timer.stop();
            m_phase = Phase::Idle;
            m_queue.onHelloReply();
            Q_EMIT foundV2(*reply, frames.mid(i + 1));
            return;
        }
    }
}

void ProtocolDetector::onTimeout()
{
    if (m_phase == Phase::Listening)
        onListenTimeout();
    else if (m_phase == Phase::Hello)
        onHelloTimeout();
}

void ProtocolDetector::onListenTimeout()
{
    if (m_legacyFrames >= kLegacyFramesNeeded) {
        m_phase = Phase::Idle;
        Q_EMIT foundLegacy();
        return;
    }
    // Step 2: HELLO with a seq whose frame holds no 'i', so a legacy device is never upset.
    if (detectsAtTwoRates() && !m_link->setBaud(kDefaultV2Baud)) {
        fail(detail(state::BaudSwitchFailed{kDefaultV2Baud, m_link->errorString()}));
        return;
    }
    Q_EMIT progress(detail(state::SendingHello{}));
    m_phase = Phase::Hello;
    m_helloSeq = safeHelloSeq(m_queue.peekSeq());
    m_queue.setNextSeq(static_cast<quint8>(*m_helloSeq + 1));
    m_v2.clear();
    m_helloSends = 0;
    sendHello();
}

void ProtocolDetector::sendHello()
{
    // Led by a delimiter: a stray byte already on the line (noise, a terminal's echo) ends
    // as a frame of its own that the device drops, instead of corrupting the HELLO. Sent
    // kHelloSends times within the wait, the same bytes each time, in case one is lost.
    ++m_helloSends;
    m_timer.start(kHelloWaitMs / kHelloSends);
    m_link->write(QByteArray(1, '\0') + v2::encodeFrame(*m_helloSeq, v2::Hello{}));
}

void ProtocolDetector::onHelloTimeout()
{
    if (m_link && m_helloSeq && m_helloSends < kHelloSends) {
        sendHello();
        return;
    }
    if (!m_giveUp.hasExpired()) { // another round, from the legacy frames at their rate
        m_helloSeq.reset();
        if (detectsAtTwoRates() && !m_link->setBaud(kDefaultLegacyBaud)) {
            fail(detail(state::BaudSwitchFailed{kDefaultLegacyBaud, m_link->errorString()}));
            return;
        }
        listen();
        return;
    }
    fail(detail(state::NoAnswer{detectsAtTwoRates() ? kDefaultLegacyBaud : 0, kListenMs,
                                m_legacyFrames, kLegacyFramesNeeded, kHelloWaitMs}));
}

void ProtocolDetector::onHelloUnanswered()
{
    if (m_phase != Phase::Hello)
        return;
    if (!m_giveUp.hasExpired()) { // a forced v2 device still booting: ask again
        m_queue.enqueueHello();
        return;
    }
    fail(detail(
        state::NoHelloReply{CommandQueue::kCommandRetries + 1, CommandQueue::kCommandTimeoutMs}));
}

void ProtocolDetector::fail(const StateDetail &detail)
{
    m_timer.stop();
    m_phase = Phase::Idle;
    Q_EMIT failed(detail);
}

} // namespace hatpic
