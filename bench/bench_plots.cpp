// bench_plots [--seconds S] [--rate HZ] [--frames N] [--width W] [--height H]
//             [--no-fast-polylines]
//
// Measures the live-plot pipeline at telemetry rate: appending samples to the SampleBuffer,
// decimating one channel of a full window, and a full repaint of the three plots (decimate
// every visible series + QCustomPlot replot + the widget paint), on the offscreen platform
// unless QT_QPA_PLATFORM says otherwise. Prints medians, 95th percentiles and maxima. Times are
// the CPU time of the GUI thread (benchclock.h), except the panel's own decimate and replot
// figures, which it measures in wall time.
#include "benchclock.h"

#include "plots/decimator.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "plots/samplebuffer.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFile>
#include <QSysInfo>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

using namespace hatpic;

namespace {

struct Figures
{
    double median = 0;
    double p95 = 0;
    double max = 0;
};

Figures summarize(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    Figures f;
    if (values.empty())
        return f;
    f.median = values[values.size() / 2];
    f.p95 = values[std::min(values.size() - 1, values.size() * 95 / 100)];
    f.max = values.back();
    return f;
}

Sample makeSample(qint64 i, double rate)
{
    Sample s;
    s.t_s = double(i) / rate;
    s.theta = 0.4 * std::sin(2 * std::numbers::pi * 0.2 * s.t_s) + 0.001 * std::sin(i * 1.7);
    s.omega = 0.5 * std::cos(2 * std::numbers::pi * 0.2 * s.t_s);
    s.tau = -0.06 * std::sin(2 * std::numbers::pi * 0.2 * s.t_s);
    s.tau_rec = -0.4 * s.theta;
    s.tau_ext = 0.01 * std::sin(i * 0.01);
    s.tau_total = s.tau_rec + s.tau_ext;
    s.v_ref = 0.5 * s.theta;
    s.p_ref = 0.1 * s.t_s;
    s.flags = 0;
    return s;
}

QString cpuModel()
{
    QFile file(QStringLiteral("/proc/cpuinfo"));
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("unknown CPU");
    const QList<QByteArray> lines = file.readAll().split('\n');
    for (const QByteArray &line : lines) {
        if (line.startsWith("model name"))
            return QString::fromUtf8(line.mid(line.indexOf(':') + 1).trimmed());
    }
    return QStringLiteral("unknown CPU");
}

void print(const char *what, const Figures &f, const char *unit)
{
    std::printf("%-44s median %9.3f  p95 %9.3f  max %9.3f %s\n", what, f.median, f.p95, f.max,
                unit);
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addHelpOption();
    const QCommandLineOption secondsOpt(QStringLiteral("seconds"),
                                        QStringLiteral("Window length [s] (60)."),
                                        QStringLiteral("S"), QStringLiteral("60"));
    const QCommandLineOption rateOpt(QStringLiteral("rate"),
                                     QStringLiteral("Telemetry rate [Hz] (1000)."),
                                     QStringLiteral("HZ"), QStringLiteral("1000"));
    const QCommandLineOption framesOpt(QStringLiteral("frames"),
                                       QStringLiteral("Repaints to time (300)."),
                                       QStringLiteral("N"), QStringLiteral("300"));
    const QCommandLineOption widthOpt(QStringLiteral("width"),
                                      QStringLiteral("Plot widget width [px] (1000)."),
                                      QStringLiteral("W"), QStringLiteral("1000"));
    const QCommandLineOption heightOpt(QStringLiteral("height"),
                                       QStringLiteral("Plot widget height [px] (760)."),
                                       QStringLiteral("H"), QStringLiteral("760"));
    const QCommandLineOption slowLinesOpt(
        QStringLiteral("no-fast-polylines"),
        QStringLiteral("Draw lines segment by segment (QCustomPlot's default) for comparison."));
    parser.addOptions({secondsOpt, rateOpt, framesOpt, widthOpt, heightOpt, slowLinesOpt});
    parser.process(app);
    const double seconds = parser.value(secondsOpt).toDouble();
    const double rate = parser.value(rateOpt).toDouble();
    const int frames = parser.value(framesOpt).toInt();
    const int width = parser.value(widthOpt).toInt();
    const int height = parser.value(heightOpt).toInt();
    const qint64 window = std::llround(seconds * rate);
    const double repaintHz = PlotPanel::kDefaultRepaintHz;
    const qint64 perFrame = std::llround(rate / repaintHz);

    std::printf("bench_plots: %.0f s window at %.0f Hz (%lld samples), plots %d×%d px, "
                "platform %s\n",
                seconds, rate, window, width, height, qPrintable(QApplication::platformName()));
    std::printf("machine: %s, %d cores, %s\n", qPrintable(cpuModel()), QThread::idealThreadCount(),
                qPrintable(QSysInfo::prettyProductName()));

    // 1. Append: batches of 20 samples (the session's 50 Hz batches at 1 kHz).
    {
        SampleBuffer buffer(SampleBuffer::kDefaultCapacity);
        SampleBatch batch;
        std::vector<double> perSample;
        qint64 i = 0;
        for (int round = 0; round < 2000; ++round) {
            batch.clear();
            for (int k = 0; k < 20; ++k)
                batch.append(makeSample(i++, rate));
            const double t0 = benchclock::threadNs();
            buffer.append(batch);
            perSample.push_back((benchclock::threadNs() - t0) / 20.0);
        }
        print("append, per sample (batches of 20)", summarize(perSample), "ns");
    }

    // 2. Decimate one channel of a full window onto the plot width.
    SampleBuffer buffer(std::max<qint64>(window + perFrame * (frames + 10), 1));
    for (qint64 i = 0; i < window; ++i)
        buffer.append(makeSample(i, rate));
    {
        Decimator decimator(width - 260);
        QVector<QCPGraphData> out;
        std::vector<double> ms;
        for (int round = 0; round < 200; ++round) {
            const double t0 = benchclock::threadNs();
            decimator.run(buffer, Channel::TauRec, buffer.lastTime() - seconds, buffer.lastTime(),
                          1.0, out);
            ms.push_back((benchclock::threadNs() - t0) / 1e6);
        }
        print("decimate one channel, full window", summarize(ms), "ms");
        std::printf("%-44s %lld samples -> %lld points\n", "", window, qint64(out.size()));
    }

    // 3. Full repaints while data keeps arriving, as in the live window.
    PlotPanel panel;
    panel.resize(width, height);
    panel.setSource(&buffer);
    panel.setWindowLength(seconds);
    panel.setRepaintRate(1); // the benchmark drives the repaints itself
    if (parser.isSet(slowLinesOpt))
        panel.customPlot()->setPlottingHint(QCP::phFastPolylines, false);
    DeviceParams params;
    panel.setDeviceParams(params);
    panel.show();
    QApplication::processEvents();
    panel.repaintNow();
    QApplication::processEvents();
    std::vector<double> frameMs;
    std::vector<double> decimateMs;
    std::vector<double> replotMs;
    qint64 next = window;
    for (int f = 0; f < frames; ++f) {
        SampleBatch batch;
        for (qint64 k = 0; k < perFrame; ++k)
            batch.append(makeSample(next++, rate));
        buffer.append(batch);
        const double t0 = benchclock::threadNs();
        panel.repaintIfNeeded();
        QApplication::processEvents(); // the widget's paint event (blits the replotted buffer)
        frameMs.push_back((benchclock::threadNs() - t0) / 1e6);
        decimateMs.push_back(panel.repaintStats().lastDecimateMs);
        replotMs.push_back(panel.repaintStats().lastReplotMs);
    }
    print("repaint: decimate 7 visible series (wall)", summarize(decimateMs), "ms");
    print("repaint: QCustomPlot replot (wall)", summarize(replotMs), "ms");
    print("repaint: whole frame incl. paint event (CPU)", summarize(frameMs), "ms");
    std::printf("%-44s %lld points drawn per frame\n", "", qint64(panel.repaintStats().lastPoints));
    const Figures total = summarize(frameMs);
    std::printf("%-44s %.1f %% of one core at %.0f Hz (median frame)\n", "",
                total.median * repaintHz / 10.0, repaintHz);
    return 0;
}
