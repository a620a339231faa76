// The Experiments panel with real widgets (offscreen) on the built-in simulated joystick: a
// short step experiment from the Run button to the figures, the overlay and the exports; the
// refusal on a legacy device; Cancel; the spectrum of the plots' visible window.
#include "analysis/frequencyresponse.h"
#include "experiments/experimentplots.h"
#include "experiments/experimentspanel.h"
#include "plots/axistitle.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "plots/samplebuffer.h"
#include "session/deviceclient.h"
#include "simulatoroptions.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QVBoxLayout>

#include <cmath>
#include <numbers>
#include <optional>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

constexpr int kConnectMs = 5000;
constexpr int kRunMs = 15000;

bool connectSim(DeviceClient &client, ProtocolChoice protocol = ProtocolChoice::V2)
{
    client.connectDevice(test::simulatorOptions({}, protocol));
    return QTest::qWaitFor([&] { return client.state() == SessionState::Connected; }, kConnectMs);
}

//! The figures table's cell (row named `name`, column 1 measured or 2 model) as a number.
double figure(const QTableWidget *table, const QString &name, int column)
{
    for (int row = 0; row < table->rowCount(); ++row) {
        if (table->item(row, 0)->text() == name)
            return table->item(row, column)->text().toDouble();
    }
    return std::nan("");
}

} // namespace

class TestExperimentsPanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void stepFromTheRunButton();
    void refusesALegacyDevice();
    void cancelStopsTheRun();
    void levelsFollowTheTuningAfterARun();
    void cautionOnADetent();
    void runKeepsTheKeyboard();
    void spectrumOfTheVisibleWindow();
    void bodePlotReadableWhenShort();
    void figuresBesideThePlotsOrATab();
};

void TestExperimentsPanel::stepFromTheRunButton()
{
    DeviceClient client;
    QVERIFY(connectSim(client));
    ExperimentsPanel panel(&client, test::joystickOf(client.options()), nullptr);
    panel.resize(1000, 600);
    panel.show();
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params, kConnectMs);
    // A knob the simulated servo follows closely (docs/experiments.md, the tolerance):
    // ω_n = 14.14 rad/s, ζ = 0.707.
    DeviceParams slow = *client.deviceTuning().params;
    slow.D_adm = 2e-3;
    slow.M_adm = 4e-2;
    QObject caller;
    std::optional<Outcome> pushed;
    client.request(request::Push{{slow, std::nullopt}},
                   {&caller, [&pushed](const Outcome &o) { pushed = o; }});
    QTRY_VERIFY_WITH_TIMEOUT(pushed.has_value(), kConnectMs);
    // The push's result comes after its read-back: the device's parameters are the new ones.
    QCOMPARE(std::get<outcome::Done>(pushed->result).readBack, outcome::ReadBack::Matches);
    QVERIFY(std::abs(client.deviceTuning().params->D_adm - 2e-3) < 1e-9);
    panel.fillDefaults();
    // The defaults for the device's parameters (K_max 0.4, band [0.02, 0.1]).
    auto *to = panel.findChild<QDoubleSpinBox *>(u"stepTo"_s);
    QVERIFY(std::abs(to->value() - 0.4 * 0.08) < 1e-5);
    auto *run = panel.findChild<QPushButton *>(u"runExperiment"_s);
    QVERIFY(run->isEnabled());
    // The simulator's hand is the program's to lift: nobody is told to let go of a knob.
    QCOMPARE(panel.status(), u"The simulated hand is idle while an experiment runs."_s);
    QSignalSpy runningChanged(&panel, &ExperimentsPanel::runningChanged);
    QSignalSpy finished(&panel, &ExperimentsPanel::finished);
    QTest::mouseClick(run, Qt::LeftButton);
    QVERIFY(panel.running());
    QVERIFY(!run->isEnabled());
    QVERIFY(panel.findChild<QPushButton *>(u"cancelExperiment"_s)->isEnabled());
    QCOMPARE(runningChanged.size(), 1);
    QVERIFY(runningChanged.first().first().toBool());
    QVERIFY(panel.status().startsWith(u"Running… the simulated hand is idle"_s));
    QVERIFY(finished.wait(kRunMs));
    QVERIFY2(panel.result() && panel.result()->completed(), qPrintable(panel.status()));
    QCOMPARE(runningChanged.size(), 2);
    QVERIFY(!runningChanged.last().first().toBool());
    // What held the knob, first among the figures and on the plot's time axis; the main
    // figures in the status line.
    QCOMPARE(panel.figures()->item(0, 0)->text(), u"Hand on the knob"_s);
    QCOMPARE(panel.figures()->item(0, 1)->text(), u"idle (simulated)"_s);
    QVERIFY(panel.plots()
                ->plot(ExperimentPlots::StepTab)
                ->xAxis->label()
                .contains(u"hand: idle (simulated)"_s));
    QVERIFY2(panel.status().contains(u"ω_n "_s) && panel.status().contains(u"(model 14.1)"_s),
             qPrintable(panel.status()));

    // Measured next to the model's derived figures (within 10 %, docs/experiments.md).
    const QTableWidget *table = panel.figures();
    const double omegaN = figure(table, u"ω_n [rad/s]"_s, 1);
    const double omegaModel = figure(table, u"ω_n [rad/s]"_s, 2);
    QCOMPARE(omegaModel, 14.14);
    QVERIFY2(std::abs(omegaN / omegaModel - 1) < 0.1, qPrintable(QString::number(omegaN)));
    QVERIFY(std::abs(figure(table, u"ζ"_s, 1) / figure(table, u"ζ"_s, 2) - 1) < 0.1);

    // The overlay: the measured step and the ideal model's, both rising to Δτ/K_max = 0.04 rad.
    QCustomPlot *step = panel.plots()->plot(ExperimentPlots::StepTab);
    QCOMPARE(panel.plots()->currentWidget(), step);
    QCOMPARE(step->graphCount(), 2);
    for (int i = 0; i < 2; ++i) {
        const auto data = step->graph(i)->data();
        QVERIFY(data->size() > 100);
        QVERIFY2(std::abs((data->end() - 1)->value - 0.04) < 0.004,
                 qPrintable(QString::number((data->end() - 1)->value)));
    }

    QTemporaryDir dir;
    QString error;
    QVERIFY2(panel.exportCsv(dir.filePath(u"step.csv"_s), &error), qPrintable(error));
    QFile csv(dir.filePath(u"step.csv"_s));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    QCOMPARE(csv.readLine(), QByteArray("t_s,theta,tau_ext,model_theta\n"));
    for (const QString &name : {u"step.png"_s, u"step.svg"_s}) {
        QVERIFY2(panel.exportImage(dir.filePath(name), &error), qPrintable(error));
        QVERIFY(QFile(dir.filePath(name)).size() > 1000);
    }
    QFile svg(dir.filePath(u"step.svg"_s));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    QVERIFY(svg.readAll().contains("<svg"));
}

void TestExperimentsPanel::refusesALegacyDevice()
{
    DeviceClient client;
    QVERIFY(connectSim(client, ProtocolChoice::Legacy));
    ExperimentsPanel panel(&client, test::joystickOf(client.options()), nullptr);
    QVERIFY(!panel.run());
    QVERIFY2(panel.status().contains(u"legacy"_s), qPrintable(panel.status()));
    QVERIFY(!panel.running());
}

void TestExperimentsPanel::cancelStopsTheRun()
{
    DeviceClient client;
    QVERIFY(connectSim(client));
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params, kConnectMs);
    ExperimentsPanel panel(&client, test::joystickOf(client.options()), nullptr);
    panel.findChild<QDoubleSpinBox *>(u"duration"_s)->setValue(20);
    QVERIFY(panel.run());
    QTest::mouseClick(panel.findChild<QPushButton *>(u"cancelExperiment"_s), Qt::LeftButton);
    QVERIFY(!panel.running());
    QCOMPARE(panel.status(), u"The experiment was cancelled."_s);
    QVERIFY(!panel.result()); // nothing half-measured is shown as a result
}

namespace {

//! Pushes `params` and waits for the device's read-back.
bool pushParams(DeviceClient &client, const DeviceParams &params)
{
    QObject caller;
    bool pushed = false;
    client.request(request::Push{{params, std::nullopt}},
                   {&caller, [&pushed](const Outcome &) { pushed = true; }});
    return QTest::qWaitFor([&] { return pushed; }, kConnectMs) &&
           QTest::qWaitFor([&] { return client.deviceTuning().params == roundedToFloat(params); },
                           kConnectMs);
}

} // namespace

// Issue 27: the levels followed the device's parameters until a run, then kept the old ones,
// and the next step left the notch band. They follow it always, except the fields typed.
void TestExperimentsPanel::levelsFollowTheTuningAfterARun()
{
    DeviceClient client;
    QVERIFY(connectSim(client));
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params, kConnectMs);
    ExperimentsPanel panel(&client, test::joystickOf(client.options()), nullptr);
    panel.show();
    auto *kind = panel.findChild<QComboBox *>(u"experimentKind"_s);
    auto *from = panel.findChild<QDoubleSpinBox *>(u"stepFrom"_s);
    auto *to = panel.findChild<QDoubleSpinBox *>(u"stepTo"_s);
    // A short run: a spectrum of 0.1 s, so the panel holds a result.
    kind->setCurrentIndex(kind->findData(int(ExperimentKind::Spectrum)));
    panel.findChild<QDoubleSpinBox *>(u"duration"_s)->setValue(0.1);
    QSignalSpy finished(&panel, &ExperimentsPanel::finished);
    QVERIFY(panel.run());
    QVERIFY(finished.wait(kRunMs));
    QVERIFY(panel.result());
    kind->setCurrentIndex(kind->findData(int(ExperimentKind::Step)));

    DeviceParams stiff = *client.deviceTuning().params;
    stiff.K_max = 0.8;
    QVERIFY(pushParams(client, stiff));
    const ExperimentPlan expected = ExperimentPlan::defaults(ExperimentKind::Step, stiff);
    QTRY_VERIFY(std::abs(to->value() - expected.tauTo) < 1e-5);
    QVERIFY(std::abs(from->value() - expected.tauFrom) < 1e-5);

    // A level the user typed stays; the other follows.
    to->setFocus();
    to->selectAll();
    QTest::keyClicks(to, u"0.05"_s);
    QVERIFY(std::abs(to->value() - 0.05) < 1e-9);
    QVERIFY(panel.typed(to));
    stiff.K_max = 0.6;
    QVERIFY(pushParams(client, stiff));
    const ExperimentPlan next = ExperimentPlan::defaults(ExperimentKind::Step, stiff);
    QTRY_VERIFY(std::abs(from->value() - next.tauFrom) < 1e-5);
    QVERIFY(std::abs(to->value() - 0.05) < 1e-9);
    // Defaults fills them all again.
    panel.fillDefaults();
    QVERIFY(std::abs(to->value() - next.tauTo) < 1e-5);
    QVERIFY(!panel.typed(to));
}

// Issue 27: on the Detents preset a detent held the knob, the step moved it 2 encoder counts,
// and its ω_n was reported as a result. The effects are named before the run, and the result
// says its operating point is not the model's.
void TestExperimentsPanel::cautionOnADetent()
{
    DeviceClient client;
    QVERIFY(connectSim(client));
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params, kConnectMs);
    ExperimentsPanel panel(&client, test::joystickOf(client.options()), nullptr);
    panel.resize(1000, 600);
    panel.show();
    QVERIFY(!panel.status().contains(u"Caution"_s));
    // The Detents preset (resources/presets/detents.json).
    DeviceParams p = *client.deviceTuning().params;
    p.M_adm = 0.015;
    p.K_min = 0.03;
    p.K_max = 1.3;
    p.N = 0.01;
    p.Q_dz = 0.005;
    EffectParams fx;
    fx.detent_strength = 0.04;
    fx.detent_spacing = 0.2;
    fx.detent_range = 0.9;
    QObject caller;
    bool pushed = false;
    client.request(request::Push{{p, fx}},
                   {&caller, [&pushed](const Outcome &) { pushed = true; }});
    QTRY_VERIFY_WITH_TIMEOUT(pushed, kConnectMs);
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().effects &&
                                 client.deviceTuning().effects->detent_strength > 0,
                             kConnectMs);
    QTRY_VERIFY2(panel.status().contains(u"Caution: Detents are on"_s), qPrintable(panel.status()));
    QSignalSpy finished(&panel, &ExperimentsPanel::finished);
    QVERIFY(panel.run());
    QVERIFY(finished.wait(kRunMs));
    QVERIFY2(panel.status().contains(u"encoder counts"_s), qPrintable(panel.status()));
    QCOMPARE(panel.figures()->item(1, 0)->text(), u"Operating point"_s);
    QCOMPARE(panel.figures()->item(1, 1)->text(), u"not the model's (see the status)"_s);
}

// Issue 27: Run, disabled once pressed, handed the focus on to the next widget of the window (the
// simulated hand's selector). It goes to Cancel, and back to Run when the run ends.
void TestExperimentsPanel::runKeepsTheKeyboard()
{
    DeviceClient client;
    QVERIFY(connectSim(client));
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params, kConnectMs);
    QWidget window;
    auto *panel =
        new ExperimentsPanel(&client, test::joystickOf(client.options()), nullptr, &window);
    auto *after = new QComboBox(&window); // what comes next in the window's focus chain
    auto *layout = new QVBoxLayout(&window);
    layout->addWidget(panel);
    layout->addWidget(after);
    window.show();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    auto *kind = panel->findChild<QComboBox *>(u"experimentKind"_s);
    kind->setCurrentIndex(kind->findData(int(ExperimentKind::Spectrum)));
    panel->findChild<QDoubleSpinBox *>(u"duration"_s)->setValue(0.2);
    auto *run = panel->findChild<QPushButton *>(u"runExperiment"_s);
    auto *cancel = panel->findChild<QPushButton *>(u"cancelExperiment"_s);
    run->setFocus(Qt::TabFocusReason);
    QSignalSpy finished(panel, &ExperimentsPanel::finished);
    QTest::keyClick(run, Qt::Key_Space);
    QVERIFY(panel->running());
    QCOMPARE(QApplication::focusWidget(), cancel);
    QVERIFY(finished.wait(kRunMs));
    QCOMPARE(QApplication::focusWidget(), run);
}

void TestExperimentsPanel::spectrumOfTheVisibleWindow()
{
    DeviceClient client;
    PlotPanel plots;
    SampleBuffer buffer;
    // One second of a knob chattering at 50 Hz, 1 mrad, on the plots.
    for (int i = 0; i < 1000; ++i) {
        Sample s;
        s.t_s = i * 1e-3;
        s.theta = 1e-3 * std::sin(2 * std::numbers::pi * 50 * s.t_s);
        s.tau = 1e-3 * std::sin(2 * std::numbers::pi * 120 * s.t_s);
        buffer.append(s);
    }
    plots.setSource(&buffer);
    plots.setWindowLength(1.0);
    plots.setViewEnd(0.999);
    ExperimentsPanel panel(&client, test::joystickOf(client.options()), &plots);
    panel.showVisibleSpectrum();
    QCustomPlot *spectrum = panel.plots()->plot(ExperimentPlots::SpectrumTab);
    QCOMPARE(panel.plots()->currentWidget(), spectrum);
    QCOMPARE(spectrum->graphCount(), 2);
    // The θ line at 50 Hz reads 20·log10(1e-3) = −60 dB.
    const auto theta = spectrum->graph(0)->data();
    auto peak = theta->begin();
    for (auto it = theta->begin(); it != theta->end(); ++it)
        peak = it->value > peak->value ? it : peak;
    QVERIFY2(std::abs(peak->key - 50) < 1.01, qPrintable(QString::number(peak->key)));
    QVERIFY(std::abs(peak->value + 60) < 1.5);
}

// Once, in the short dock of a 1280×720 window, the Bode plot's labels ran into each other (two
// frequency labels, and a gain label longer than its plot is tall) and its legend lay over the
// measured points.
void TestExperimentsPanel::bodePlotReadableWhenShort()
{
    ExperimentPlots plots;
    plots.resize(450, 230);
    plots.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plots));
    ExperimentResult r;
    r.plan.kind = ExperimentKind::Frequency;
    for (double f : {2.0, 4.0, 8.0, 12.0, 16.0, 24.0}) {
        analysis::FrequencyPoint p;
        p.frequency = f;
        p.gain = analysis::modelGain(r.params, f) * 0.9;
        p.magnitude = std::abs(p.gain);
        p.phase = std::arg(p.gain);
        r.points.push_back(p);
    }
    plots.showResult(r);
    QCustomPlot *bode = plots.plot(ExperimentPlots::BodeTab);
    QCOMPARE(plots.currentWidget(), bode);
    bode->replot();
    QCPAxisRect *gain = bode->axisRect(0);
    QCPAxisRect *phase = bode->axisRect(1);
    QVERIFY(gain->axis(QCPAxis::atBottom)->label().isEmpty()); // one frequency axis, labelled
    QVERIFY(!phase->axis(QCPAxis::atBottom)->label().isEmpty());
    QList<QRect> titles; // level in a corner of each plot, never along an axis
    for (QCPAxisRect *rect : {gain, phase}) {
        QVERIFY(rect->axis(QCPAxis::atLeft)->label().isEmpty());
        const QCPItemText *title = cornerTitle(rect);
        QVERIFY(title && !title->text().isEmpty());
        const QRect box =
            QRectF(title->topLeft->pixelPosition(), title->bottomRight->pixelPosition())
                .toAlignedRect();
        QVERIFY2(rect->rect().contains(box), qPrintable(title->text()));
        titles.append(box);
    }
    QVERIFY(!titles[0].intersects(titles[1]));
    QVERIFY(!gain->rect().intersects(phase->rect()));
    int legends = 0;
    for (QCPLayoutElement *element : bode->plotLayout()->elements(true)) {
        if (auto *legend = qobject_cast<QCPLegend *>(element); legend && legend->itemCount() > 0) {
            QVERIFY(!legend->outerRect().intersects(gain->rect()));
            QVERIFY(!legend->outerRect().intersects(phase->rect()));
            ++legends;
        }
    }
    QCOMPARE(legends, 1);
}

void TestExperimentsPanel::figuresBesideThePlotsOrATab()
{
    DeviceClient client;
    ExperimentsPanel panel(&client, test::joystickOf(client.options()), nullptr);
    panel.resize(1100, 350);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto *results = panel.findChild<QWidget *>(u"experimentResults"_s);
    QVERIFY(results);
    QCOMPARE(panel.plots()->indexOf(results), -1); // beside the plots
    QVERIFY(results->isVisible());
    panel.resize(720, 300); // the dock at 1280×720
    QTRY_VERIFY(panel.plots()->indexOf(results) >= 0);
    QCOMPARE(panel.plots()->tabText(panel.plots()->indexOf(results)), u"Figures"_s);
    QVERIFY(panel.plots()->plot(ExperimentPlots::StepTab)->width() >=
            ExperimentsPanel::kMinPlotWidth);
    panel.resize(1100, 350);
    QTRY_COMPARE(panel.plots()->indexOf(results), -1);
    QVERIFY(results->isVisible());
}

QTEST_MAIN(TestExperimentsPanel)
#include "tst_experimentspanel.moc"
