// Legacy ASCII protocol: frame encoding and the decoder of frames mixed with boot text.
#include "protocol/legacy.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace hatpic::legacy;
using namespace Qt::StringLiterals;

using Frames = QList<hatpic::legacy::Frame>;
Q_DECLARE_METATYPE(Frames)

namespace hatpic::legacy {
inline char *toString(const Frame &f)
{
    return qstrdup(encodeFrame(f).constData());
}
} // namespace hatpic::legacy

namespace {

struct Result
{
    Frames frames;
    QStringList text;
};

Result decodeWhole(QByteArrayView input, Decoder &decoder)
{
    Result r;
    decoder.feed(input, r.frames, &r.text);
    return r;
}

//! What a device with the published firmware sends right after it boots.
QByteArray capturedStream()
{
    return "0c1000d1000o\r\n" // the port opened in the middle of a frame
           "\r\n"
           "STS3032 Torque control\r\n"
           "Current pos motor : 1000\r\n"
           "1000\r\n"
           "\r\n"
           "ia1000b1000c1000d1000o\r\n"
           "ia1012b1000c1000d1000o\r\n"
           "ia-3b1000c1000d1000o\r\n"
           "ia4095b1000c1000d1000o\r\n"
           "ia1001b10"; // cut off: the rest has not arrived yet
}

const Frames kCapturedFrames{{1000, 1000, 1000, 1000},
                             {1012, 1000, 1000, 1000},
                             {-3, 1000, 1000, 1000},
                             {4095, 1000, 1000, 1000}};
const QStringList kCapturedText{
    u"0c1000d1000o"_s, QString(), u"STS3032 Torque control"_s, u"Current pos motor : 1000"_s,
    u"1000"_s,         QString()};

} // namespace

class TestLegacy : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // ---- encoding ----
    void encode_data()
    {
        QTest::addColumn<int>("a");
        QTest::addColumn<int>("b");
        QTest::addColumn<QByteArray>("wire");
        QTest::newRow("neutral feedback") << 1000 << 0 << QByteArray("ia1000b0c0d0o");
        QTest::newRow("clamped feedback") << 1350 << 0 << QByteArray("ia1350b0c0d0o");
        QTest::newRow("negative") << -42 << -1 << QByteArray("ia-42b-1c0d0o");
        QTest::newRow("field clamped to +99999") << 123456 << 0 << QByteArray("ia99999b0c0d0o");
        QTest::newRow("field clamped to -99999")
            << 0 << std::numeric_limits<int>::min() << QByteArray("ia0b-99999c0d0o");
    }
    void encode()
    {
        QFETCH(int, a);
        QFETCH(int, b);
        QFETCH(QByteArray, wire);
        const QByteArray encoded = encodeFrame(Frame{a, b, 0, 0});
        QCOMPARE(encoded, wire);
        // Hazard (protocol.md § 1): the only 'i' is the first byte and an 'o' ends the frame.
        QCOMPARE(encoded.count('i'), 1);
        QVERIFY(encoded.startsWith('i') && encoded.endsWith('o'));
    }

    void encodeDecodeRoundTrip()
    {
        QRandomGenerator rng(0x1E6AC7u);
        Decoder decoder;
        Frames sent;
        Frames got;
        QStringList text;
        for (int i = 0; i < 5000; ++i) {
            const auto field = [&rng] {
                return int(rng.bounded(2 * kFieldLimit + 1)) - kFieldLimit;
            };
            Frame f{field(), field(), field(), field()};
            if (rng.bounded(2))
                f.tilt = Tilt{field(), field()};
            sent.append(f);
            decoder.feed(encodeFrame(f), got, &text);
        }
        QCOMPARE(got, sent);
        QVERIFY(text.isEmpty());
        QCOMPARE(decoder.stats().malformed, quint64(0));
        QCOMPARE(decoder.stats().tiltFrames,
                 quint64(std::count_if(sent.cbegin(), sent.cend(),
                                       [](const Frame &f) { return f.tilt.has_value(); })));
    }

    void encodeTilt()
    {
        const QByteArray encoded = encodeFrame(Frame{1000, 1001, 999, 1000, Tilt{0, 2000}});
        QCOMPARE(encoded, QByteArray("ia1000b1001c999d1000p0r2000o"));
        QCOMPARE(encoded.count('i'), 1);
    }

    // ---- the IMU branch's tilt fields ----
    void tiltFromTheFirmwaresMapping_data()
    {
        // What the firmware computes from its sensor's reading (issue 36): pitch
        // map(−90…90 → 0…2000); roll map(−90…−180 → 0…1000) below 0, map(180…90 → 1000…2000)
        // from 0 on (mounted upside down: ±180° is level).
        QTest::addColumn<double>("sensorRollDeg");
        QTest::addColumn<double>("sensorPitchDeg");
        QTest::addColumn<double>("rollDeg");
        QTest::addColumn<double>("pitchDeg");
        QTest::newRow("level") << 180.0 << 0.0 << 0.0 << 0.0;
        QTest::newRow("level, read as -180") << -180.0 << 0.0 << 0.0 << 0.0;
        QTest::newRow("rolled +30") << -150.0 << 0.0 << 30.0 << 0.0;
        QTest::newRow("rolled -45") << 135.0 << 0.0 << -45.0 << 0.0;
        QTest::newRow("rolled a quarter turn") << -90.0 << 0.0 << 90.0 << 0.0;
        QTest::newRow("pitched +60") << 180.0 << 60.0 << 0.0 << 60.0;
        QTest::newRow("pitched -90") << 180.0 << -90.0 << 0.0 << -90.0;
    }
    void tiltFromTheFirmwaresMapping()
    {
        QFETCH(double, sensorRollDeg);
        QFETCH(double, sensorPitchDeg);
        QFETCH(double, rollDeg);
        QFETCH(double, pitchDeg);
        // Arduino's map(), on the firmware's doubles.
        const auto map = [](double x, double inMin, double inMax, double outMin, double outMax) {
            return (x - inMin) * (outMax - outMin) / (inMax - inMin) + outMin;
        };
        const int rollField =
            int(std::lround(sensorRollDeg < 0 ? map(sensorRollDeg, -90, -180, 0, 1000)
                                              : map(sensorRollDeg, 180, 90, 1000, 2000)));
        const int pitchField = int(std::lround(map(sensorPitchDeg, -90, 90, 0, 2000)));
        const double degree = std::numbers::pi / 180;
        const double halfField = 0.5 * (std::numbers::pi / 2) / 1000;
        QVERIFY(std::abs(TiltConversion::rollFromField(rollField) - rollDeg * degree) <= halfField);
        QVERIFY(std::abs(TiltConversion::pitchFromField(pitchField) - pitchDeg * degree) <=
                halfField);
        QCOMPARE(TiltConversion::rollToField(rollDeg * degree), rollField);
        QCOMPARE(TiltConversion::pitchToField(pitchDeg * degree), pitchField);
    }

    void imuBranchPositions()
    {
        // P_n: 1000 at the centre, 4096 a turn, clamped to 0…2000 as the branch's firmware does.
        QCOMPARE(imuBranchField(0.0), 1000);
        QCOMPARE(imuBranchField(2 * std::numbers::pi / 4096 * 12), 1012);
        QCOMPARE(imuBranchField(-10.0), 0);
        QCOMPARE(imuBranchField(10.0), 2000);
        QCOMPARE(imuBranchField(std::nan("")), 1000);
        for (int field = 0; field <= 2000; ++field)
            QCOMPARE(imuBranchField(imuBranchAngle(field)), field);
    }

    void tiltFieldsAreClamped()
    {
        const double quarter = std::numbers::pi / 2;
        QCOMPARE(TiltConversion::rollFromField(-5), quarter);
        QCOMPARE(TiltConversion::rollFromField(99999), -quarter);
        QCOMPARE(TiltConversion::pitchFromField(2001), quarter);
        QCOMPARE(TiltConversion::rollToField(10.0), 0);
        QCOMPARE(TiltConversion::pitchToField(-10.0), 0);
        QCOMPARE(TiltConversion::rollToField(std::nan("")), TiltConversion::kLevel);
        QCOMPARE(TiltConversion::pitchToField(std::nan("")), TiltConversion::kLevel);
        // A field is 0.09°: every field comes back from its angle.
        for (int field = 0; field <= TiltConversion::kFieldMax; ++field) {
            QCOMPARE(TiltConversion::rollToField(TiltConversion::rollFromField(field)), field);
            QCOMPARE(TiltConversion::pitchToField(TiltConversion::pitchFromField(field)), field);
        }
    }

    // ---- decoding ----
    void decode_data()
    {
        QTest::addColumn<QByteArray>("input");
        QTest::addColumn<Frames>("frames");
        QTest::addColumn<QStringList>("text");
        QTest::addColumn<int>("malformed");

        const Frames none;
        const QStringList noText;
        QTest::newRow("device frame with CRLF") << QByteArray("ia1000b1000c1000d1000o\r\n")
                                                << Frames{{1000, 1000, 1000, 1000}} << noText << 0;
        QTest::newRow("host frames back to back, no terminator")
            << QByteArray("ia1100b0c0d0oia650b0c0d0o") << Frames{{1100, 0, 0, 0}, {650, 0, 0, 0}}
            << noText << 0;
        QTest::newRow("signs") << QByteArray("ia-5b+7c0d-99999o") << Frames{{-5, 7, 0, -99999}}
                               << noText << 0;
        QTest::newRow("limits and leading zeros") << QByteArray("ia99999b-99999c-000001d000000o")
                                                  << Frames{{99999, -99999, -1, 0}} << noText << 0;

        QTest::newRow("boot text") << QByteArray("STS3032 Torque control\r\n") << none
                                   << QStringList{u"STS3032 Torque control"_s} << 0;
        QTest::newRow("boot text with position")
            << QByteArray("Current pos motor : 1000\r\n") << none
            << QStringList{u"Current pos motor : 1000"_s} << 0;
        QTest::newRow("bare number")
            << QByteArray("1000\r\n") << none << QStringList{u"1000"_s} << 0;
        QTest::newRow("words with i and ia stay text")
            << QByteArray("Initializing serial via 2 wires, min pos: 10\r\n") << none
            << QStringList{u"Initializing serial via 2 wires, min pos: 10"_s} << 0;
        QTest::newRow("iab is text: a frame needs a number after ia")
            << QByteArray("iab0c0d0o\n") << none << QStringList{u"iab0c0d0o"_s} << 0;
        QTest::newRow("ia and a digit inside a word starts a frame (known limit)")
            << QByteArray("media1 rest\r\n") << none << QStringList{u"med rest"_s} << 1;
        QTest::newRow("text before a frame on the same line")
            << QByteArray("pos ia1000b1000c1000d1000o\r\n") << Frames{{1000, 1000, 1000, 1000}}
            << QStringList{u"pos "_s} << 0;
        QTest::newRow("text after a frame on the same line")
            << QByteArray("ia1000b1000c1000d1000o ok\r\n") << Frames{{1000, 1000, 1000, 1000}}
            << QStringList{u" ok"_s} << 0;
        QTest::newRow("empty lines") << QByteArray("\r\n\r\n\n") << none
                                     << QStringList{QString(), QString(), QString()} << 0;
        QTest::newRow("LF only") << QByteArray("abc\ndef\n") << none
                                 << QStringList{u"abc"_s, u"def"_s} << 0;
        QTest::newRow("CR inside a line removed")
            << QByteArray("a\rb\r\n") << none << QStringList{u"ab"_s} << 0;
        QTest::newRow("i at the end of a line")
            << QByteArray("Hi\r\nhi\n") << none << QStringList{u"Hi"_s, u"hi"_s} << 0;
        QTest::newRow("i before a frame")
            << QByteArray("iia1b2c3d4o\n") << Frames{{1, 2, 3, 4}} << QStringList{u"i"_s} << 0;
        QTest::newRow("UTF-8 text") << QByteArray("Température 25 °C\r\n") << none
                                    << QStringList{u"Température 25 °C"_s} << 0;
        QTest::newRow("unterminated text is held")
            << QByteArray("no newline yet") << none << noText << 0;
        QTest::newRow("partial frame at the start is text")
            << QByteArray("0c1000d1000o\r\nia1b2c3d4o\r\n") << Frames{{1, 2, 3, 4}}
            << QStringList{u"0c1000d1000o"_s} << 0;

        QTest::newRow("malformed: missing letter b")
            << QByteArray("ia1000c1000d1000o\r\n") << none << noText << 1;
        QTest::newRow("malformed: letters out of order")
            << QByteArray("ia1b2d3c4o\r\n") << none << noText << 1;
        QTest::newRow("malformed: sign inside a number")
            << QByteArray("ia1000b10-0c1000d1000o\r\n") << none << noText << 1;
        QTest::newRow("malformed: empty field")
            << QByteArray("ia1000bc0d0o\r\n") << none << noText << 1;
        QTest::newRow("malformed: sign without digits")
            << QByteArray("ia-b0c0d0o\r\n") << none << noText << 1;
        QTest::newRow("malformed: two signs")
            << QByteArray("ia--5b0c0d0o\r\n") << none << noText << 1;
        QTest::newRow("malformed: over-long number (7 digits)")
            << QByteArray("ia0001000b0c0d0o\r\n") << none << noText << 1;
        QTest::newRow("malformed: field above 99999")
            << QByteArray("ia100000b0c0d0o\r\n") << none << noText << 1;
        QTest::newRow("malformed: last field below -99999")
            << QByteArray("ia0b0c0d-100000o\r\n") << none << noText << 1;
        QTest::newRow("malformed: missing o before CRLF")
            << QByteArray("ia1000b1000c1000d1000\r\n") << none << noText << 1;
        QTest::newRow("malformed: non-number, rest of the line is text")
            << QByteArray("ia1000bxc1000d1000o\r\n") << none << QStringList{u"xc1000d1000o"_s} << 1;
        QTest::newRow("malformed: cut by a device reset, boot text kept")
            << QByteArray("ia10STS3032 Torque control\r\n") << none
            << QStringList{u"STS3032 Torque control"_s} << 1;
        QTest::newRow("malformed then good frame at the next i")
            << QByteArray("ia10ia1000b1000c1000d1000o\r\n") << Frames{{1000, 1000, 1000, 1000}}
            << noText << 1;
        QTest::newRow("malformed then good frame on the next line")
            << QByteArray("ia12b3\r\nia1b2c3d4o\r\n") << Frames{{1, 2, 3, 4}} << noText << 1;

        // The IMU branch's device frame: four servos, then p<ROLL>r<PITCH>.
        QTest::newRow("IMU-branch frame")
            << QByteArray("ia1000b990c2000d0p1000r1500o\r\n")
            << Frames{{1000, 990, 2000, 0, Tilt{1000, 1500}}} << noText << 0;
        QTest::newRow("IMU-branch and master frames mixed")
            << QByteArray("ia1b2c3d4p5r6o\r\nia1b2c3d4o\r\n")
            << Frames{{1, 2, 3, 4, Tilt{5, 6}}, {1, 2, 3, 4}} << noText << 0;
        QTest::newRow("malformed: pitch missing")
            << QByteArray("ia1b2c3d4p5o\r\nia1b2c3d4p5r6o\r\n") << Frames{{1, 2, 3, 4, Tilt{5, 6}}}
            << noText << 1;
        QTest::newRow("malformed: r before p")
            << QByteArray("ia1b2c3d4r5p6o\r\n") << none << noText << 1;
        QTest::newRow("malformed: tilt after field C")
            << QByteArray("ia1b2c3p5r6o\r\n") << none << noText << 1;
        QTest::newRow("malformed: letter where the roll belongs")
            << QByteArray("ia1b2c3d4pr6o\r\n") << none << noText << 1;
        QTest::newRow("malformed: a field after the pitch")
            << QByteArray("ia1b2c3d4p5r6d7o\r\n") << none << noText << 1;
    }
    void decode()
    {
        QFETCH(QByteArray, input);
        QFETCH(Frames, frames);
        QFETCH(QStringList, text);
        QFETCH(int, malformed);

        // Whole, then one byte at a time: the same result.
        for (const bool byteWise : {false, true}) {
            Decoder decoder;
            Result r;
            if (byteWise) {
                for (const char c : input)
                    decoder.feed(QByteArrayView(&c, 1), r.frames, &r.text);
            } else {
                r = decodeWhole(input, decoder);
            }
            QCOMPARE(r.frames, frames);
            QCOMPARE(r.text, text);
            QCOMPARE(decoder.stats().frames, quint64(frames.size()));
            QCOMPARE(decoder.stats().textLines, quint64(text.size()));
            QCOMPARE(decoder.stats().malformed, quint64(malformed));
            QCOMPARE(decoder.stats().bytes, quint64(input.size()));
        }
    }

    void capturedStreamWhole()
    {
        Decoder decoder;
        const QByteArray stream = capturedStream();
        const Result r = decodeWhole(stream, decoder);
        QCOMPARE(r.frames, kCapturedFrames);
        QCOMPARE(r.text, kCapturedText);
        QCOMPARE(decoder.stats().malformed, quint64(0));
        QCOMPARE(decoder.pendingBytes(), qsizetype(9)); // "ia1001b10" waits for its end
        // The rest of the last frame arrives.
        Frames frames;
        QStringList text;
        decoder.feed("00c1000d1000o\r\n", frames, &text);
        QCOMPARE(frames, (Frames{{1001, 1000, 1000, 1000}}));
        QVERIFY(text.isEmpty());
        QCOMPARE(decoder.pendingBytes(), qsizetype(0));
    }

    //! The captured stream cut into three chunks at every pair of positions.
    void capturedStreamEverySplit()
    {
        const QByteArray stream = capturedStream();
        for (qsizetype a = 0; a <= stream.size(); ++a) {
            for (qsizetype b = a; b <= stream.size(); ++b) {
                Decoder decoder;
                Result r;
                decoder.feed(QByteArrayView(stream).first(a), r.frames, &r.text);
                decoder.feed(QByteArrayView(stream).sliced(a, b - a), r.frames, &r.text);
                decoder.feed(QByteArrayView(stream).sliced(b), r.frames, &r.text);
                QVERIFY2(r.frames == kCapturedFrames && r.text == kCapturedText,
                         qPrintable(u"split at %1 and %2"_s.arg(a).arg(b)));
                QCOMPARE(decoder.stats().malformed, quint64(0));
            }
        }
    }

    void textIsOptional()
    {
        Decoder decoder;
        Frames frames;
        decoder.feed(capturedStream(), frames);
        QCOMPARE(frames, kCapturedFrames);
        QCOMPARE(decoder.stats().textLines, quint64(kCapturedText.size()));
    }

    void longLines_data()
    {
        QTest::addColumn<int>("length");
        QTest::addColumn<QList<int>>("pieces");
        QTest::newRow("255 bytes: one line") << 255 << QList<int>{255};
        QTest::newRow("256 bytes: cut, no empty line after") << 256 << QList<int>{256};
        QTest::newRow("600 bytes: three pieces") << 600 << QList<int>{256, 256, 88};
    }
    void longLines()
    {
        QFETCH(int, length);
        QFETCH(QList<int>, pieces);
        Decoder decoder;
        Frames frames;
        QStringList text;
        decoder.feed(QByteArray(QByteArray(length, 'x') + "\r\n"), frames, &text);
        QCOMPARE(text.size(), pieces.size());
        for (int i = 0; i < pieces.size(); ++i)
            QCOMPARE(text[i].size(), pieces[i]);
        QCOMPARE(decoder.stats().longLines, quint64(length / Decoder::kMaxLineBytes));
        QVERIFY(decoder.pendingBytes() == 0);
    }

    //! Valid frames, boot text and malformed frames in random order and random chunks:
    //! exactly the valid frames and the text come out, every malformed frame is counted,
    //! memory stays bounded.
    void randomMixedStream()
    {
        QRandomGenerator rng(0x1E6AC1u);
        static const char *const kMalformed[] = {"ia1000c1000d1000o",
                                                 "ia1b2d3c4o",
                                                 "ia1000b10-0c1000d1000o",
                                                 "ia1000bc0d0o",
                                                 "ia-b0c0d0o",
                                                 "ia--5b0c0d0o",
                                                 "ia0001000b0c0d0o",
                                                 "ia100000b0c0d0o",
                                                 "ia0b0c0d-100000o",
                                                 "ia1000b1000c1000d1000",
                                                 "ia10"};
        static const char kTextChars[] = "abcdefghjklmnopqrstuvwxyz ABCDEFGHIJKLM:0123456789-.";
        QByteArray stream;
        Frames frames;
        QStringList text;
        int malformed = 0;
        for (int i = 0; i < 20000; ++i) {
            switch (rng.bounded(4)) {
            case 0: { // a text line without 'i'
                QByteArray line;
                const int n = int(rng.bounded(60));
                for (int k = 0; k < n; ++k)
                    line += kTextChars[rng.bounded(int(sizeof kTextChars) - 1)];
                stream += line + "\r\n";
                text.append(QString::fromLatin1(line));
                break;
            }
            case 1:
                stream += kMalformed[rng.bounded(int(std::size(kMalformed)))];
                stream += "\r\n";
                ++malformed;
                break;
            default: {
                const auto field = [&rng] { return int(rng.bounded(5000)) - 500; };
                const Frame f{field(), field(), field(), field()};
                stream += encodeFrame(f) + "\r\n";
                frames.append(f);
            }
            }
        }
        Decoder decoder;
        Result r;
        QByteArrayView rest(stream);
        while (!rest.isEmpty()) {
            const qsizetype n = std::min<qsizetype>(rest.size(), 1 + rng.bounded(100));
            decoder.feed(rest.first(n), r.frames, &r.text);
            rest = rest.sliced(n);
            QVERIFY(decoder.pendingBytes() <= Decoder::kMaxFrameBytes + Decoder::kMaxLineBytes);
        }
        QCOMPARE(r.frames, frames);
        QCOMPARE(r.text, text);
        QCOMPARE(decoder.stats().malformed, quint64(malformed));
    }

    //! Random bytes rich in frame characters never crash the decoder or grow its memory.
    void garbageIsBounded()
    {
        QRandomGenerator rng(0x6A7BA6Eu);
        static const char kChars[] = "iiaa0123456789-+bcdo\r\n xyz";
        Decoder decoder;
        Frames frames;
        QStringList text;
        for (int i = 0; i < 200000; ++i) {
            char chunk[16];
            for (char &c : chunk)
                c = rng.bounded(8) ? kChars[rng.bounded(int(sizeof kChars) - 1)]
                                   : char(rng.bounded(256));
            decoder.feed(QByteArrayView(chunk, sizeof chunk), frames, &text);
            QVERIFY(decoder.pendingBytes() <= Decoder::kMaxFrameBytes + Decoder::kMaxLineBytes);
            frames.clear();
            text.clear();
        }
        QVERIFY(decoder.stats().malformed > 0);
        // Whatever came before, a newline and a frame decode cleanly.
        decoder.feed("\nia1b2c3d4o", frames, &text);
        QCOMPARE(frames, (Frames{{1, 2, 3, 4}}));
    }

    void clearForgetsPartialData()
    {
        Decoder decoder;
        Result r;
        decoder.feed("half a line ia1000b1", r.frames, &r.text);
        QVERIFY(decoder.pendingBytes() > 0);
        decoder.clear();
        QCOMPARE(decoder.pendingBytes(), qsizetype(0));
        decoder.feed("000c0d0o\r\nia5b6c7d8o\r\n", r.frames, &r.text);
        QCOMPARE(r.frames, (Frames{{5, 6, 7, 8}}));
        QCOMPARE(r.text, QStringList{u"000c0d0o"_s});
        decoder.resetStats();
        QCOMPARE(decoder.stats(), DecoderStats{});
    }
};

QTEST_GUILESS_MAIN(TestLegacy)
#include "tst_legacy.moc"
