// Protocol v2 message encoding and decoding (protocol.md §§ 2, 3, 5).
#include "v2testutil.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;
using namespace hatpic::v2;
using namespace Qt::StringLiterals;

Q_DECLARE_METATYPE(hatpic::v2::Message)
Q_DECLARE_METATYPE(hatpic::v2::Direction)

namespace {

//! The parameters as they come back from the wire: every double rounded to binary32.
DeviceParams asFloats(DeviceParams p)
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        p.setField(i, static_cast<double>(static_cast<float>(p.field(i))));
    return p;
}

//! Decodes `wire` as one stream and expects exactly one good frame.
std::optional<Frame> decodeOne(const QByteArray &wire, Direction direction)
{
    FrameDecoder decoder(direction);
    QList<Frame> out;
    decoder.feed(wire, out);
    if (out.size() != 1 || decoder.stats().totalDropped() != 0 || decoder.stats().frames != 1)
        return std::nullopt;
    return out.first();
}

//! The block as it travels: each field a float32.
EffectParams f32Effects(EffectParams p)
{
    for (int i = 0; i < EffectParams::kFieldCount; ++i)
        p.setField(i, double(float(p.field(i))));
    return p;
}

Direction receiverOf(const Message &m)
{
    return messageType(m) < 0x80 ? Direction::FromHost : Direction::FromDevice;
}

//! Payload bytes of a wire frame (COBS removed, type/seq/crc stripped).
QByteArray payloadOf(const QByteArray &wire)
{
    QByteArray packet;
    if (!cobsDecode(QByteArrayView(wire).chopped(1), packet) || packet.size() < 4)
        return {};
    return packet.mid(2, packet.size() - 4);
}

} // namespace

class TestV2Codec : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // ---- protocol.md § 5, byte for byte, both ways ----
    void specExamples_data()
    {
        QTest::addColumn<int>("seq");
        QTest::addColumn<Message>("message");
        QTest::addColumn<QByteArray>("wire");

        QTest::newRow("HELLO seq 0")
            << 0 << Message(Hello{}) << QByteArray::fromHex("02 01 03 3e 2e 00");
        QTest::newRow("HELLO seq 1")
            << 1 << Message(Hello{}) << QByteArray::fromHex("05 01 01 1f 3e 00");
        QTest::newRow("GET_PARAMS seq 2")
            << 2 << Message(GetParams{}) << QByteArray::fromHex("05 02 02 2f 5b 00");
        QTest::newRow("SET_PARAMS seq 3 defaults")
            << 3 << Message(SetParams{DeviceParams{}})
            << QByteArray::fromHex("1b 03 03 17 b7 d1 38 0a d7 23 3c 9a 99 19 3e cd cc cc 3e"
                                   "cd cc cc 3d 0a d7 a3 3c 01 01 01 03 47 42 00");
        QTest::newRow("PING seq 4 token DEADBEEF")
            << 4 << Message(Ping{0xDEADBEEF})
            << QByteArray::fromHex("09 07 04 ef be ad de 3c bb 00");
        QTest::newRow("ACK seq 0 of seq 3 OK")
            << 0 << Message(Ack{3, AckStatus::Ok, kNoField})
            << QByteArray::fromHex("02 83 02 03 02 ff 03 f3 8c 00");
        Telemetry t;
        t.t_us = 1000;
        t.theta = 0.05f;
        t.omega = 0.5f;
        t.tau = -0.01f;
        t.tau_rec = -0.02f;
        t.tau_ext = 0.0f;
        t.flags = 0b10;
        QTest::newRow("TELEMETRY seq 7")
            << 7 << Message(t)
            << QByteArray::fromHex("05 90 07 e8 03 01 05 cd cc 4c 3d 01 01 0a 3f 0a d7 23 bc"
                                   "0a d7 a3 bc 01 01 01 04 02 0a 2e 00");
    }
    void specExamples()
    {
        QFETCH(int, seq);
        QFETCH(Message, message);
        QFETCH(QByteArray, wire);

        QCOMPARE(encodeFrame(quint8(seq), message).toHex(' '), wire.toHex(' '));

        Message expected = message;
        if (auto *p = std::get_if<SetParams>(&expected))
            p->params = asFloats(p->params);
        const auto frame = decodeOne(wire, receiverOf(message));
        QVERIFY(frame);
        QCOMPARE(*frame, (Frame{quint8(seq), expected}));
    }

    //! protocol.md § 4: the detection HELLO must not contain 0x69 ('i').
    void helloSeqZeroHasNoLetterI() { QVERIFY(!encodeFrame(0, Hello{}).contains('i')); }

    // ---- every type round trips, with edge values ----
    void roundTrip_data()
    {
        QTest::addColumn<int>("seq");
        QTest::addColumn<Message>("message");
        QTest::addColumn<int>("payloadBytes");

        QTest::newRow("HELLO") << 0 << Message(Hello{}) << 0;
        QTest::newRow("GET_PARAMS") << 255 << Message(GetParams{}) << 0;
        DeviceParams p;
        p.D_adm = 0.5;
        p.M_adm = 10.0;
        p.K_min = 0.0;
        p.K_max = 50.0;
        p.N = 1.5;
        p.Q_dz = 0.25;
        p.theta0 = -3.0;
        QTest::newRow("SET_PARAMS exact floats") << 1 << Message(SetParams{p}) << 28;
        QTest::newRow("SET_STREAM max") << 2 << Message(SetStream{65535}) << 2;
        QTest::newRow("SET_STREAM stop") << 3 << Message(SetStream{0}) << 2;
        QTest::newRow("SET_FEEDBACK negative") << 4 << Message(SetFeedback{-0.125f}) << 4;
        QTest::newRow("SET_FEEDBACK smallest denormal")
            << 4 << Message(SetFeedback{std::numeric_limits<float>::denorm_min()}) << 4;
        QTest::newRow("SAVE_PARAMS") << 5 << Message(SaveParams{}) << 0;
        QTest::newRow("PING zero token") << 6 << Message(Ping{0}) << 4;
        QTest::newRow("PING max token") << 7 << Message(Ping{0xFFFFFFFF}) << 4;
        QTest::newRow("ZERO") << 8 << Message(Zero{}) << 0;

        HelloReply hr;
        hr.maxStreamHz = 1000;
        hr.deviceId = 0x12345678;
        hr.tauLimit = 0.44f;
        hr.firmware = fixedText<kFirmwareBytes>(u"hatpic-sim 1.0"_s);
        QTest::newRow("HELLO_REPLY") << 9 << Message(hr) << 28;
        hr.firmware = fixedText<kFirmwareBytes>(u"0123456789abcdef"_s);
        QTest::newRow("HELLO_REPLY firmware exactly 16 bytes") << 10 << Message(hr) << 28;
        hr.firmware = {};
        QTest::newRow("HELLO_REPLY empty firmware") << 11 << Message(hr) << 28;
        hr.firmware = fixedText<kFirmwareBytes>(u"fw€中😀"_s); // 2 + 3 + 3 + 4 = 12 bytes
        QTest::newRow("HELLO_REPLY multibyte firmware") << 12 << Message(hr) << 28;
        QTest::newRow("PARAMS defaults rounded")
            << 13 << Message(Params{asFloats(DeviceParams{})}) << 28;
        QTest::newRow("ACK OUT_OF_RANGE field 3")
            << 14 << Message(Ack{200, AckStatus::OutOfRange, 3}) << 4;
        QTest::newRow("ACK STORAGE_ERROR")
            << 15 << Message(Ack{0, AckStatus::StorageError, kNoField}) << 4;
        QTest::newRow("ACK unknown status passes through")
            << 15 << Message(Ack{1, AckStatus(9), kNoField}) << 4;
        QTest::newRow("PONG") << 16 << Message(Pong{0xA5A5A5A5}) << 4;
        Telemetry t;
        t.t_us = 0xFFFFFFFF;
        t.theta = -3.14159274f;
        t.omega = 1e30f;
        t.tau = -0.0f;
        t.tau_rec = std::numeric_limits<float>::max();
        t.tau_ext = std::numeric_limits<float>::lowest();
        t.flags = kFlagDeadZone | kFlagNotch | kFlagSaturated | kFlagFeedbackStale;
        QTest::newRow("TELEMETRY extremes") << 17 << Message(t) << 25;
        t.tau_fx = -0.0625f;
        QTest::newRow("TELEMETRY with tau_fx") << 22 << Message(t) << 29;
        t.tau_pc = -0.003f;
        t.pc_reserve = 0.015f;
        QTest::newRow("TELEMETRY with tau_pc and R") << 28 << Message(t) << 37;
        PassivityParams pc;
        pc.pc_damping_max = 0.25;
        pc.pc_reserve_max = double(0.02f);
        QTest::newRow("SET_PASSIVITY") << 29 << Message(SetPassivity{pc}) << 8;
        QTest::newRow("GET_PASSIVITY") << 30 << Message(GetPassivity{}) << 0;
        QTest::newRow("PASSIVITY") << 31 << Message(Passivity{pc}) << 8;
        EffectParams fx;
        fx.detent_strength = 0.05;
        fx.detent_spacing = 0.2;
        fx.detent_range = 0.8;
        fx.wall_min = -0.5;
        fx.wall_max = 0.5;
        fx.wall_stiffness = 5;
        fx.wall_damping = 0.02;
        fx = f32Effects(fx);
        QTest::newRow("SET_EFFECTS") << 23 << Message(SetEffects{fx}) << 28;
        QTest::newRow("GET_EFFECTS") << 24 << Message(GetEffects{}) << 0;
        QTest::newRow("EFFECTS") << 25 << Message(Effects{fx}) << 28;
        QTest::newRow("VIBRATE") << 26 << Message(Vibrate{0.1f, 80.0f, 0.25f}) << 12;
        HelloReply capable;
        capable.capabilities = kCapabilityEffects;
        QTest::newRow("HELLO_REPLY with effects") << 27 << Message(capable) << 28;
        // Several knobs (docs/protocol.md § 2): every addition a trailing optional field.
        HelloReply four;
        four.capabilities = kCapabilityEffects | kCapabilityPassivity | kCapabilityAxes;
        four.axes = 4;
        QTest::newRow("HELLO_REPLY with four knobs") << 32 << Message(four) << 29;
        QTest::newRow("SET_PARAMS knob 3")
            << 33 << Message(SetParams{asFloats(DeviceParams{}), 2}) << 29;
        QTest::newRow("GET_PARAMS knob 2") << 34 << Message(GetParams{1}) << 1;
        QTest::newRow("PARAMS knob 2") << 35 << Message(Params{asFloats(DeviceParams{}), 1}) << 29;
        QTest::newRow("ZERO knob 4") << 36 << Message(Zero{3}) << 1;
        QTest::newRow("SET_EFFECTS knob 2") << 37 << Message(SetEffects{fx, 1}) << 29;
        QTest::newRow("GET_EFFECTS knob 2") << 38 << Message(GetEffects{1}) << 1;
        QTest::newRow("EFFECTS knob 2") << 39 << Message(Effects{fx, 1}) << 29;
        QTest::newRow("VIBRATE knob 3") << 40 << Message(Vibrate{0.1f, 80.0f, 0.25f, 2}) << 13;
        QTest::newRow("SET_PASSIVITY knob 2") << 41 << Message(SetPassivity{pc, 1}) << 9;
        QTest::newRow("GET_PASSIVITY knob 2") << 42 << Message(GetPassivity{1}) << 1;
        QTest::newRow("PASSIVITY knob 2") << 43 << Message(Passivity{pc, 1}) << 9;
        SetFeedback every{0.01f};
        every.more = {-0.02f, 0.0f, 0.03f};
        QTest::newRow("SET_FEEDBACK four knobs") << 44 << Message(every) << 16;
        SetFeedback two{0.01f};
        two.more[0] = 0.02f;
        QTest::newRow("SET_FEEDBACK two knobs") << 45 << Message(two) << 8;
        Telemetry knobs = t;
        for (std::size_t k = 0; k < knobs.more.size(); ++k) {
            KnobTelemetry knob;
            knob.theta = 0.1f * float(k + 2);
            knob.omega = -0.5f;
            knob.tau = 0.002f;
            knob.tau_rec = -0.01f;
            knob.tau_ext = 0.02f;
            knob.flags = kFlagNotch | kFlagFeedbackStale;
            knob.tau_fx = 0.001f;
            knob.tau_pc = -0.004f;
            knob.pc_reserve = 0.01f;
            knobs.more[k] = knob;
        }
        QTest::newRow("TELEMETRY four knobs") << 46 << Message(knobs) << 136;
        knobs.more[2].reset();
        QTest::newRow("TELEMETRY three knobs") << 47 << Message(knobs) << 103;
        QTest::newRow("LOG one byte") << 18 << Message(Log{fixedText<kMaxPayload>(u"x"_s)}) << 1;
        QTest::newRow("LOG 240 bytes")
            << 19 << Message(Log{fixedText<kMaxPayload>(QString(240, u'L'))}) << 240;
        QTest::newRow("LOG with NUL and newline")
            << 20 << Message(Log{fixedText<kMaxPayload>(QString(u"a\nb"_s + QChar(0) + u"c"_s))})
            << 5;
        QTest::newRow("LOG multibyte")
            << 21 << Message(Log{fixedText<kMaxPayload>(u"Überlast 中 😀"_s)}) << 18;
    }
    void roundTrip()
    {
        QFETCH(int, seq);
        QFETCH(Message, message);
        QFETCH(int, payloadBytes);

        const QByteArray wire = encodeFrame(quint8(seq), message);
        QVERIFY(!wire.isEmpty());
        QCOMPARE(wire.count('\0'), 1);
        QVERIFY(wire.endsWith('\0'));
        QCOMPARE(payloadOf(wire).size(), payloadBytes);
        const auto frame = decodeOne(wire, receiverOf(message));
        QVERIFY(frame);
        QCOMPARE(*frame, (Frame{quint8(seq), message}));
    }

    //! Each side's decoder refuses the other side's types.
    void otherDirectionIsUnknown_data() { roundTrip_data(); }
    void otherDirectionIsUnknown()
    {
        QFETCH(int, seq);
        QFETCH(Message, message);
        const Direction wrong = receiverOf(message) == Direction::FromHost ? Direction::FromDevice
                                                                           : Direction::FromHost;
        FrameDecoder decoder(wrong);
        QList<Frame> out;
        decoder.feed(encodeFrame(quint8(seq), message), out);
        QCOMPARE(out.size(), 1);
        QCOMPARE(out.first(),
                 (Frame{quint8(seq), Refused{messageType(message), AckStatus::UnknownType}}));
        QCOMPARE(decoder.stats().dropped(DropReason::UnknownType), quint64(1));
        QCOMPARE(decoder.stats().frames, quint64(0));
    }

    // ---- conversions and limits ----
    void paramsTravelAsFloats_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<double>("received");
        QTest::newRow("0.1 rounds to the nearest float") << 0.1 << double(0.1f);
        QTest::newRow("exact float unchanged") << 0.375 << 0.375;
        QTest::newRow("1e-6 lower bound of D_adm") << 1e-6 << double(1e-6f);
        QTest::newRow("too large becomes +inf") << 1e300 << std::numeric_limits<double>::infinity();
        QTest::newRow("too large negative becomes -inf")
            << -1e300 << -std::numeric_limits<double>::infinity();
        QTest::newRow("underflow becomes zero") << 1e-300 << 0.0;
    }
    void paramsTravelAsFloats()
    {
        QFETCH(double, value);
        QFETCH(double, received);
        for (int field = 0; field < DeviceParams::kFieldCount; ++field) {
            DeviceParams p;
            p.setField(field, value);
            const auto frame = decodeOne(encodeFrame(1, SetParams{p}), Direction::FromHost);
            QVERIFY(frame);
            const auto *got = std::get_if<SetParams>(&frame->message);
            QVERIFY(got);
            QCOMPARE(got->params.field(field), received);
            // Other fields come back as their own float roundings.
            for (int other = 0; other < DeviceParams::kFieldCount; ++other)
                if (other != field)
                    QCOMPARE(got->params.field(other), double(float(p.field(other))));
        }
    }

    void nanParamSurvives()
    {
        DeviceParams p;
        p.K_max = std::numeric_limits<double>::quiet_NaN();
        const auto frame = decodeOne(encodeFrame(1, Params{p}), Direction::FromDevice);
        QVERIFY(frame);
        QVERIFY(std::isnan(std::get<Params>(frame->message).params.K_max));
    }

    void firmwareTruncation_data()
    {
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<QString>("received");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("ASCII cut at 16")
            << u"HATPIC-fw-1.2.3-long"_s << u"HATPIC-fw-1.2.3-"_s << QByteArray("HATPIC-fw-1.2.3-");
        QTest::newRow("two-byte char straddling the limit")
            << u"abcdefghijklmnoé"_s << u"abcdefghijklmno"_s << QByteArray("abcdefghijklmno\0", 16);
        QTest::newRow("four-byte char straddling the limit")
            << u"abcdefghijklm😀"_s << u"abcdefghijklm"_s << QByteArray("abcdefghijklm\0\0\0", 16);
        QTest::newRow("short name NUL padded")
            << u"sim"_s << u"sim"_s << QByteArray("sim").leftJustified(16, '\0');
        QTest::newRow("embedded NUL ends the name")
            << QString(u"ab"_s + QChar(0) + u"cd"_s) << u"ab"_s
            << QByteArray("ab\0cd", 5).leftJustified(16, '\0');
    }
    void firmwareTruncation()
    {
        QFETCH(QString, firmware);
        QFETCH(QString, received);
        QFETCH(QByteArray, bytes);
        HelloReply m;
        m.firmware = fixedText<kFirmwareBytes>(firmware);
        const QByteArray wire = encodeFrame(0, m);
        QCOMPARE(payloadOf(wire).mid(12).toHex(' '), bytes.toHex(' '));
        const auto frame = decodeOne(wire, Direction::FromDevice);
        QVERIFY(frame);
        QCOMPARE(toQString(std::get<HelloReply>(frame->message).firmware), received);
    }

    void firmwareWithoutNulUsesAll16Bytes()
    {
        QByteArray payload = QByteArray::fromHex("02 00 e8 03 01 00 00 00 00 00 00 00");
        payload += "ABCDEFGHIJKLMNOP";
        const auto frame = decodeOne(encodePacket(0x81, 0, payload), Direction::FromDevice);
        QVERIFY(frame);
        QCOMPARE(toQString(std::get<HelloReply>(frame->message).firmware), u"ABCDEFGHIJKLMNOP"_s);
        QCOMPARE(std::get<HelloReply>(frame->message).maxStreamHz, quint16(1000));
    }

    void reservedBytesIgnoredAndWrittenZero()
    {
        // ACK with a non-zero reserved byte decodes like one with 0.
        const auto ack = decodeOne(encodePacket(0x83, 1, QByteArray::fromHex("05 02 04 7f")),
                                   Direction::FromDevice);
        QVERIFY(ack);
        QCOMPARE(ack->message, Message(Ack{5, AckStatus::OutOfRange, 4}));
        QCOMPARE(payloadOf(encodeFrame(1, Ack{5, AckStatus::OutOfRange, 4})).toHex(' '),
                 QByteArray("05 02 04 00"));
        // HELLO_REPLY's byte at offset 1, reserved in protocol.md, carries the capability
        // flags of effects.md § 3: a device that predates them sends 0 there.
        HelloReply hr;
        hr.protocolVersion = 7;
        QByteArray payload = payloadOf(encodeFrame(0, hr));
        QCOMPARE(payload.at(0), char(7));
        QCOMPARE(payload.at(1), char(0));
        payload[1] = char(kCapabilityEffects);
        const auto reply = decodeOne(encodePacket(0x81, 0, payload), Direction::FromDevice);
        QVERIFY(reply);
        hr.capabilities = kCapabilityEffects;
        QCOMPARE(reply->message, Message(hr));
    }

    void logTruncation_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("bytes");
        QTest::newRow("241 ASCII bytes cut to 240") << QString(241, u'a') << 240;
        QTest::newRow("239 + two-byte char cut to 239")
            << QString(QString(239, u'a') + u"é"_s) << 239;
        QTest::newRow("238 + four-byte char cut to 238")
            << QString(QString(238, u'a') + u"😀"_s) << 238;
        QTest::newRow("80 three-byte chars fit exactly") << QString(80, u'€') << 240;
        QTest::newRow("81 three-byte chars cut to 240") << QString(81, u'€') << 240;
    }
    void logTruncation()
    {
        QFETCH(QString, text);
        QFETCH(int, bytes);
        const QByteArray wire = encodeFrame(0, Log{fixedText<kMaxPayload>(text)});
        QCOMPARE(payloadOf(wire).size(), bytes);
        const auto frame = decodeOne(wire, Direction::FromDevice);
        QVERIFY(frame);
        const QString got = toQString(std::get<Log>(frame->message).text);
        QVERIFY(text.startsWith(got));
        QCOMPARE(got.toUtf8().size(), bytes);
    }

    void notEncodable_data()
    {
        QTest::addColumn<Message>("message");
        QTest::newRow("empty LOG") << Message(Log{});
        QTest::newRow("REFUSED") << Message(Refused{0x42, AckStatus::UnknownType});
    }
    void notEncodable()
    {
        QFETCH(Message, message);
        QVERIFY(encodeFrame(0, message).isEmpty());
    }

    void encodePacketLayout()
    {
        // type | seq | payload | crc little-endian, then COBS and one delimiter.
        const QByteArray wire = encodePacket(0x42, 0x99, QByteArray("\x01\x00\x02", 3));
        QByteArray packet;
        QVERIFY(cobsDecode(QByteArrayView(wire).chopped(1), packet));
        QCOMPARE(packet.left(5).toHex(' '), QByteArray("42 99 01 00 02"));
        const quint16 crc = crc16(QByteArrayView(packet).first(5));
        QCOMPARE(quint8(packet.at(5)), quint8(crc & 0xFF));
        QCOMPARE(quint8(packet.at(6)), quint8(crc >> 8));
    }

    // ---- names and types ----
    void messageTypes_data()
    {
        QTest::addColumn<Message>("message");
        QTest::addColumn<int>("type");
        QTest::newRow("HELLO") << Message(Hello{}) << 0x01;
        QTest::newRow("GET_PARAMS") << Message(GetParams{}) << 0x02;
        QTest::newRow("SET_PARAMS") << Message(SetParams{}) << 0x03;
        QTest::newRow("SET_STREAM") << Message(SetStream{}) << 0x04;
        QTest::newRow("SET_FEEDBACK") << Message(SetFeedback{}) << 0x05;
        QTest::newRow("SAVE_PARAMS") << Message(SaveParams{}) << 0x06;
        QTest::newRow("PING") << Message(Ping{}) << 0x07;
        QTest::newRow("ZERO") << Message(Zero{}) << 0x08;
        QTest::newRow("SET_PASSIVITY") << Message(SetPassivity{}) << 0x0C;
        QTest::newRow("GET_PASSIVITY") << Message(GetPassivity{}) << 0x0D;
        QTest::newRow("PASSIVITY") << Message(Passivity{}) << 0x8D;
        QTest::newRow("HELLO_REPLY") << Message(HelloReply{}) << 0x81;
        QTest::newRow("PARAMS") << Message(Params{}) << 0x82;
        QTest::newRow("ACK") << Message(Ack{}) << 0x83;
        QTest::newRow("PONG") << Message(Pong{}) << 0x87;
        QTest::newRow("TELEMETRY") << Message(Telemetry{}) << 0x90;
        QTest::newRow("LOG") << Message(Log{}) << 0xE0;
        QTest::newRow("REFUSED keeps its type")
            << Message(Refused{0x33, AckStatus::BadLength}) << 0x33;
    }
    void messageTypes()
    {
        QFETCH(Message, message);
        QFETCH(int, type);
        QCOMPARE(int(messageType(message)), type);
    }

    void ackStatusNames_data()
    {
        QTest::addColumn<int>("status");
        QTest::addColumn<QString>("name");
        QTest::newRow("0") << 0 << u"OK"_s;
        QTest::newRow("1") << 1 << u"BAD_LENGTH"_s;
        QTest::newRow("2") << 2 << u"OUT_OF_RANGE"_s;
        QTest::newRow("3") << 3 << u"UNKNOWN_TYPE"_s;
        QTest::newRow("4") << 4 << u"STORAGE_ERROR"_s;
        QTest::newRow("5") << 5 << u"UNSUPPORTED"_s;
        QTest::newRow("unknown 6") << 6 << u"STATUS_6"_s;
        QTest::newRow("unknown 255") << 255 << u"STATUS_255"_s;
    }
    void ackStatusNames()
    {
        QFETCH(int, status);
        QFETCH(QString, name);
        QCOMPARE(ackStatusName(AckStatus(status)), name);
    }
};

QTEST_GUILESS_MAIN(TestV2Codec)
#include "tst_v2codec.moc"
