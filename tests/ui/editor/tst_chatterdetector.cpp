// Chatter at the dead-zone edge, detected from the simulated joystick's own telemetry: the
// Notchy preset as it was (a 0.06 N·m notch step) buzzed under the simulator's gentle hand;
// every shipped preset must not. The warning shows in the derived figures.
#include "editor/chatterdetector.h"
#include "editor/derivedfiguresview.h"
#include "editor/parametereditor.h"
#include "editorrig.h"
#include "profile/profile.h"
#include "sim/offlinesimulation.h"
#include "simulator/simulatorpanel.h"

#include <QComboBox>
#include <QLabel>
#include <QTest>

using namespace hatpic;
using hatpic::test::EditorRig;
using namespace Qt::StringLiterals;

namespace {

//! The detector's largest finding over `seconds` of the simulator under `hand`.
std::optional<double> worstChatter(const DeviceParams &device, const HostParams &host,
                                   const HandInput &hand, double seconds)
{
    OfflineSimulationConfig config;
    config.device = device;
    config.host = host;
    config.hand = hand;
    config.duration = seconds;
    OfflineSimulation sim(config);
    ChatterDetector detector;
    detector.setParams(device);
    std::optional<double> worst;
    while (!sim.atEnd()) {
        detector.add(sim.next());
        if (const std::optional<double> f = detector.frequency(); f && (!worst || *f > *worst))
            worst = f;
    }
    return worst;
}

Sample at(double t, double theta)
{
    Sample s;
    s.t_s = t;
    s.theta = theta;
    return s;
}

//! The device of the watch's tests: a dead zone of ±0.04 rad whose edge jumps by
//! K_max·Q_dz = 0.06 N·m.
DeviceParams buzzedDevice()
{
    DeviceParams device;
    device.K_max = 1.5;
    device.Q_dz = 0.04;
    return device;
}

//! A knob held at that edge, buzzing across it at 14 Hz, at `t` [s].
double buzzingTheta(double t)
{
    return 0.04 + 0.002 * std::sin(2 * 3.14159265358979 * 14 * t);
}

//! The buzzing knob from `fromMs` to `toMs`, one sample a millisecond.
SampleBatch buzz(int fromMs, int toMs)
{
    SampleBatch out;
    for (int i = fromMs; i <= toMs; ++i)
        out.append(at(i / 1000.0, buzzingTheta(i / 1000.0)));
    return out;
}

} // namespace

class TestChatterDetector : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void oldNotchyChattersUnderTheGentleHand();
    void presetsDoNotChatter_data();
    void presetsDoNotChatter();
    void slowCrossingsAreNotChatter();
    void noDeadZoneNothingToWatch();
    void warningInTheDerivedFigures();
    void watchesTheTunedKnob();
    void aChangeThatMovesNoEdgeKeepsCounting();
};

void TestChatterDetector::oldNotchyChattersUnderTheGentleHand()
{
    Profile notchy = *preset(u"Notchy"_s);
    notchy.device.K_max = 1.5; // the preset before issue 12
    notchy.device.Q_dz = 0.04;
    const std::optional<double> f =
        worstChatter(notchy.device, notchy.host, SimulatorPanel::gentleHand(), 6.0);
    QVERIFY(f.has_value());
    // Seen by hand in the tuner: a steady buzz of about 14 Hz.
    QVERIFY2(*f > 10 && *f < 25, qPrintable(QString::number(*f)));
}

void TestChatterDetector::presetsDoNotChatter_data()
{
    QTest::addColumn<QString>("name");
    for (const QString &name : presetNames())
        QTest::newRow(qPrintable(name)) << name;
}

void TestChatterDetector::presetsDoNotChatter()
{
    QFETCH(QString, name);
    const Profile p = *preset(name);
    const std::optional<double> f =
        worstChatter(p.device, p.host, SimulatorPanel::gentleHand(), 10.0);
    QVERIFY2(!f, qPrintable(QString::number(f.value_or(0))));
}

void TestChatterDetector::slowCrossingsAreNotChatter()
{
    DeviceParams p;
    p.Q_dz = 0.02;
    ChatterDetector d;
    d.setParams(p);
    // A hand wiggling across the edge at 3 Hz for 3 s: deliberate, not a buzz.
    for (int i = 0; i <= 3000; ++i) {
        const double t = i / 1000.0;
        d.add(at(t, 0.02 + 0.01 * std::sin(2 * 3.14159265358979 * 3 * t)));
    }
    QVERIFY(!d.frequency());
    // The same at 14 Hz is chatter, and the frequency is measured.
    for (int i = 3001; i <= 5000; ++i) {
        const double t = i / 1000.0;
        d.add(at(t, 0.02 + 0.001 * std::sin(2 * 3.14159265358979 * 14 * t)));
    }
    QVERIFY(d.frequency());
    QVERIFY2(std::abs(*d.frequency() - 14) < 1, qPrintable(QString::number(*d.frequency())));
    // A new parameter set starts again.
    d.setParams(p);
    QVERIFY(!d.frequency());
}

void TestChatterDetector::noDeadZoneNothingToWatch()
{
    DeviceParams p;
    p.Q_dz = 0;
    ChatterDetector d;
    d.setParams(p);
    for (int i = 0; i <= 2000; ++i)
        d.add(at(i / 1000.0, (i % 2 ? 1e-3 : -1e-3)));
    QVERIFY(!d.frequency());
    d.setParams(std::nullopt);
    for (int i = 0; i <= 2000; ++i)
        d.add(at(i / 1000.0, (i % 2 ? 1e-3 : -1e-3)));
    QVERIFY(!d.frequency());
}

void TestChatterDetector::warningInTheDerivedFigures()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setDeviceTuning({buzzedDevice(), std::nullopt});
    ChatterWatch watch(&editor);
    DerivedFiguresView *figures = editor.derivedFiguresView();
    QVERIFY(!figures->isShowingChatter());
    watch.addSamples(buzz(0, 1500));
    QVERIFY(figures->isShowingChatter());
    const QString text = figures->findChild<QLabel *>(u"warning_chatter"_s)->text();
    QVERIFY2(text.contains(u"K_max·Q_dz = 0.06 N·m"_s), qPrintable(text));
    QVERIFY(figures->warningText().contains(text));

    // The knob at rest: the warning goes once the last second has no chatter.
    SampleBatch rest;
    for (int i = 1501; i <= 3000; ++i)
        rest.append(at(i / 1000.0, 0.0));
    watch.addSamples(rest);
    QVERIFY(!figures->isShowingChatter());
}

void TestChatterDetector::watchesTheTunedKnob()
{
    // A device with two knobs: knob 1 still, knob 2 buzzing at its dead zone's edge.
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setDeviceTuning({buzzedDevice(), std::nullopt});
    editor.setKnobs(2);
    ChatterWatch watch(&editor);
    DerivedFiguresView *figures = editor.derivedFiguresView();
    const auto batch = [](int from, int to) {
        SampleBatch out;
        for (int i = from; i <= to; ++i) {
            const double t = i / 1000.0;
            Sample s = at(t, 0.0);
            auto board = std::make_shared<BoardSample>();
            board->axes = 2;
            board->more[0].theta = buzzingTheta(t);
            s.board = std::move(board);
            out.append(s);
        }
        return out;
    };
    watch.addSamples(batch(0, 1500)); // knob 1 tuned: it is still
    QVERIFY(!figures->isShowingChatter());

    auto *box = editor.findChild<QComboBox *>(u"combo_knob"_s);
    QVERIFY(box);
    box->setCurrentIndex(1);
    Q_EMIT box->activated(1);
    QCOMPARE(editor.knob(), 1);
    watch.addSamples(batch(1501, 3000)); // knob 2 tuned: its θ buzzes
    QVERIFY(figures->isShowingChatter());
}

void TestChatterDetector::aChangeThatMovesNoEdgeKeepsCounting()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    DeviceParams device = buzzedDevice();
    editor.setDeviceTuning({device, std::nullopt});
    ChatterWatch watch(&editor);
    DerivedFiguresView *figures = editor.derivedFiguresView();
    watch.addSamples(buzz(0, 900));
    QVERIFY(figures->isShowingChatter());
    // A push of K_max moves no edge: the buzz goes on being counted (0.1 s more would not be
    // chatter on its own).
    device.K_max = 1.2;
    editor.setDeviceTuning({device, std::nullopt});
    watch.addSamples(buzz(901, 1000));
    QVERIFY(figures->isShowingChatter());
    // A new θ0 moves the edge: counting starts again.
    device.theta0 = 0.5;
    editor.setDeviceTuning({device, std::nullopt});
    watch.addSamples(buzz(1001, 1100));
    QVERIFY(!figures->isShowingChatter());
}

QTEST_MAIN(TestChatterDetector)
#include "tst_chatterdetector.moc"
