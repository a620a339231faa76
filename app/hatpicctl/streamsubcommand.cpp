// hatpicctl stream: telemetry to stdout or to a recording, then the link statistics.
#include "common/exitcodes.h"
#include "common/quitonsignal.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "session/sessionwording.h"
#include "subcommands.h"

#include "telemetry/recording.h"
#include "telemetry/samplecolumns.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QDateTime>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>

#include <cmath>
#include <optional>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

constexpr int kDefaultRateHz = 1000;

QString milliseconds(double ms)
{
    return ms < 0 ? u"–"_s : QString::number(ms, 'f', 3) + u" ms";
}

class StreamSubcommand final : public DeviceSubcommand
{
public:
    StreamSubcommand()
        : DeviceSubcommand(
              {.name = u"stream"_s,
               .summary = u"Stream telemetry (CSV to stdout, or a recording); link stats."_s,
               .synopsis =
                   u"stream --port PORT [--rate HZ] [--duration S] [--csv FILE [--force]]"_s,
               .description =
                   u"Streams telemetry for --duration seconds (default: until Ctrl+C).\n"
                   "Without --csv every sample goes to stdout as CSV with the header\n"_s +
                   QString::fromLatin1(sampleCsvHeader()) +
                   u",\n"
                   "then a device with several knobs or a tilt adds theta_2 ... p_ref_2, ...,\n"
                   "roll, pitch (docs/recording.md).\n"
                   "With --csv FILE the samples are recorded to FILE (the tuner's recording\n"
                   "format, metadata in FILE's .json sibling) and stdout stays empty. An\n"
                   "existing FILE or .json is never overwritten without --force.\n"
                   "Ctrl+C, SIGTERM and SIGHUP end the stream cleanly (recording closed).\n"
                   "At the end the link statistics go to stderr: frames/s, frames, frames\n"
                   "missing by sequence number, decoder drops by reason, round-trip time."_s})
    {}

protected:
    void addCommandOptions(QCommandLineParser &parser) override
    {
        parser.addOption(
            QCommandLineOption(u"rate"_s,
                               u"Telemetry rate to request (default: 1000); the device may clamp "
                               "it."_s,
                               u"HZ"_s, QString::number(kDefaultRateHz)));
        parser.addOption({u"duration"_s,
                          u"How long to stream, in seconds (default: until interrupted)."_s,
                          u"S"_s});
        parser.addOption({u"csv"_s, u"Record to FILE instead of stdout."_s, u"FILE"_s});
        parser.addOption({u"force"_s, u"Overwrite FILE and its .json if they exist."_s});
    }

    int prepare(const QCommandLineParser &parser, DeviceOptions &options) override
    {
        bool ok = false;
        const int rate = parser.value(u"rate"_s).toInt(&ok);
        if (!ok || rate < 1 || rate > 65535) {
            printError(u"--rate must be a whole number of Hz from 1 to 65535, got '" +
                       parser.value(u"rate"_s) + u"'.");
            return ExitBadUsage;
        }
        options.connect.streamRateHz = static_cast<quint16>(rate);
        m_duration = 0;
        if (parser.isSet(u"duration"_s)) {
            m_duration = parser.value(u"duration"_s).toDouble(&ok);
            if (!ok || !std::isfinite(m_duration) || m_duration <= 0 || m_duration > 1e6) {
                printError(u"--duration must be a number of seconds above 0, got '" +
                           parser.value(u"duration"_s) + u"'.");
                return ExitBadUsage;
            }
        }
        m_csvPath = parser.value(u"csv"_s);
        m_force = parser.isSet(u"force"_s);
        if (parser.isSet(u"csv"_s) && m_csvPath.isEmpty()) {
            printError(u"--csv needs a file name; without --csv the samples go to "
                       "stdout."_s);
            return ExitBadUsage;
        }
        // Everything about the files is checked before the port is opened or a file touched.
        if (!m_csvPath.isEmpty()) {
            if (const QString problem =
                    outputTargetProblem({m_csvPath, recordingMetadataPath(m_csvPath)}, m_force,
                                        u"a recording needs files of its own"_s);
                !problem.isEmpty()) {
                printError(problem);
                return ExitBadUsage;
            }
        }
        return ExitSuccess;
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &) override
    {
        DeviceClient &client = runner.client();
        const DeviceInfo info = client.deviceInfo();

        HostParams host;
        if (std::isfinite(info.tauLimit) && info.tauLimit > 0 && info.tauLimit <= 10)
            host.tau_limit = info.tauLimit;
        client.setHostParams(host);

        // The tuning in force, for the recording's metadata (legacy cannot tell).
        if (info.canSetParams()) {
            Outcome read;
            if (const int code = runner.runCommand(request::Read{}, &read); code)
                return code;
            if (const int code = DeviceRunner::reportOutcome(read); code)
                return code;
        }

        // The recording is the session's own (the tuner's too): written on the link's thread,
        // flushed every 0.5 s, with parameter events, closed cleanly if the port vanishes.
        QObject context;
        if (!m_csvPath.isEmpty()) {
            // --force: the user allowed replacing whatever .json is there (a profile, say),
            // which the recorder would otherwise refuse.
            const QString json = recordingMetadataPath(m_csvPath);
            if (m_force && QFileInfo(json).isFile() && !QFile::remove(json)) {
                printError(u"Cannot replace " + json + u'.');
                return ExitBadUsage;
            }
            // The session refuses a start with a notice (no device) or a status with an error.
            std::optional<SessionNotice> refused;
            QObject::connect(&client, &DeviceClient::notice, &context,
                             [&](const SessionNotice &notice) {
                                 if (notice.kind == SessionNotice::Kind::RecordingNeedsDevice)
                                     refused = notice;
                             });
            client.startRecording(m_csvPath, u"hatpicctl stream"_s);
            runner.runFor(kRecordingStartWaitS, [&] {
                const RecordingStatus status = client.recordingStatus();
                return status.active || !status.error.isEmpty() || refused;
            });
            if (!client.recordingStatus().active) {
                printError(u"Cannot write the recording " + m_csvPath + u": " +
                           asSentence(refused ? SessionWording::notice(*refused)
                                              : client.recordingStatus().error));
                return ExitBadUsage;
            }
        }
        // To stdout the header goes with the first samples: the IMU branch's board says what it
        // is (four knobs, a tilt) in its first frame. A stream without samples still gets it.
        std::optional<DeviceInfo> columnsOf;
        const auto writeHeader = [&] {
            if (columnsOf || !m_csvPath.isEmpty())
                return;
            columnsOf = client.deviceInfo();
            QByteArray header = sampleCsvHeader();
            for (const QByteArray &extra : extraSampleColumns(columnsOf->axes, columnsOf->tilt))
                header += ',' + extra;
            writeOut(header + '\n');
        };

        quint64 samples = 0;
        bool recordingFailed = false;
        bool stdoutClosed = false; // its reader went away (`| head`): the stream ends
        QObject::connect(&client, &DeviceClient::recordingChanged, &context,
                         [&](const RecordingStatus &status) {
                             if (!status.active && !status.error.isEmpty())
                                 recordingFailed = true;
                         });
        QObject::connect(
            &client, &DeviceClient::samplesReady, &context, [&](const SampleBatch &batch) {
                samples += static_cast<quint64>(batch.size());
                if (m_csvPath.isEmpty()) {
                    writeHeader();
                    QByteArray rows;
                    for (const Sample &sample : batch) {
                        appendSampleCsvRow(rows, sample);
                        appendExtraCsvFields(rows, sample, columnsOf->axes, columnsOf->tilt);
                        rows += '\n';
                    }
                    writeOut(rows);
                    stdoutClosed = stdoutClosed || !flushOut();
                }
            });
        QObject::connect(&client, &DeviceClient::statsUpdated, &context,
                         [&](const LinkStats &) { ++m_statsUpdates; });

        bool interrupted = false; // SIGINT, SIGTERM, SIGHUP: the stream ends in order
        int code = ExitSuccess;
        QElapsedTimer elapsed;
        elapsed.start();
        {
            const InterruptsCall interrupts([&] {
                interrupted = true;
                runner.wake();
            });
            code = runner.runFor(m_duration,
                                 [&] { return interrupted || recordingFailed || stdoutClosed; });
        }
        const double seconds = elapsed.nsecsElapsed() * 1e-9;
        writeHeader();
        QObject::disconnect(&client, &DeviceClient::samplesReady, &context, nullptr);

        // The recording covers the requested duration, not the wait for statistics below.
        RecordingStatus recorded = client.recordingStatus();
        if (recorded.active) {
            client.stopRecording();
            runner.runFor(kRecordingStartWaitS, [&] { return !client.recordingStatus().active; });
            recorded = client.recordingStatus();
        }

        // The statistics arrive periodically; wait for one more report (bounded) so the
        // figures cover the whole run.
        if (code == ExitSuccess) {
            const quint64 before = m_statsUpdates;
            runner.runFor(kStatsWaitS, [&] { return m_statsUpdates > before; });
        }

        flushOut();
        // With a recording, the figure is its rows on disk (what a reader will find).
        if (!m_csvPath.isEmpty())
            samples = recorded.samples;
        printStatistics(client, seconds, samples, recorded);

        if (code == ExitNoDevice)
            return runner.reportLoss();
        if (recordingFailed) {
            printError(u"The recording stopped: " + asSentence(recorded.error));
            return ExitBadUsage;
        }
        if (stdoutClosed) {
            printError(u"Standard output was closed by its reader after " +
                       QString::number(samples) + u" samples; the stream stopped.");
            return ExitBadUsage;
        }
        if (code == ExitSuccess && samples == 0) {
            const quint64 frames = client.stats().frames;
            if (frames == 0) {
                printError(u"No telemetry arrived from " + info.port + u" in " +
                           QString::number(seconds, 'f', 1) + u" s; the device did not stream.");
            } else {
                // It streams, only no frame fell within the run (a slow rate, a short run).
                const quint16 rate = runner.options().connect.streamRateHz;
                printError(u"No sample arrived within the " + QString::number(seconds, 'f', 1) +
                           u" s of the stream, though the device streams (" +
                           QString::number(frames) + (frames == 1 ? u" frame"_s : u" frames"_s) +
                           u" since connecting); at " + QString::number(rate) +
                           u" Hz a frame comes every " + QString::number(1.0 / rate, 'g', 3) +
                           u" s, so give a --duration of "
                           u"at least " +
                           QString::number(2.0 / rate, 'g', 3) + u" s.");
            }
            return ExitNoDevice;
        }
        return code;
    }

private:
    static constexpr double kStatsWaitS = 1.5;
    static constexpr double kRecordingStartWaitS = 2.0; //!< bound on opening/closing the files [s]

    void printStatistics(const DeviceClient &client, double seconds, quint64 samples,
                         const RecordingStatus &recorded) const
    {
        const LinkStats stats = client.stats();
        const DeviceInfo info = client.deviceInfo();
        const auto line = [](const char16_t *key, const QString &value) -> QString {
            return QString::fromUtf16(key).leftJustified(14) + value + u'\n';
        };
        QString text;
        text += line(u"link", info.port + u", " + wireProtocolName(info.protocol) + u", " +
                                  QString::number(info.baud) + u" baud");
        text += line(u"duration", QString::number(seconds, 'f', 3) + u" s");
        text += line(u"samples", QString::number(samples) + u" (" +
                                     QString::number(seconds > 0 ? samples / seconds : 0, 'f', 1) +
                                     u" per second)");
        text += line(u"frames/s",
                     QString::number(stats.framesPerSecond, 'f', 1) + u" over the last second");
        // Duplicates only when there were some: the line stays as it was on a sound link.
        text += line(u"frames",
                     QString::number(stats.frames) + u" received, " +
                         QString::number(stats.seqDrops) + u" missing by seq" +
                         (stats.duplicates > 0
                              ? u", " + QString::number(stats.duplicates) + u" received twice"
                              : QString()) +
                         u" (since connecting)");
        QStringList reasons;
        for (int r = 0; r < v2::kDropReasonCount; ++r) {
            reasons << v2::dropReasonName(static_cast<v2::DropReason>(r)) + u' ' +
                           QString::number(stats.decoderDrops[static_cast<std::size_t>(r)]);
        }
        QString drops =
            QString::number(stats.totalDecoderDrops()) + u" (" + reasons.join(u", "_s) + u')';
        if (info.protocol == WireProtocol::Legacy)
            drops += u", legacy malformed " + QString::number(stats.legacyMalformed);
        text += line(u"decoder drops", drops);
        text += line(u"rtt", u"last " + milliseconds(stats.rttLastMs) + u", median " +
                                 milliseconds(stats.rttMedianMs) + u", max " +
                                 milliseconds(stats.rttMaxMs));
        if (!m_csvPath.isEmpty()) {
            text +=
                line(u"recording", m_csvPath + u", " + QString::number(recorded.samples) +
                                       u" samples, " + QString::number(recorded.bytes) + u" bytes");
        }
        printNote(text);
    }

    double m_duration = 0; //!< [s]; 0 = until interrupted
    QString m_csvPath;
    bool m_force = false;
    quint64 m_statsUpdates = 0;
};

} // namespace

std::unique_ptr<Subcommand> makeStreamSubcommand()
{
    return std::make_unique<StreamSubcommand>();
}

} // namespace hatpic::cli
