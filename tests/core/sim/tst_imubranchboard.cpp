// The simulated IMU-branch board (hatpic-sim --device imu-branch): four knobs, each the published
// firmware's spring on its own servo, and a tilt, behind the branch's legacy frames.
#include "protocol/legacy.h"
#include "sim/simulateddevice.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

HandInput handOf(const QString &spec)
{
    return *HandInput::parse(spec);
}

SimulatedDevice::Config boardConfig()
{
    SimulatedDevice::Config c;
    c.board = SimulatedDevice::Board::ImuBranch;
    c.ideal = true; // no noise: knobs compare exactly
    return c;
}

//! Runs `device` for `ms` ms and returns the frames it sent.
QList<legacy::Frame> framesOf(SimulatedDevice &device, int ms, legacy::Decoder &decoder,
                              QStringList *text = nullptr)
{
    QList<legacy::Frame> frames;
    for (int i = 0; i < ms; ++i) {
        device.advance(1e-3);
        decoder.feed(device.takeOutput(), frames, text);
    }
    return frames;
}

//! The branch's P field of a knob at `theta`: ticks from the centre, +1000, clamped to 0…2000.
int positionField(double theta)
{
    return int(std::lround(std::clamp(theta * 4096 / (2 * std::numbers::pi) + 1000, 0.0, 2000.0)));
}

} // namespace

class TestImuBranchBoard : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void framesCarryFourKnobsAndTheTilt()
    {
        SimulatedDevice::Config c = boardConfig();
        c.protocol = WireProtocol::V2; // the board speaks its own frames whatever this says
        c.roll = 0.3;
        c.pitch = -0.2;
        SimulatedDevice device(c);
        QCOMPARE(device.knobs(), 4);
        QCOMPARE(device.config().protocol, WireProtocol::Legacy);
        QCOMPARE(device.baud(), 115200);
        legacy::Decoder decoder;
        QStringList text;
        const QList<legacy::Frame> frames = framesOf(device, 1100, decoder, &text);
        QCOMPARE(text.value(0), u"STS3032 Torque control"_s); // boot text, then frames
        QCOMPARE(frames.size(), 5);                           // every 200 ms
        const legacy::Frame expected{1000, 1000, 1000, 1000,
                                     legacy::Tilt{legacy::TiltConversion::rollToField(0.3),
                                                  legacy::TiltConversion::pitchToField(-0.2)}};
        for (const legacy::Frame &f : frames)
            QCOMPARE(f, expected);
        QCOMPARE(expected.tilt->roll, 809); // 1000 − 0.3 rad · 1000 / (π/2)
        QCOMPARE(expected.tilt->pitch, 873);
        QCOMPARE(decoder.stats().tiltFrames, quint64(5));
        QCOMPARE(decoder.stats().malformed, quint64(0));
    }

    void eachKnobIsTheSingleKnobsCode()
    {
        // Knob 3 pushed as a single published-firmware knob would be: the same angles, cycle
        // for cycle; the others stay at rest.
        SimulatedDevice::Config c = boardConfig();
        c.otherHands[1] = handOf(u"const:0.05"_s);
        SimulatedDevice board(c);
        SimulatedDevice::Config one;
        one.protocol = WireProtocol::Legacy;
        one.ideal = true;
        one.hand = handOf(u"const:0.05"_s);
        SimulatedDevice single(one);
        for (int i = 0; i < 2000; ++i) {
            const double alone = single.step().theta;
            board.step();
            const std::vector<double> angles = board.knobAngles();
            QCOMPARE(angles.size(), std::size_t(4));
            QCOMPARE(angles[2], alone);
            QCOMPARE(angles[0], 0.0);
            QCOMPARE(angles[1], 0.0);
            QCOMPARE(angles[3], 0.0);
        }
        QVERIFY(board.knobAngles()[2] > 0.05); // it did move
        legacy::Decoder decoder;
        const QList<legacy::Frame> frames = framesOf(board, 250, decoder);
        QVERIFY(!frames.isEmpty());
        QCOMPARE(frames.last().c, positionField(board.knobAngles()[2]));
        QCOMPARE(frames.last().a, 1000);
    }

    void handsSwitchWhileRunning()
    {
        SimulatedDevice board(boardConfig());
        board.setHand(4, handOf(u"const:-0.05"_s));
        board.setHand(1, handOf(u"const:0.05"_s));
        board.setHand(5, handOf(u"const:0.05"_s)); // no such knob: ignored
        board.setHand(0, handOf(u"const:0.05"_s));
        for (int i = 0; i < 1000; ++i)
            board.step();
        const std::vector<double> angles = board.knobAngles();
        QVERIFY(angles[0] > 0.02);
        QCOMPARE(angles[3], -angles[0]); // the same spring, pushed the other way
        QCOMPARE(angles[1], 0.0);
        QCOMPARE(angles[2], 0.0);
    }

    void feedbackGoesToEachServo()
    {
        // The branch adds field n − 1000 to servo n's torque.
        SimulatedDevice board(boardConfig());
        board.receive("ia1000b1350c1000d650o");
        for (int i = 0; i < 1000; ++i)
            board.step();
        const std::vector<double> angles = board.knobAngles();
        QCOMPARE(angles[0], 0.0);
        QVERIFY(angles[1] > 0.01);
        QCOMPARE(angles[2], 0.0);
        QCOMPARE(angles[3], -angles[1]);
        // A malformed frame changes nothing, and the board goes on.
        board.receive("ia1000b0o");
        for (int i = 0; i < 10; ++i)
            board.step();
        QVERIFY(board.knobAngles()[1] > 0.01);
    }

    void anUnfinishedFrameStallsTheWholeBoard()
    {
        // The published firmware's loop waits from 'i' to 'o': no frames, knobs held.
        SimulatedDevice::Config c = boardConfig();
        c.hand = handOf(u"const:0.05"_s);
        c.otherHands[0] = handOf(u"const:0.05"_s);
        SimulatedDevice board(c);
        for (int i = 0; i < 50; ++i) // still moving: a held knob shows
            board.step();
        legacy::Decoder decoder;
        board.takeOutput();
        board.receive("ia1000b10");
        const std::vector<double> held = board.knobAngles();
        QVERIFY(framesOf(board, 600, decoder).isEmpty());
        QCOMPARE(board.knobAngles(), held);
        board.receive("00c1000d1000o");
        QVERIFY(!framesOf(board, 600, decoder).isEmpty());
        QVERIFY(board.knobAngles()[0] > held[0]);
        QVERIFY(board.knobAngles()[1] > held[1]);
    }

    void tiltFollowsSetTilt()
    {
        SimulatedDevice board(boardConfig());
        board.setTilt(-0.5, 1.0);
        legacy::Decoder decoder;
        const QList<legacy::Frame> frames = framesOf(board, 450, decoder);
        QVERIFY(!frames.isEmpty());
        const legacy::Tilt tilt = *frames.last().tilt;
        QVERIFY(std::abs(legacy::TiltConversion::rollFromField(tilt.roll) + 0.5) < 1e-3);
        QVERIFY(std::abs(legacy::TiltConversion::pitchFromField(tilt.pitch) - 1.0) < 1e-3);
    }

    void aSingleKnobIsUnchanged()
    {
        SimulatedDevice::Config c;
        c.protocol = WireProtocol::Legacy;
        SimulatedDevice knob(c);
        QCOMPARE(knob.knobs(), 1);
        knob.setTilt(0.4, 0.4); // ignored
        knob.setHand(2, handOf(u"const:0.05"_s));
        legacy::Decoder decoder;
        const QList<legacy::Frame> frames = framesOf(knob, 450, decoder);
        QCOMPARE(frames.size(), 2);
        QCOMPARE(frames.last(), (legacy::Frame{1000, 1000, 1000, 1000}));
        QCOMPARE(decoder.stats().tiltFrames, quint64(0));
    }
};

QTEST_GUILESS_MAIN(TestImuBranchBoard)
#include "tst_imubranchboard.moc"
