// The Experiments panel's stability map with real widgets offscreen: it computes off the GUI
// thread (the event loop keeps running, Cancel works), shows the same cells as the core's map
// for the edited tuning, marks the settings in use, says when the tuning changed, and names a
// bad list.
#include "experiments/stabilitymapview.h"
#include "tuning/tuningmodel.h"

#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

using namespace hatpic;

class TestStabilityMapView : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void computesTheEditedTuningsMap();
    void cancels();
    void namesABadList();
};

namespace {

template<typename T> T *child(QWidget &w, const char *name)
{
    return w.findChild<T *>(QLatin1String(name));
}

} // namespace

void TestStabilityMapView::computesTheEditedTuningsMap()
{
    TuningModel tuning;
    StabilityMapView view(tuning);
    view.resize(900, 400);
    view.show();
    child<QLineEdit>(view, "mapDelays")->setText(QStringLiteral("0,0.15"));
    child<QLineEdit>(view, "mapGains")->setText(QStringLiteral("0.02"));
    child<QDoubleSpinBox>(view, "mapDuration")->setValue(10);
    child<QDoubleSpinBox>(view, "mapDelayInUse")->setValue(0.15);
    QSignalSpy finished(&view, &StabilityMapView::finished);
    QTest::mouseClick(child<QPushButton>(view, "computeMap"), Qt::LeftButton);
    // Off the GUI thread: the click returned at once, the buttons say so.
    QVERIFY(view.computing());
    QVERIFY(!child<QPushButton>(view, "computeMap")->isEnabled());
    QVERIFY(child<QPushButton>(view, "cancelMap")->isEnabled());
    QVERIFY(finished.wait(60000));
    QVERIFY(!view.computing());
    // The controller off, then as edited (the defaults: on).
    QCOMPARE(view.cells().size(), std::size_t(4));
    QCOMPARE(view.cells()[1].pc, 0.0);
    QVERIFY(view.cells()[0].result.settled);  // 0 s: settles
    QVERIFY(!view.cells()[1].result.settled); // 150 ms: swings without the controller
    QCOMPARE(view.cells()[3].pc, PassivityParams{}.pc_damping_max);
    QVERIFY(view.cells()[3].result.settled); // and holds the contact with it
    QVERIFY2(view.status().contains(u"3 of 4 cells settle"), qPrintable(view.status()));
    QVERIFY(view.svg().contains("pc_damping_max = 0.7"));
    QVERIFY(view.svg().contains("the settings in use"));
    QVERIFY(view.svg().contains("not settled"));

    // The same cells as the core's map of the same tuning.
    teleop::MapSpec spec = view.spec();
    const auto direct = teleop::runMap(spec);
    QCOMPARE(direct[1].result.p2p, view.cells()[1].result.p2p);
    QCOMPARE(direct[3].result.settleS, view.cells()[3].result.settleS);

    // The controller turned off in the editor: one map, off.
    Tuning edited = tuning.edited();
    edited.passivity = PassivityParams::off();
    tuning.setEdited(edited);
    QCOMPARE(view.spec().cellCount(), 2);

    // A heavier damping edited: the map is stale, and the next one runs it.
    edited.device.M_adm = 0.05;
    tuning.setEdited(edited);
    QVERIFY(view.status().contains(u"compute it again"));
    QCOMPARE(view.spec().base.device.M_adm, 0.05);
}

void TestStabilityMapView::cancels()
{
    TuningModel tuning;
    StabilityMapView view(tuning);
    view.show();
    child<QLineEdit>(view, "mapDelays")->setText(QStringLiteral("0:0.3/20"));
    child<QLineEdit>(view, "mapGains")->setText(QStringLiteral("0.01:0.04/20"));
    QSignalSpy finished(&view, &StabilityMapView::finished);
    QVERIFY(view.compute());
    QTest::mouseClick(child<QPushButton>(view, "cancelMap"), Qt::LeftButton);
    QVERIFY(finished.wait(60000));
    QCOMPARE(view.status(), QStringLiteral("Cancelled."));
    QVERIFY(view.cells().empty());
    QVERIFY(child<QPushButton>(view, "computeMap")->isEnabled());
}

void TestStabilityMapView::namesABadList()
{
    TuningModel tuning;
    StabilityMapView view(tuning);
    child<QLineEdit>(view, "mapDelays")->setText(QStringLiteral("0,soon"));
    QVERIFY(!view.compute());
    QVERIFY2(view.status().contains(u"Delays: needs a number, got 'soon'"),
             qPrintable(view.status()));
    child<QLineEdit>(view, "mapDelays")->setText(QStringLiteral("0,20"));
    QVERIFY(!view.compute());
    QVERIFY2(view.status().contains(u"delay") && view.status().contains(u"20"),
             qPrintable(view.status()));
}

QTEST_MAIN(TestStabilityMapView)
#include "tst_stabilitymapview.moc"
