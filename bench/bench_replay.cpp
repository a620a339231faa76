// bench_replay [--events N[,N...]] [--rate HZ] [--bare --rows N]
//
// Opens generated recordings for replay as the tuner does (PlotFeed::openRecording: read the
// CSV, fill the replay buffer, draw the event markers into a PlotPanel) and prints the time it
// took and the process's peak resident memory (run one size per process for that figure).
// Each recording holds N events, one per row at the recorder's most (50 events/s), each a
// different note ("note 17"), between samples at --rate (default 50 Hz: every row carries an
// event). --bare instead writes --rows rows of only t_s and theta ("0.001,0"), no events: the
// smallest rows a reader accepts, so the most samples per megabyte.
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/replaycontroller.h"
#include "telemetry/recording.h"
#include "telemetry/samplecolumns.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <cstdio>
#include <sys/resource.h>

using namespace hatpic;

namespace {

//! Writes a recording of `events` events, one every 1/50 s, with samples at `rate` Hz.
QString writeRecording(const QString &dir, int events, double rate)
{
    const QString path = dir + QStringLiteral("/replay-%1.csv").arg(events);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    const QStringList columns = recordingColumns();
    file.write(columns.join(u',').toUtf8() + '\n');
    const double duration = events / 50.0;
    const qint64 rows = static_cast<qint64>(duration * rate) + 1;
    int written = 0;
    QByteArray line;
    for (qint64 i = 0; i < rows; ++i) {
        const double t = i / rate;
        line = QByteArray::number(t, 'f', 6);
        for (qsizetype c = 1; c + 1 < columns.size(); ++c)
            line += c == columns.indexOf(QStringLiteral("flags")) ? QByteArray(",0")
                                                                  : QByteArray(",0.125");
        line += ',';
        if (written < events && t * 50.0 >= written) {
            line +=
                "K_max " + QByteArray::number(written) + " → " + QByteArray::number(written + 1);
            ++written;
        }
        line += '\n';
        file.write(line);
    }
    return path;
}

QString writeBare(const QString &dir, qint64 rows)
{
    const QString path = dir + QStringLiteral("/bare-%1.csv").arg(rows);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("t_s,theta\n");
    QByteArray chunk;
    for (qint64 i = 0; i < rows; ++i) {
        chunk += QByteArray::number(i * 0.001, 'g', 10) + ",0\n";
        if (chunk.size() > (1 << 20)) {
            file.write(chunk);
            chunk.clear();
        }
    }
    file.write(chunk);
    return path;
}

double peakRssMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("events"), QStringLiteral("Events per recording."),
                      QStringLiteral("N,..."), QStringLiteral("50000,100000,200000")});
    parser.addOption({QStringLiteral("rate"), QStringLiteral("Sample rate [Hz]."),
                      QStringLiteral("HZ"), QStringLiteral("50")});
    parser.addOption({QStringLiteral("bare"), QStringLiteral("Rows of t_s and theta only.")});
    parser.addOption({QStringLiteral("rows"), QStringLiteral("Rows with --bare."),
                      QStringLiteral("N"), QStringLiteral("5000000")});
    parser.process(app);
    const double rate = parser.value(QStringLiteral("rate")).toDouble();
    const bool bare = parser.isSet(QStringLiteral("bare"));

    QTemporaryDir dir;
    std::printf("%10s %10s %12s %10s %12s %14s\n", "events", "rows", "CSV [MB]", "open [s]",
                "events held", "peak RSS [MiB]");
    const QStringList sizes = bare ? QStringList{QStringLiteral("0")}
                                   : parser.value(QStringLiteral("events")).split(u',');
    for (const QString &n : sizes) {
        const QString path =
            bare ? writeBare(dir.path(), parser.value(QStringLiteral("rows")).toLongLong())
                 : writeRecording(dir.path(), n.toInt(), rate);
        PlotPanel panel;
        panel.resize(1000, 760);
        PlotFeed feed(&panel);
        QElapsedTimer clock;
        clock.start();
        QString error;
        const bool ok = feed.openRecording(path, &error);
        const double seconds = clock.nsecsElapsed() / 1e9;
        if (!ok) {
            std::printf("%10s open failed: %s\n", qPrintable(n), qPrintable(error));
            continue;
        }
        if (!feed.replay()->warnings().isEmpty())
            std::printf("  %s\n", qPrintable(feed.replay()->warnings().constFirst()));
        std::printf("%10s %10lld %12.1f %10.2f %12lld %14.0f\n", qPrintable(n),
                    static_cast<long long>(feed.replay()->buffer().size()),
                    QFileInfo(path).size() / 1e6, seconds,
                    static_cast<long long>(feed.replay()->recording().events.size()), peakRssMiB());
        std::fflush(stdout);
        QFile::remove(path);
    }
    return 0;
}
