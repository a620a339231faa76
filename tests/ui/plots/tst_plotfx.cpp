// The torque plot's τ_fx series (effects.md): drawn from the samples that carry τ_fx, nothing
// where the device does not send it (NaN), in its own colour, listed in the legend with its
// value, and written by the CSV export as the tau_fx column; and its parts τ_det, τ_wall and
// τ_vib, computed by the buffer from θ, ω and the device's block, off by default.
#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace hatpic;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

//! 1 kHz samples over [from, to): τ_fx = 0.03·sin(2π·t) before `knownUntil`, NaN after.
void fill(SampleBuffer &buffer, double from, double to, double knownUntil)
{
    const int n = int(std::lround((to - from) * 1000));
    for (int i = 0; i < n; ++i) {
        Sample s;
        s.t_s = from + i / 1000.0;
        s.theta = 0.1 * std::sin(s.t_s);
        s.tau_rec = -0.4 * s.theta;
        s.tau_fx = s.t_s < knownUntil ? 0.03 * std::sin(2 * std::numbers::pi * s.t_s) : kNaN;
        s.tau_total = s.tau_rec + (std::isnan(s.tau_fx) ? 0.0 : s.tau_fx);
        buffer.append(s);
    }
}

} // namespace

class TestPlotFx : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tauFxIsATorqueSeries();
    void drawsOnlyWhereKnown();
    void legacyDrawsNothing();
    void exportWritesTauFx();
    void bufferSplitsTauFx();
    void partsAreOptionalSeries();
};

void TestPlotFx::tauFxIsATorqueSeries()
{
    PlotPanel panel;
    QCPGraph *g = panel.graph(Channel::TauFx);
    QVERIFY(g);
    QCOMPARE(g->valueAxis(), panel.graph(Channel::TauRec)->valueAxis()); // the torque plot
    QCOMPARE(g->pen().color(), palette::channel(Channel::TauFx));
    QVERIFY(panel.isChannelVisible(Channel::TauFx));
    QVERIFY(panel.legend(PlotPanel::Plot::Torque)->hasItemWithPlottable(g));
    QCOMPARE(channelLabel(Channel::TauFx), QStringLiteral("τ_fx"));
    panel.setChannelVisible(Channel::TauFx, false);
    QVERIFY(!g->visible());
}

void TestPlotFx::drawsOnlyWhereKnown()
{
    SampleBuffer buffer;
    fill(buffer, 0, 4, 2.0); // τ_fx known for 2 s, then a device that does not send it
    PlotPanel panel;
    panel.resize(900, 600);
    panel.setSource(&buffer);
    panel.setWindowLength(5);
    panel.repaintNow();
    const QCPGraph *g = panel.graph(Channel::TauFx);
    QVERIFY(panel.pointCount(Channel::TauFx) > 0);
    double lo = 0;
    double hi = 0;
    int known = 0;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
        if (std::isnan(it->value))
            continue;
        ++known;
        QVERIFY2(it->key < 2.0, qPrintable(QString::number(it->key)));
        lo = std::min(lo, it->value);
        hi = std::max(hi, it->value);
    }
    QVERIFY(known > 0);
    // The decimated series keeps the extremes of the data.
    QVERIFY(std::abs(hi - 0.03) < 1e-6 && std::abs(lo + 0.03) < 1e-6);
    // The legend's value at the newest sample: unknown.
    QVERIFY2(g->name().contains(QStringLiteral("—")), qPrintable(g->name()));
}

void TestPlotFx::legacyDrawsNothing()
{
    SampleBuffer buffer;
    fill(buffer, 0, 2, -1.0); // never known
    PlotPanel panel;
    panel.resize(900, 600);
    panel.setSource(&buffer);
    panel.repaintNow();
    const QCPGraph *g = panel.graph(Channel::TauFx);
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
        QVERIFY(std::isnan(it->value));
    QVERIFY(panel.pointCount(Channel::TauRec) > 0); // the others are drawn
}

void TestPlotFx::exportWritesTauFx()
{
    SampleBuffer buffer;
    fill(buffer, 0, 4, 2.0);
    PlotPanel panel;
    panel.setSource(&buffer);
    panel.setWindowLength(5);
    panel.repaintNow();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("fx.csv"));
    QString error;
    const qsizetype rows = panel.exportCsv(path, &error);
    QVERIFY2(rows == buffer.size(), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = file.readAll().split('\n');
    const QList<QByteArray> header = lines.first().split(',');
    const qsizetype column = header.indexOf("tau_fx");
    QVERIFY(column > 0);
    int known = 0;
    int unknown = 0;
    for (qsizetype i = 1; i + 1 < lines.size(); ++i) {
        const QList<QByteArray> fields = lines.at(i).split(',');
        const double t = fields.at(0).toDouble();
        const QByteArray fx = fields.at(column);
        if (t < 2.0 - 1e-9) {
            bool ok = false;
            QVERIFY(std::abs(fx.toDouble(&ok) - 0.03 * std::sin(2 * std::numbers::pi * t)) < 1e-9);
            QVERIFY(ok);
            ++known;
        } else {
            QVERIFY(fx.isEmpty());
            ++unknown;
        }
    }
    QCOMPARE(known, 2000);
    QCOMPARE(unknown, 2000);
}

void TestPlotFx::bufferSplitsTauFx()
{
    // Detents A = 0.04 every 0.2 rad over ±1; a wall at +0.3 (K_w = 2, B_w = 0.5); θ0 = 0.1.
    const EffectParams fx{.detent_strength = 0.04,
                          .detent_spacing = 0.2,
                          .detent_range = 1.0,
                          .wall_max = 0.3,
                          .wall_stiffness = 2.0,
                          .wall_damping = 0.5};
    SampleBuffer buffer;
    Sample s;
    s.theta = 0.15; // e = 0.05: τ_det = −0.04
    s.omega = 1.0;
    s.tau_fx = -0.04 + 0.01; // plus a cue of 0.01
    buffer.append(s);        // no block known yet: parts unknown
    buffer.setEffects(fx, 0.1);
    s.t_s = 0.001;
    buffer.append(s);
    s.t_s = 0.002;
    s.theta = 0.5; // e = 0.4: 0.1 beyond the wall, moving in: −2·0.1 − 0.5·1 = −0.7; τ_det ≈ 0
    s.tau_fx = -0.7;
    buffer.append(s);
    s.t_s = 0.003;
    s.tau_fx = kNaN; // unknown τ_fx: unknown parts
    buffer.append(s);
    for (Channel part : {Channel::TauDet, Channel::TauWall, Channel::TauVib}) {
        QVERIFY(std::isnan(buffer.value(part, 0)));
        QVERIFY(std::isnan(buffer.value(part, 3)));
    }
    QVERIFY(std::abs(buffer.value(Channel::TauDet, 1) + 0.04) < 1e-12);
    QCOMPARE(buffer.value(Channel::TauWall, 1), 0.0);
    QVERIFY(std::abs(buffer.value(Channel::TauVib, 1) - 0.01) < 1e-12);
    QVERIFY(std::abs(buffer.value(Channel::TauWall, 2) + 0.7) < 1e-12);
    QVERIFY(std::abs(buffer.value(Channel::TauDet, 2)) < 1e-12);
    QVERIFY(std::abs(buffer.value(Channel::TauVib, 2)) < 1e-12);
    // The parts are not Sample columns: a round trip keeps τ_fx, not them.
    QCOMPARE(buffer.sample(1).tau_fx, -0.03);
}

void TestPlotFx::partsAreOptionalSeries()
{
    const EffectParams fx{.detent_strength = 0.03, .detent_spacing = 0.2, .detent_range = 1.0};
    SampleBuffer buffer;
    buffer.setEffects(fx, 0.0);
    fill(buffer, 0, 4, 2.0);
    PlotPanel panel;
    panel.resize(900, 600);
    panel.setSource(&buffer);
    panel.setWindowLength(5);
    panel.repaintNow();
    for (Channel part : {Channel::TauDet, Channel::TauWall, Channel::TauVib}) {
        QVERIFY(!panel.isChannelVisible(part)); // off by default
        QCOMPARE(panel.pointCount(part), 0);
        QCOMPARE(panel.graph(part)->valueAxis(), panel.graph(Channel::TauFx)->valueAxis());
        panel.setChannelVisible(part, true);
    }
    panel.repaintNow();
    // τ_det drawn where τ_fx is known (t < 2 s), nothing after.
    const QCPGraph *det = panel.graph(Channel::TauDet);
    int known = 0;
    for (auto it = det->data()->constBegin(); it != det->data()->constEnd(); ++it) {
        if (std::isnan(it->value))
            continue;
        ++known;
        QVERIFY(it->key < 2.0);
        QVERIFY(std::abs(it->value) <= 0.03 + 1e-12);
    }
    QVERIFY(known > 0);
    QVERIFY(panel.graph(Channel::TauWall)->name().startsWith(QStringLiteral("τ_wall")));
}

QTEST_MAIN(TestPlotFx)
#include "tst_plotfx.moc"
