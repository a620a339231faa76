// The ESP32 host link's transmit queue (firmware/src/txqueue.*): its fill is exact, so a frame
// is taken whole or not at all, TELEMETRY is dropped before it eats the replies' reserve, and
// what goes out is every accepted frame, in order, over a UART that drains at its line rate.
#include "txqueue.h"

#include "protocol/v2codec.h"

#include <QTest>

#include <algorithm>

using namespace hatpic;
using namespace hatpic::esp32;
using Traffic = fw::HostPort::Traffic;

namespace {

QByteArray telemetryFrame(std::uint8_t seq)
{
    v2::Telemetry t;
    t.t_us = 1000u * seq;
    t.theta = 0.01f * float(seq);
    t.tau_fx = 0.0f;
    return v2::encodeFrame(seq, t);
}

QByteArray logFrame(std::uint8_t seq)
{
    v2::Log log;
    log.text.assign(std::string(v2::kMaxPayload, 'x')); // the largest frame there is
    return v2::encodeFrame(seq, log);
}

std::span<const std::uint8_t> bytesOf(const QByteArray &frame)
{
    return {reinterpret_cast<const std::uint8_t *>(frame.constData()), std::size_t(frame.size())};
}

//! Takes up to `count` bytes out of the queue, as the UART's FIFO would, into `wire`.
void drain(TxQueue &queue, std::size_t count, QByteArray &wire)
{
    while (count > 0 && queue.size() > 0) {
        const std::span<const std::uint8_t> front = queue.front();
        const std::size_t n = std::min(count, front.size());
        wire.append(reinterpret_cast<const char *>(front.data()), qsizetype(n));
        queue.pop(n);
        count -= n;
    }
}

} // namespace

class TestTxQueue : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void frameIsTakenWholeOrNotAtAll();
    void telemetryLeavesTheReplyReserve();
    void floodOverTheLineRate();
};

void TestTxQueue::frameIsTakenWholeOrNotAtAll()
{
    TxQueue queue;
    const QByteArray frame = logFrame(1);
    QByteArray accepted;
    while (queue.push(bytesOf(frame), Traffic::Reply))
        accepted += frame;
    QCOMPARE(queue.size(), std::size_t(accepted.size()));
    QVERIFY(queue.room() < std::size_t(frame.size()));
    // Nothing of a refused frame went in.
    const std::size_t before = queue.size();
    QVERIFY(!queue.push(bytesOf(frame), Traffic::Reply));
    QCOMPARE(queue.size(), before);

    // Around the end of the ring and back: the same bytes come out.
    QByteArray wire;
    drain(queue, 1000, wire);
    QVERIFY(queue.push(bytesOf(frame), Traffic::Reply)); // wraps
    accepted += frame;
    drain(queue, TxQueue::kCapacity, wire);
    QCOMPARE(queue.size(), std::size_t(0));
    QCOMPARE(wire, accepted);
}

void TestTxQueue::telemetryLeavesTheReplyReserve()
{
    TxQueue queue;
    int telemetry = 0;
    while (queue.push(bytesOf(telemetryFrame(std::uint8_t(telemetry))), Traffic::Stream))
        ++telemetry;
    QVERIFY(telemetry > 100);
    QVERIFY(queue.room() >= TxQueue::kReplyReserve);
    QVERIFY(queue.room() < TxQueue::kReplyReserve + std::size_t(telemetryFrame(0).size()));
    // Two of the largest replies still fit; the third does not.
    QVERIFY(queue.push(bytesOf(logFrame(1)), Traffic::Reply));
    QVERIFY(queue.push(bytesOf(logFrame(2)), Traffic::Reply));
    QVERIFY(!queue.push(bytesOf(logFrame(3)), Traffic::Reply));
}

void TestTxQueue::floodOverTheLineRate()
{
    // 921600 baud carries 92 bytes a millisecond. Offered: 5 TELEMETRY frames a millisecond
    // (175 bytes) and a 249-byte LOG every 50 ms. The queue fills, then drops TELEMETRY only;
    // every frame it took goes out whole, in order.
    constexpr std::size_t kLineBytesPerMs = 92;
    TxQueue queue;
    QByteArray accepted;
    QByteArray wire;
    int dropped = 0;
    std::uint8_t seq = 0;
    for (int ms = 0; ms < 2000; ++ms) {
        for (int i = 0; i < 5; ++i) {
            const QByteArray frame = telemetryFrame(seq++);
            if (queue.push(bytesOf(frame), Traffic::Stream))
                accepted += frame;
            else
                ++dropped;
        }
        if (ms % 50 == 0) {
            const QByteArray reply = logFrame(seq);
            QVERIFY2(queue.push(bytesOf(reply), Traffic::Reply), qPrintable(QString::number(ms)));
            accepted += reply;
        }
        QVERIFY(queue.size() <= TxQueue::kCapacity);
        drain(queue, kLineBytesPerMs, wire);
    }
    drain(queue, TxQueue::kCapacity, wire);
    QVERIFY(dropped > 4000);
    QCOMPARE(wire, accepted);
    QList<v2::Frame> frames;
    v2::FrameDecoder decoder(v2::Direction::FromDevice);
    decoder.feed(wire, frames);
    QCOMPARE(decoder.stats().totalDropped(), std::uint64_t(0));
    QCOMPARE(qsizetype(frames.size()), qsizetype(accepted.count('\0')));
}

QTEST_GUILESS_MAIN(TestTxQueue)
#include "tst_txqueue.moc"
