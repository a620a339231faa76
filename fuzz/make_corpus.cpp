// Writes the seed corpus of the fuzz targets with the project's own encoders, so that every
// seed is a valid input the targets then mutate: `fuzz_make_corpus DIR` fills DIR/<target>/.
// The profile seeds are the presets of resources/presets, copied as they are. Run by hand when
// a format changes.
#include "firmware/sts3032.h"
#include "protocol/framecodec.h"
#include "protocol/legacy.h"
#include "telemetry/recordingwriter.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <cstdio>
#include <vector>

using namespace hatpic;

namespace {

using Bytes = std::vector<std::uint8_t>;

QString g_root;

void write(const QString &target, const QString &name, const Bytes &bytes)
{
    QDir().mkpath(g_root + u'/' + target);
    QFile file(g_root + u'/' + target + u'/' + name);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(reinterpret_cast<const char *>(bytes.data()), qint64(bytes.size())) !=
            qint64(bytes.size())) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(file.fileName()));
        std::exit(1);
    }
}

Bytes frame(std::uint8_t seq, const v2::Message &m)
{
    v2::FrameBuffer b;
    const std::size_t n = v2::encodeFrame(seq, m, b);
    return Bytes(b.begin(), b.begin() + std::ptrdiff_t(n));
}

Bytes cat(std::initializer_list<Bytes> parts)
{
    Bytes out;
    for (const Bytes &p : parts)
        out.insert(out.end(), p.begin(), p.end());
    return out;
}

Bytes sts(std::uint8_t id, std::uint8_t code, const Bytes &params)
{
    std::array<std::uint8_t, fw::sts::kMaxPacketBytes> b{};
    const std::size_t n = fw::sts::encodePacket(id, code, params, b);
    return Bytes(b.begin(), b.begin() + std::ptrdiff_t(n));
}

Bytes text(std::string_view s)
{
    return Bytes(s.begin(), s.end());
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_make_corpus DIR\n");
        return 2;
    }
    g_root = QString::fromLocal8Bit(argv[1]);

    // ---- v2, host → device (fuzz_wire_device; fuzz_devicecore with 2 leading bytes) ----
    DeviceParams soft;
    soft.K_max = 0.2;
    const std::vector<std::pair<QString, v2::Message>> commands = {
        {u"hello"_qs, v2::Hello{}},
        {u"get_params"_qs, v2::GetParams{}},
        {u"set_params"_qs, v2::SetParams{soft}},
        {u"set_stream"_qs, v2::SetStream{1000}},
        {u"set_feedback"_qs, v2::SetFeedback{0.05f}},
        {u"save_params"_qs, v2::SaveParams{}},
        {u"ping"_qs, v2::Ping{0x12345678}},
        {u"zero"_qs, v2::Zero{}},
    };
    Bytes session;
    std::uint8_t seq = 0;
    for (const auto &[name, message] : commands) {
        const Bytes f = frame(seq++, message);
        write(u"fuzz_wire_device"_qs, name, cat({{0}, f}));
        session.insert(session.end(), f.begin(), f.end());
    }
    // protocol.md § 2: HELLO with seq 0 on the wire.
    write(u"fuzz_wire_device"_qs, u"hello_protocol_md"_qs, {0, 0x02, 0x01, 0x03, 0x3e, 0x2e, 0x00});
    write(u"fuzz_wire_device"_qs, u"session"_qs, cat({{7}, session}));
    // A session with a retry, a refused type and a bad length, then feedback while streaming.
    const Bytes retry = frame(9, v2::SetStream{500});
    Bytes refusedType = frame(3, v2::Hello{});
    Bytes raw(64);
    const Bytes unknown(raw.begin(),
                        raw.begin() + std::ptrdiff_t(v2::encodePacket(0x42, 10, {}, raw)));
    const std::uint8_t shortPayload[] = {1};
    const Bytes badLength(
        raw.begin(), raw.begin() + std::ptrdiff_t(v2::encodePacket(0x04, 11, shortPayload, raw)));
    Bytes feedback;
    for (int i = 0; i < 20; ++i) {
        const Bytes f = frame(std::uint8_t(i), v2::SetFeedback{0.01f * float(i)});
        feedback.insert(feedback.end(), f.begin(), f.end());
    }
    write(u"fuzz_devicecore"_qs, u"session"_qs, cat({{1, 50}, session}));
    write(u"fuzz_devicecore"_qs, u"retry_refused"_qs,
          cat({{2, 60}, retry, retry, unknown, badLength, frame(12, v2::Ping{7})}));
    write(u"fuzz_devicecore"_qs, u"stream_feedback"_qs,
          cat({{3, 0xC0},
               frame(1, v2::SetStream{1000}),
               feedback,
               frame(2, v2::Zero{}),
               frame(3, v2::SaveParams{})}));
    write(u"fuzz_wire_device"_qs, u"refused"_qs, cat({{5}, unknown, badLength}));

    // ---- v2, device → host (fuzz_wire_host) ----
    v2::HelloReply hello;
    hello.maxStreamHz = 1000;
    hello.deviceId = 0x53494D31;
    hello.tauLimit = 0.44f;
    hello.firmware.assign("hatpic-sim 0.1");
    v2::Telemetry tm;
    tm.t_us = 123456;
    tm.theta = 0.1f;
    tm.omega = -0.5f;
    tm.tau = 0.02f;
    tm.tau_rec = -0.03f;
    tm.tau_ext = 0.01f;
    tm.flags = v2::kFlagDeadZone | v2::kFlagFeedbackStale;
    v2::Log log;
    log.text.assign("servo bus: 100 consecutive errors, torque disabled");
    const std::vector<std::pair<QString, v2::Message>> replies = {
        {u"hello_reply"_qs, hello},
        {u"params"_qs, v2::Params{DeviceParams{}}},
        {u"ack"_qs, v2::Ack{4, v2::AckStatus::OutOfRange, 3}},
        {u"pong"_qs, v2::Pong{0x12345678}},
        {u"telemetry"_qs, tm},
        {u"log"_qs, log},
    };
    Bytes stream;
    seq = 0;
    for (const auto &[name, message] : replies) {
        const Bytes f = frame(seq++, message);
        write(u"fuzz_wire_host"_qs, name, cat({{0}, f}));
        stream.insert(stream.end(), f.begin(), f.end());
    }
    for (std::uint8_t i = 0; i < 8; ++i) {
        const Bytes f = frame(i, tm);
        stream.insert(stream.end(), f.begin(), f.end());
    }
    write(u"fuzz_wire_host"_qs, u"stream"_qs, cat({{9}, stream}));

    // ---- legacy ----
    write(u"fuzz_legacy"_qs, u"boot_and_frames"_qs,
          cat({{0},
               text("STS3032 Torque control\r\nInitializing serial\r\n"),
               text("ia1000b0c-12d3o\r\nia1010b5c-20d4o\r\n")}));
    write(u"fuzz_legacy"_qs, u"host_frames"_qs,
          cat({{1}, text("ia1000b0c0d0oia1350b0c0d0oia650b0c0d0o")}));
    write(u"fuzz_legacy"_qs, u"malformed_then_good"_qs,
          cat({{2}, text("ia10ia1000b1000c1000d1000o\r\nmedia1 viable via 2\r\n")}));
    write(u"fuzz_legacy"_qs, u"imu_branch"_qs,
          cat({{3},
               text("ia1000b990c1012d1000p1000r1000o\r\nia1b2c3d4p0r2000o\r\n"
                    "ia1b2c3d4p5o\r\nia1000b1000c1000d1000o\r\n")}));

    // ---- STS3032 ----
    const Bytes feedbackReply = sts(1, 0, {0xE8, 0x03, 0x10, 0x80, 0x20, 0x04});
    const Bytes pingReply = sts(1, 0, {});
    const Bytes readRequest = sts(1, fw::sts::kRead, {fw::sts::kRegPresentPosition, 6});
    write(u"fuzz_sts_parser"_qs, u"feedback_reply"_qs, feedbackReply);
    write(u"fuzz_sts_parser"_qs, u"echo_then_reply"_qs, cat({readRequest, feedbackReply}));
    write(u"fuzz_sts_parser"_qs, u"noise_resync"_qs,
          cat({{0xFF, 0xFF, 0xFF, 0x01, 0x7F}, pingReply, {0x00, 0xFF}, feedbackReply}));
    write(u"fuzz_sts_parser"_qs, u"status_error"_qs, sts(1, 0x20, {0x00, 0x08}));
    // fuzz_stsbus: op, addr, count, payload(count), mode, [shape, code, params], after.
    write(u"fuzz_sts_bus"_qs, u"ping_read_write"_qs,
          cat({{0, 0, 0, 0x08, 0, 0},                    // PING, well-formed reply
               {1, 56, 6, 0, 0, 0, 0, 0, 0, 0x09, 0, 0}, // READ 6 with echo + reply
               {0xE8, 0x03, 0x10, 0x80, 0x20, 0x04},     //   its params
               {2, 42, 2, 0xE8, 0x03, 0x08, 0, 0},       // WRITE goal, reply
               {5, 42, 2, 1, 0xE8, 0x03, 0x00}}));       // SYNC_WRITE
    write(u"fuzz_sts_bus"_qs, u"timeouts"_qs,
          cat({{0, 0, 0, 0x00}, {1, 56, 6, 0, 0, 0, 0, 0, 0, 0x10, 0xFF}}));

    // ---- recording: a short valid one, alone and with its sidecar ----
    QTemporaryDir dir;
    const QString csvPath = dir.filePath(u"rec.csv"_qs);
    {
        RecordingWriter recorder;
        RecordingMetadata meta;
        meta.start = QDateTime::fromString(u"2024-05-01T10:00:00.000Z"_qs, Qt::ISODateWithMs);
        meta.source = u"fuzz_make_corpus"_qs;
        if (!recorder.open(csvPath, meta)) {
            std::fprintf(stderr, "%s\n", qPrintable(recorder.error()));
            return 1;
        }
        SampleBatch batch;
        for (int i = 0; i < 5; ++i) {
            Sample s;
            s.t_s = 0.001 * i;
            s.t_us = quint32(1000 * i);
            s.theta = 0.01 * i;
            s.omega = 0.5;
            s.flags = quint16(i % 3);
            batch.append(s);
            if (i == 2)
                recorder.addEvent(u"K_max 0.4 → 0.6"_qs);
        }
        recorder.append(batch);
        recorder.close();
    }
    QFile csv(csvPath);
    QFile json(recordingMetadataPath(csvPath));
    if (!csv.open(QIODevice::ReadOnly) || !json.open(QIODevice::ReadOnly))
        return 1;
    const QByteArray csvBytes = csv.readAll();
    const QByteArray jsonBytes = json.readAll();
    const auto toBytes = [](const QByteArray &a) { return Bytes(a.begin(), a.end()); };
    write(u"fuzz_recording"_qs, u"csv_only"_qs, toBytes(csvBytes));
    write(u"fuzz_recording"_qs, u"csv_and_json"_qs, toBytes(csvBytes + '\0' + jsonBytes));
    return 0;
}
