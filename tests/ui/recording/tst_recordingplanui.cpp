// The recording options as a person sets them: the dialog's fields make the plan (and only the
// threshold's fields are enabled for a threshold), the plan is saved and read back, and the
// record button arms, shows what it waits for, and calls off an armed recording.
#include "recording/recordingcontrols.h"
#include "recording/recordingplandialog.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;

namespace {

RecordingPlan thetaRising()
{
    RecordingPlan plan;
    plan.start = RecordingPlan::Start::Threshold;
    plan.quantity = RecordingPlan::Quantity::Theta;
    plan.edge = RecordingPlan::Edge::Rising;
    plan.level = 0.2;
    plan.preTrigger_s = 0.5;
    plan.duration_s = 3;
    return plan;
}

} // namespace

class TestRecordingPlanUi : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void dialogMakesThePlan();
    void planIsSavedAndReadBack();
    void armsAndCancels();
    void lengthShownWhileRecording();
};

void TestRecordingPlanUi::dialogMakesThePlan()
{
    RecordingPlanDialog dialog;
    dialog.show();
    auto *start = dialog.findChild<QComboBox *>(QStringLiteral("planStart"));
    auto *quantity = dialog.findChild<QComboBox *>(QStringLiteral("planQuantity"));
    auto *edge = dialog.findChild<QComboBox *>(QStringLiteral("planEdge"));
    auto *level = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("planLevel"));
    auto *pre = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("planPreTrigger"));
    auto *length = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("planDuration"));
    QVERIFY(start && quantity && edge && level && pre && length);
    QCOMPARE(dialog.plan(), RecordingPlan{});
    QVERIFY(!level->isEnabled()); // "Now" has no threshold
    QCOMPARE(length->text(), QStringLiteral("until stopped"));

    start->setCurrentIndex(start->findData(int(RecordingPlan::Start::Threshold)));
    QVERIFY(level->isEnabled());
    quantity->setCurrentIndex(quantity->findData(int(RecordingPlan::Quantity::Tau)));
    QVERIFY(level->suffix().contains(QStringLiteral("N·m")));
    edge->setCurrentIndex(edge->findData(int(RecordingPlan::Edge::Falling)));
    level->setValue(-0.05);
    pre->setValue(99); // beyond what is kept
    length->setValue(2.5);
    const RecordingPlan plan = dialog.plan();
    QCOMPARE(plan.start, RecordingPlan::Start::Threshold);
    QCOMPARE(plan.quantity, RecordingPlan::Quantity::Tau);
    QCOMPARE(plan.edge, RecordingPlan::Edge::Falling);
    QCOMPARE(plan.level, -0.05);
    QCOMPARE(plan.preTrigger_s, RecordingPlan::kMaxPreTrigger_s);
    QCOMPARE(plan.duration_s, 2.5);
    QCOMPARE(RecordingPlanDialog::describeTrigger(plan),
             QStringLiteral("τ falling through -0.05 N·m"));

    dialog.setPlan(thetaRising());
    QCOMPARE(dialog.plan(), thetaRising());
}

void TestRecordingPlanUi::planIsSavedAndReadBack()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    QCOMPARE(RecordingPlanDialog::loadPlan(settings), RecordingPlan{}); // nothing saved yet
    RecordingPlanDialog::savePlan(settings, thetaRising());
    QCOMPARE(RecordingPlanDialog::loadPlan(settings), thetaRising());
    settings.setValue(QStringLiteral("recording/plan/start"), 42); // hand-edited nonsense
    settings.setValue(QStringLiteral("recording/plan/preTrigger"), -3);
    const RecordingPlan read = RecordingPlanDialog::loadPlan(settings);
    QCOMPARE(read.start, RecordingPlan::Start::Now);
    QCOMPARE(read.preTrigger_s, 0.0);
}

void TestRecordingPlanUi::armsAndCancels()
{
    RecordingControls controls;
    controls.show();
    controls.setCanRecord(true);
    controls.setPlanChooser([](const RecordingPlan &) { return std::optional(thetaRising()); });
    controls.planAction()->trigger();
    QCOMPARE(controls.plan(), thetaRising());
    controls.setPlanChooser([](const RecordingPlan &) { return std::nullopt; }); // cancelled
    controls.planAction()->trigger();
    QCOMPARE(controls.plan(), thetaRising());

    controls.setPathChooser([](const QString &) { return QStringLiteral("/data/runs/armed"); });
    QSignalSpy start(&controls, &RecordingControls::startRequested);
    QSignalSpy stop(&controls, &RecordingControls::stopRequested);
    controls.recordAction()->trigger();
    QCOMPARE(start.size(), 1);

    RecordingStatus armed;
    armed.armed = true;
    armed.path = QStringLiteral("/data/runs/armed.csv");
    controls.setStatus(armed);
    QVERIFY(controls.recordAction()->isChecked());
    QVERIFY(!controls.planAction()->isEnabled()); // the plan stays as armed
    QCOMPARE(controls.recordAction()->text(), QStringLiteral("Cancel &recording"));
    QCOMPARE(controls.statusText(),
             QStringLiteral("◌ Armed: waiting for θ rising through 0.2 rad"));
    controls.recordAction()->trigger();
    QCOMPARE(stop.size(), 1);
    QCOMPARE(start.size(), 1);

    controls.setStatus(RecordingStatus{});
    QVERIFY(!controls.recordAction()->isChecked());
    QVERIFY(controls.planAction()->isEnabled());
}

void TestRecordingPlanUi::lengthShownWhileRecording()
{
    RecordingControls controls;
    controls.setPlan(thetaRising());
    RecordingStatus status;
    status.active = true;
    status.seconds = 1.2;
    status.bytes = 3400;
    status.samples = 1200;
    controls.setStatus(status);
    QCOMPARE(controls.statusText(), QStringLiteral("● 00:01 of 00:03 · 3.4 kB · 1200 samples"));
}

QTEST_MAIN(TestRecordingPlanUi)
#include "tst_recordingplanui.moc"
