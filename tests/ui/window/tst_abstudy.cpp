// A/B in the real MainWindow against the in-process simulator ("sim"): both slots' curves in
// the stiffness view, the differences table, push on switch, the blind test driven by keys
// (its trials file, what stays hidden, an abort), and the profile's notes (edit, undo, save,
// open).
#include "blindtest/blinddialog.h"
#include "blindtest/blindrunner.h"
#include "editor/parametereditor.h"
#include "model/stiffness.h"
#include "plots/qcp.h"
#include "profiles/abcomparepanel.h"
#include "profiles/profilecontroller.h"
#include "profiles/profilenotesedit.h"
#include "stiffness/stiffnessview.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>
#include <numbers>

using namespace hatpic;

namespace {

constexpr int kConnectMs = 15000; //!< generous: the machine is shared

template<typename T> T *part(const QObject *window, const char *name)
{
    auto *found = window->findChild<T *>(QString::fromLatin1(name));
    if (!found)
        qFatal("the window has no %s named %s", T::staticMetaObject.className(), name);
    return found;
}

//! The table's row whose parameter starts with `symbol` ("K_max"), as its four texts.
QStringList tableRow(QTableWidget *table, const QString &symbol)
{
    for (int r = 0; r < table->rowCount(); ++r) {
        if (table->item(r, 0)->text().startsWith(symbol + u' ')) {
            QStringList cells;
            for (int c = 0; c < table->columnCount(); ++c)
                cells << table->item(r, c)->text();
            return cells;
        }
    }
    return {};
}

} // namespace

class TestAbStudy : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();

    void overlayShowsBothSlots();
    void differencesTableInDisplayUnits();
    void pushOnSwitchPushesTheSlot();
    void blindRunByKeysWritesTheTrials();
    void blindAbortKeepsAnsweredTrialsAndResumes();
    void existingTrialsFileIsNotReplacedWithoutAsking();
    void notesEditUndoSaveOpen();

private:
    template<typename T> T *find(const char *name) const { return part<T>(m_window.get(), name); }
    ProfileController *profiles() const { return find<ProfileController>("profileController"); }
    ParameterEditor *editor() const { return find<ParameterEditor>("parameterEditor"); }
    DeviceClient *client() const { return find<DeviceClient>("deviceClient"); }
    //! The device's parameters as read (DeviceParams{} until the device has told them).
    DeviceParams deviceParams() const
    {
        return client()->deviceTuning().params.value_or(DeviceParams{});
    }
    void connectSim();
    //! Starts slot B as a copy of A with K_max = `kMax` and θ0 = `theta0`; A stays active.
    void makeB(double kMax, double theta0 = 0.0);
    //! The blind dialog, opened from the A/B panel's button, with `trials` and `seed`.
    BlindDialog *openBlind(int trials, int seed, const QString &file);

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestAbStudy::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("hatpic-test"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_abstudy"));
    QVERIFY(m_dir.isValid());
}

void TestAbStudy::init()
{
    QSettings().clear();
    m_window = std::make_unique<MainWindow>();
    m_window->resize(1400, 900);
    profiles()->setQuestion([](const QString &) { return QMessageBox::Discard; });
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestAbStudy::cleanup()
{
    m_window.reset();
}

void TestAbStudy::connectSim()
{
    ConnectOptions options;
    options.port = QStringLiteral("sim");
    options.protocol = ProtocolChoice::V2;
    m_window->connectTo(options);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
    QTRY_VERIFY_WITH_TIMEOUT(client()->deviceTuning().params.has_value(), kConnectMs);
}

void TestAbStudy::makeB(double kMax, double theta0)
{
    QCOMPARE(profiles()->activeSlot(), 0);
    profiles()->abToggleAction()->trigger();
    DeviceParams b = editor()->params();
    b.K_max = kMax;
    b.theta0 = theta0;
    editor()->setParams(b, editor()->hostParams(), QStringLiteral("B"));
    profiles()->abToggleAction()->trigger();
    QCOMPARE(profiles()->activeSlot(), 0);
}

BlindDialog *TestAbStudy::openBlind(int trials, int seed, const QString &file)
{
    find<QPushButton>("ab_blind_test")->click();
    auto *dialog = find<BlindDialog>("blindDialog");
    if (!dialog->isVisible())
        return nullptr;
    part<QSpinBox>(dialog, "blind_trials")->setValue(trials);
    part<QSpinBox>(dialog, "blind_seed")->setValue(seed);
    part<QLineEdit>(dialog, "blind_file")->setText(file);
    return dialog;
}

void TestAbStudy::overlayShowsBothSlots()
{
    auto *view = find<StiffnessView>("stiffnessView");
    QCOMPARE(view->slotTorqueGraph(0), nullptr); // one slot: nothing to compare
    const DeviceParams a = editor()->params();
    makeB(a.K_max * 1.5);
    DeviceParams b = a;
    b.K_max = a.K_max * 1.5;

    for (int active : {0, 1}) {
        if (profiles()->activeSlot() != active)
            profiles()->abToggleAction()->trigger();
        for (int slot : {0, 1}) {
            QCPGraph *torque = view->slotTorqueGraph(slot);
            QCPGraph *stiffness = view->slotStiffnessGraph(slot);
            QVERIFY(torque && stiffness);
            QVERIFY(torque->visible());
            const QString name = slot == 0 ? QStringLiteral("A") : QStringLiteral("B");
            QCOMPARE(torque->name(), slot == active ? name + QStringLiteral(" (edited)") : name);
            // Each curve is its own slot's τ_rec(θ), K_rec(θ): checked in the notch band.
            const DeviceParams &p = slot == 0 ? a : b;
            const double theta = p.theta0 + 0.5 * (p.Q_dz + p.N);
            for (QCPGraph *g : {torque, stiffness}) {
                const auto it = g->data()->findBegin(theta, false);
                QVERIFY(it != g->data()->constEnd());
                const double expected =
                    g == torque ? recenteringTorque(p, it->key) : recenteringStiffness(p, it->key);
                QCOMPARE(it->value, expected);
            }
        }
        QVERIFY(view->slotTorqueGraph(0)->pen().color() != view->slotTorqueGraph(1)->pen().color());
    }
}

void TestAbStudy::differencesTableInDisplayUnits()
{
    auto *table = find<QTableWidget>("ab_differences");
    QCOMPARE(table->rowCount(), 0); // only A
    const DeviceParams a = editor()->params();
    makeB(a.K_max + 0.2, 0.1);
    QStringList row = tableRow(table, QStringLiteral("K_max"));
    QCOMPARE(row,
             (QStringList{QStringLiteral("K_max [N·m/rad]"), QString::number(a.K_max, 'g', 6),
                          QString::number(a.K_max + 0.2, 'g', 6),
                          QStringLiteral("+") + QString::number(a.K_max + 0.2 - a.K_max, 'g', 6)}));
    QCOMPARE(table->rowCount(), 2); // only what differs: K_max and θ0
    QVERIFY(table->item(0, 0)->font().bold());
    QCOMPARE(tableRow(table, QStringLiteral("K_min")), QStringList());
    find<QCheckBox>("ab_all_parameters")->setChecked(true); // every parameter
    QCOMPARE(table->rowCount(), 20); // 7 device, 7 effect, 2 passivity and 4 host fields
    QCOMPARE(tableRow(table, QStringLiteral("K_min"))[3], QString()); // equal: no Δ
    QVERIFY(!table->item(2, 0)->font().bold());
    QCOMPARE(tableRow(table, QStringLiteral("θ0")),
             (QStringList{QStringLiteral("θ0 [rad]"), QStringLiteral("0"), QStringLiteral("0.1"),
                          QStringLiteral("+0.1")}));

    // Angles follow View → Angles in degrees; an edit of the active slot shows at once.
    find<QAction>("degreesAction")->setChecked(true);
    QCOMPARE(
        tableRow(table, QStringLiteral("θ0")),
        (QStringList{QStringLiteral("θ0 [°]"), QStringLiteral("0"),
                     QString::number(0.1 * 180 / std::numbers::pi, 'g', 6),
                     QStringLiteral("+") + QString::number(0.1 * 180 / std::numbers::pi, 'g', 6)}));
    DeviceParams edited = editor()->params();
    edited.K_max = a.K_max + 0.3;
    editor()->setParams(edited, editor()->hostParams(), QStringLiteral("A"));
    QCOMPARE(tableRow(table, QStringLiteral("K_max"))[3],
             QString::number((a.K_max + 0.2) - (a.K_max + 0.3), 'g', 6));
    // The effects are compared too.
    Tuning t = editor()->tuning();
    t.effects.detent_strength = 0.05;
    editor()->setTuning(t, QStringLiteral("A detents"));
    QCOMPARE(tableRow(table, QStringLiteral("A_det")),
             (QStringList{QStringLiteral("A_det [N·m]"), QStringLiteral("0.05"),
                          QStringLiteral("0"), QStringLiteral("-0.05")}));
}

void TestAbStudy::pushOnSwitchPushesTheSlot()
{
    connectSim();
    const DeviceParams a = editor()->params();
    makeB(a.K_max + 0.2);
    // Off (the default): switching only loads the other slot into the editor.
    auto *option = find<QCheckBox>("ab_push_on_switch");
    QVERIFY(!option->isChecked());
    profiles()->abToggleAction()->trigger();
    QCOMPARE(editor()->syncState(), SyncState::Edited);
    profiles()->abToggleAction()->trigger();

    option->setChecked(true);
    QVERIFY(QSettings().value(QStringLiteral("profiles/pushOnSwitch")).toBool());
    QVERIFY(profiles()->pushOnSwitchAction()->isChecked());
    profiles()->abToggleAction()->trigger(); // to B: pushed
    QCOMPARE(profiles()->activeSlot(), 1);
    QTRY_COMPARE_WITH_TIMEOUT(editor()->syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(sameOnWire(deviceParams(), profiles()->slotProfile(1).device));
    profiles()->abToggleAction()->trigger(); // back to A: pushed
    QTRY_COMPARE_WITH_TIMEOUT(editor()->syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(sameOnWire(deviceParams(), a));
    // Undo past a switch is a switch too.
    editor()->undoStack()->undo();
    QCOMPARE(profiles()->activeSlot(), 1);
    QTRY_COMPARE_WITH_TIMEOUT(editor()->syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(sameOnWire(deviceParams(), profiles()->slotProfile(1).device));
}

void TestAbStudy::blindRunByKeysWritesTheTrials()
{
    connectSim();
    const DeviceParams a = editor()->params();
    makeB(a.K_max + 0.2);
    const DeviceParams b = profiles()->slotProfile(1).device;
    const QString path = m_dir.filePath(QStringLiteral("blind-run.csv"));
    constexpr int kTrials = 4;
    constexpr int kSeed = 1234;
    BlindDialog *dialog = openBlind(kTrials, kSeed, path);
    QVERIFY(dialog);
    part<QComboBox>(dialog, "blind_question")
        ->setCurrentText(QStringLiteral("Which felt stiffer?"));
    auto *runner = find<BlindRunner>("blindRunner");
    QVERIFY(dialog->startStudy());
    QVERIFY(!m_window->isVisible()); // no title, editor, table or curves in sight
    QVERIFY(dialog->isVisible());

    const auto orders = BlindStudy::sequence(kTrials, kSeed);
    const int answers[kTrials] = {1, 2, 2, 1};
    for (int i = 0; i < kTrials; ++i) {
        QTRY_COMPARE_WITH_TIMEOUT(runner->phase(), BlindRunner::Phase::Feeling, kConnectMs);
        // Interval 1 is on the device before the trial starts.
        QVERIFY(sameOnWire(deviceParams(), orders[i][0] == 0 ? a : b));
        for (const char *name : {"blind_trial", "blind_interval", "blind_prompt"}) {
            const QString text = part<QLabel>(dialog, name)->text();
            QVERIFY2(!text.contains(u'A') && !text.contains(u'B') && !text.contains(u'K'),
                     qPrintable(text)); // no slot, no profile, no parameter
        }
        QCOMPARE(part<QLabel>(dialog, "blind_trial")->text(),
                 QStringLiteral("Trial %1 of %2").arg(i + 1).arg(kTrials));
        QTest::keyClick(dialog, Qt::Key_1); // not yet: interval 2 has not been felt
        QCOMPARE(runner->study()->answeredCount(), i);
        QTest::keyClick(dialog, Qt::Key_Space);
        QTRY_COMPARE_WITH_TIMEOUT(runner->phase(), BlindRunner::Phase::Answering, kConnectMs);
        QCOMPARE(part<QLabel>(dialog, "blind_interval")->text(), QStringLiteral("Interval 2"));
        QVERIFY(sameOnWire(deviceParams(), orders[i][1] == 0 ? a : b));
        QTest::keyClick(dialog, answers[i] == 1 ? Qt::Key_1 : Qt::Key_2);
        QCOMPARE(runner->study()->answeredCount(), i + 1);
        // Each answer is in the file at once.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll().count('\n'), 7 + i + 1);
    }
    QCOMPARE(runner->phase(), BlindRunner::Phase::Finished);
    QVERIFY(m_window->isVisible());
    QCOMPARE(profiles()->activeSlot(), 0); // the editor shows the slot it showed before

    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).split(u'\n');
    QCOMPARE(lines[1], QStringLiteral("# profile A: Untitled"));
    QCOMPARE(lines[2], QStringLiteral("# profile B: Untitled (copy)"));
    QCOMPARE(lines[3], QStringLiteral("# seed: 1234"));
    QCOMPARE(lines[5], QStringLiteral("# question: Which felt stiffer?"));
    QCOMPARE(lines[6], QLatin1StringView(BlindStudy::kColumns));
    for (int i = 0; i < kTrials; ++i) {
        const QStringList cells = lines[7 + i].split(u',');
        QCOMPARE(cells.size(), 7);
        QCOMPARE(cells[0], QString::number(i + 1));
        QCOMPARE(cells[1], BlindStudy::orderText(orders[i]));
        QCOMPARE(cells[2], QString::number(answers[i]));
        QCOMPARE(cells[3], BlindStudy::slotName(orders[i][std::size_t(answers[i] - 1)]));
        bool ok = false;
        QVERIFY(cells[4].toDouble(&ok) >= 0 && ok);
        QVERIFY(QDateTime::fromString(cells[5], Qt::ISODateWithMs).isValid());
        QVERIFY(QDateTime::fromString(cells[6], Qt::ISODateWithMs) >=
                QDateTime::fromString(cells[5], Qt::ISODateWithMs));
    }
    QCOMPARE(lines[7 + kTrials], QString());
    QVERIFY(part<QLabel>(dialog, "blind_result")->text().contains(QStringLiteral("of 4 trials")));
}

void TestAbStudy::blindAbortKeepsAnsweredTrialsAndResumes()
{
    connectSim();
    makeB(editor()->params().K_max + 0.1);
    const QString path = m_dir.filePath(QStringLiteral("blind-abort.csv"));
    BlindDialog *dialog = openBlind(3, 5, path);
    QVERIFY(dialog);
    auto *runner = find<BlindRunner>("blindRunner");
    QVERIFY(dialog->startStudy());
    QTRY_COMPARE_WITH_TIMEOUT(runner->phase(), BlindRunner::Phase::Feeling, kConnectMs);
    QTest::keyClick(dialog, Qt::Key_Space);
    QTRY_COMPARE_WITH_TIMEOUT(runner->phase(), BlindRunner::Phase::Answering, kConnectMs);
    QTest::keyClick(dialog, Qt::Key_2);
    QTRY_COMPARE_WITH_TIMEOUT(runner->phase(), BlindRunner::Phase::Feeling, kConnectMs);
    QTest::keyClick(dialog, Qt::Key_Escape);
    QCOMPARE(runner->phase(), BlindRunner::Phase::Stopped);
    QVERIFY(m_window->isVisible());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).split(u'\n');
    QCOMPARE(lines.size(), 7 + 1 + 1); // header, one trial, the last line's end
    QVERIFY(lines[7].startsWith(QStringLiteral("1,")));
    QVERIFY(part<QLabel>(dialog, "blind_result")->text().contains(QStringLiteral("Stopped")));

    // Resume goes on from trial 2, in the same file, and hides the window again.
    auto *resume = part<QPushButton>(dialog, "blind_resume");
    QVERIFY(resume->isVisible());
    resume->click();
    QVERIFY(!m_window->isVisible());
    for (int trial = 2; trial <= 3; ++trial) {
        QTRY_COMPARE_WITH_TIMEOUT(runner->phase(), BlindRunner::Phase::Feeling, kConnectMs);
        QCOMPARE(part<QLabel>(dialog, "blind_trial")->text(),
                 QStringLiteral("Trial %1 of 3").arg(trial));
        QTest::keyClick(dialog, Qt::Key_Space);
        QTRY_COMPARE_WITH_TIMEOUT(runner->phase(), BlindRunner::Phase::Answering, kConnectMs);
        QTest::keyClick(dialog, Qt::Key_1);
    }
    QCOMPARE(runner->phase(), BlindRunner::Phase::Finished);
    QVERIFY(m_window->isVisible());
    QVERIFY(!resume->isVisible()); // nothing left to resume
    QFile whole(path);
    QVERIFY(whole.open(QIODevice::ReadOnly));
    const QStringList all = QString::fromUtf8(whole.readAll()).split(u'\n');
    QCOMPARE(all.size(), 7 + 3 + 1);
    QCOMPARE(all[7], lines[7]); // the first answer is kept as it was
    QVERIFY(all[9].startsWith(QStringLiteral("3,")));
}

void TestAbStudy::existingTrialsFileIsNotReplacedWithoutAsking()
{
    connectSim();
    makeB(editor()->params().K_max + 0.1);
    const QString path = m_dir.filePath(QStringLiteral("someone-elses.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("precious\n");
    file.close();
    BlindDialog *dialog = openBlind(2, 1, path);
    QVERIFY(dialog);
    QString asked;
    dialog->setQuestion([&asked](const QString &text) {
        asked = text;
        return QMessageBox::No;
    });
    QVERIFY(!dialog->startStudy());
    QVERIFY(asked.contains(QStringLiteral("someone-elses.csv")));
    QCOMPARE(find<BlindRunner>("blindRunner")->phase(), BlindRunner::Phase::Idle);
    QVERIFY(m_window->isVisible());
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious\n"));
}

void TestAbStudy::notesEditUndoSaveOpen()
{
    auto *notes = find<ProfileNotesEdit>("profileNotes");
    find<QDockWidget>("notesDock")->show();
    QVERIFY(!profiles()->isModified());
    notes->setFocus();
    QTest::keyClicks(notes, QStringLiteral("soft centre"));
    QCOMPARE(profiles()->notes(), QStringLiteral("soft centre"));
    QVERIFY(profiles()->isModified());
    QVERIFY(m_window->windowTitle().contains(u'*'));
    // Typing in a row is one undo step; Ctrl+Z in the notes takes it back.
    QTest::keyClick(notes, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(notes->toPlainText(), QString());
    QVERIFY(!profiles()->isModified());
    editor()->undoStack()->redo();
    QCOMPARE(notes->toPlainText(), QStringLiteral("soft centre"));

    const QString path = m_dir.filePath(QStringLiteral("noted.json"));
    QString error;
    QVERIFY2(profiles()->saveTo(path, &error), qPrintable(error));
    QVERIFY(!profiles()->isModified());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().contains("\"notes\": \"soft centre\""));

    notes->setPlainText(QStringLiteral("changed"));
    QCOMPARE(profiles()->notes(), QStringLiteral("changed"));
    QVERIFY2(profiles()->openFile(path, &error), qPrintable(error));
    QCOMPARE(notes->toPlainText(), QStringLiteral("soft centre"));
    QVERIFY(!profiles()->isModified());

    // Each slot has its own notes.
    profiles()->abToggleAction()->trigger();
    notes->setPlainText(QStringLiteral("B: stiffer"));
    profiles()->abToggleAction()->trigger();
    QCOMPARE(notes->toPlainText(), QStringLiteral("soft centre"));
    QCOMPARE(profiles()->slotProfile(1).notes, QStringLiteral("B: stiffer"));
}

QTEST_MAIN(TestAbStudy)
#include "tst_abstudy.moc"
