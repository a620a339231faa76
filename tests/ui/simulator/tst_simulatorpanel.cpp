// SimulatorPanel: each hand kind, set through the real widgets, emits the matching HandInput.
#include "simulator/simulatorpanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

using Kind = HandInput::Kind;

namespace {

HandInput make(Kind kind, double amplitude = 0, double offset = 0, double frequency = 0,
               double frequency1 = 0, double angle = 0)
{
    HandInput h;
    h.kind = kind;
    h.amplitude = amplitude;
    h.offset = offset;
    h.frequency = frequency;
    h.frequency1 = frequency1;
    h.angle = angle;
    return h;
}

} // namespace

class TestSimulatorPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void eachKindEmits_data();
    void eachKindEmits();
    void onlyUsedFieldsShown_data();
    void onlyUsedFieldsShown();
    void dragTargetAngle();
    void setHandDoesNotEmit();
    void letGoIsIdle();

private:
    template<typename T> static T *child(const SimulatorPanel &panel, const QString &name)
    {
        return panel.findChild<T *>(name);
    }
};

void TestSimulatorPanel::eachKindEmits_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("amplitude");
    QTest::addColumn<double>("offset");
    QTest::addColumn<double>("frequency");
    QTest::addColumn<double>("frequency1");
    QTest::addColumn<double>("angle");
    QTest::addColumn<HandInput>("expected");

    QTest::newRow("idle") << int(Kind::Idle) << 0.2 << 0.1 << 3.0 << 7.0 << 0.3 << make(Kind::Idle);
    QTest::newRow("constant torque")
        << int(Kind::Constant) << 0.12 << 0.1 << 3.0 << 7.0 << 0.3 << make(Kind::Constant, 0.12);
    QTest::newRow("negative constant torque")
        << int(Kind::Constant) << -0.3 << 0.0 << 1.0 << 10.0 << 0.0 << make(Kind::Constant, -0.3);
    QTest::newRow("step") << int(Kind::Step) << 0.2 << -0.05 << 3.0 << 7.0 << 0.3
                          << make(Kind::Step, 0.2, -0.05);
    QTest::newRow("sine") << int(Kind::Sine) << 0.08 << 0.1 << 2.5 << 7.0 << 0.3
                          << make(Kind::Sine, 0.08, 0, 2.5);
    QTest::newRow("chirp") << int(Kind::Chirp) << 0.05 << 0.1 << 0.5 << 20.0 << 0.3
                           << make(Kind::Chirp, 0.05, 0, 0.5, 20.0);
    QTest::newRow("virtual hand") << int(Kind::VirtualHand) << 0.2 << 0.1 << 3.0 << 7.0 << -0.4
                                  << make(Kind::VirtualHand, 0, 0, 0, 0, -0.4);
}

void TestSimulatorPanel::eachKindEmits()
{
    QFETCH(int, kind);
    QFETCH(double, amplitude);
    QFETCH(double, offset);
    QFETCH(double, frequency);
    QFETCH(double, frequency1);
    QFETCH(double, angle);
    QFETCH(HandInput, expected);

    SimulatorPanel panel;
    QCOMPARE(panel.hand(), HandInput{}); // starts idle
    QSignalSpy spy(&panel, &SimulatorPanel::handChanged);

    // Pick the kind first, as a user would, then fill in its fields.
    auto *combo = child<QComboBox>(panel, u"combo_hand_kind"_s);
    combo->setCurrentIndex(combo->findData(kind));
    child<QDoubleSpinBox>(panel, u"spin_hand_amplitude"_s)->setValue(amplitude);
    child<QDoubleSpinBox>(panel, u"spin_hand_offset"_s)->setValue(offset);
    child<QDoubleSpinBox>(panel, u"spin_hand_frequency"_s)->setValue(frequency);
    child<QDoubleSpinBox>(panel, u"spin_hand_frequency1"_s)->setValue(frequency1);
    child<QDoubleSpinBox>(panel, u"spin_hand_angle"_s)->setValue(angle);

    QCOMPARE(panel.hand(), expected);
    if (expected == HandInput{}) {
        QCOMPARE(spy.count(), 0); // nothing changed for an idle hand
    } else {
        QVERIFY(!spy.isEmpty());
        QCOMPARE(spy.last().at(0).value<HandInput>(), expected);
    }
    // No duplicate emissions: each emitted input differs from the one before.
    for (int i = 1; i < spy.count(); ++i)
        QVERIFY(!(spy.at(i).at(0).value<HandInput>() == spy.at(i - 1).at(0).value<HandInput>()));
}

void TestSimulatorPanel::onlyUsedFieldsShown_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QStringList>("shown");
    QTest::newRow("idle") << int(Kind::Idle) << QStringList{};
    QTest::newRow("constant") << int(Kind::Constant) << QStringList{u"spin_hand_amplitude"_s};
    QTest::newRow("step") << int(Kind::Step)
                          << QStringList{u"spin_hand_amplitude"_s, u"spin_hand_offset"_s};
    QTest::newRow("sine") << int(Kind::Sine)
                          << QStringList{u"spin_hand_amplitude"_s, u"spin_hand_frequency"_s};
    QTest::newRow("chirp") << int(Kind::Chirp)
                           << QStringList{u"spin_hand_amplitude"_s, u"spin_hand_frequency"_s,
                                          u"spin_hand_frequency1"_s};
    QTest::newRow("virtual hand") << int(Kind::VirtualHand)
                                  << QStringList{u"spin_hand_angle"_s, u"slider_hand_angle"_s};
}

void TestSimulatorPanel::onlyUsedFieldsShown()
{
    QFETCH(int, kind);
    QFETCH(QStringList, shown);
    SimulatorPanel panel;
    auto *combo = child<QComboBox>(panel, u"combo_hand_kind"_s);
    combo->setCurrentIndex(combo->findData(kind));
    const QStringList all = {u"spin_hand_amplitude"_s, u"spin_hand_offset"_s,
                             u"spin_hand_frequency"_s, u"spin_hand_frequency1"_s,
                             u"spin_hand_angle"_s,     u"slider_hand_angle"_s};
    for (const QString &name : all) {
        QWidget *w = child<QWidget>(panel, name);
        QVERIFY(w);
        QCOMPARE(!w->isHidden(), shown.contains(name));
    }
}

void TestSimulatorPanel::dragTargetAngle()
{
    SimulatorPanel panel;
    auto *combo = child<QComboBox>(panel, u"combo_hand_kind"_s);
    combo->setCurrentIndex(combo->findData(int(Kind::VirtualHand)));
    QSignalSpy spy(&panel, &SimulatorPanel::handChanged);
    auto *slider = child<QSlider>(panel, u"slider_hand_angle"_s);
    slider->setSliderDown(true);
    for (int tick : {100, 250, 400, 523})
        slider->setValue(tick);
    slider->setSliderDown(false);
    QCOMPARE(spy.count(), 4); // every step of the drag reaches the simulator
    QCOMPARE(spy.last().at(0).value<HandInput>(),
             make(Kind::VirtualHand, 0, 0, 0, 0, 523.0 / SimulatorPanel::kAngleTicksPerRad));
    QCOMPARE(child<QDoubleSpinBox>(panel, u"spin_hand_angle"_s)->value(), 0.523);
    QCOMPARE(slider->maximum(),
             int(std::lround(std::numbers::pi / 2 * SimulatorPanel::kAngleTicksPerRad)));
}

void TestSimulatorPanel::setHandDoesNotEmit()
{
    SimulatorPanel panel;
    QSignalSpy spy(&panel, &SimulatorPanel::handChanged);
    const HandInput chirp = make(Kind::Chirp, 0.07, 0, 1.5, 12.0);
    panel.setHand(chirp);
    QCOMPARE(spy.count(), 0);
    QCOMPARE(panel.hand(), chirp);
    const HandInput hand = make(Kind::VirtualHand, 0, 0, 0, 0, 0.25);
    panel.setHand(hand);
    QCOMPARE(panel.hand(), hand);
    QCOMPARE(child<QSlider>(panel, u"slider_hand_angle"_s)->value(), 250);
    QCOMPARE(spy.count(), 0);
    // The next user change emits relative to what was set.
    child<QDoubleSpinBox>(panel, u"spin_hand_angle"_s)->setValue(0.3);
    QCOMPARE(spy.count(), 1);
}

void TestSimulatorPanel::letGoIsIdle()
{
    SimulatorPanel panel;
    panel.setHand(make(Kind::Constant, 0.1));
    QSignalSpy spy(&panel, &SimulatorPanel::handChanged);
    QTest::mouseClick(child<QPushButton>(panel, u"button_hand_release"_s), Qt::LeftButton);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.last().at(0).value<HandInput>(), HandInput{});
}

QTEST_MAIN(TestSimulatorPanel)
#include "tst_simulatorpanel.moc"
