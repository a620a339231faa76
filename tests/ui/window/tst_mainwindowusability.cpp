// The real MainWindow as a user handles it, on the in-process simulator ("sim"): the keys (the
// shortcuts and F1's list, Alt+N to the fields and into view, Tab order, panel keys, no Tab
// stops in the toolbars), the wheel editing only a chosen field, the window at a laptop's size
// and at every size (the state tag, the hand beside the stiffness view, the derived figures in
// sight), settings across launches (fitted to the screen) and View → Reset layout.
#include "connection/connectionbar.h"
#include "connection/linkbanner.h"
#include "connection/linkstatuswidget.h"
#include "editor/deviceparameterlink.h"
#include "editor/parametereditor.h"
#include "mainwindowtest.h"
#include "plots/plotpanel.h"
#include "profiles/profilecontroller.h"
#include "simulator/simulatorpanel.h"
#include "wheelevent.h"
#include "window/mainwindow.h"
#include "window/shortcutsdialog.h"
#include "window/wheelguard.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>
#include <QToolBar>
#include <QUndoStack>

#include <algorithm>
#include <memory>

using namespace hatpic;
using namespace Qt::StringLiterals;

class TestMainWindowUsability : public test::MainWindowTest
{
    Q_OBJECT
public:
    TestMainWindowUsability() : MainWindowTest(QStringLiteral("tst_mainwindowusability")) {}

private Q_SLOTS:
    void wheelScrollsParametersAndEditsNothing();
    void settingsPersist();
    void keyboardShortcuts();
    void narrowWindowKeepsStateTagVisible();
    void oversizedSettingsAreFitted_data();
    void oversizedSettingsAreFitted();
    void handAndStiffnessInSightTogether();
    void keyboardReachesFieldsAndActions();
    void goToScrollsTheFieldIntoView();
    void keyboardFocusAndPanelKeys();
    void resetLayoutRestoresTheDocks();
    void derivedFiguresInSightAtEverySize_data();
    void derivedFiguresInSightAtEverySize();
};

void TestMainWindowUsability::wheelScrollsParametersAndEditsNothing()
{
    // Issue 21, item 15: at 1280×720, with live push on, the pointer resting on K_min and the
    // Parameters panel scrolled past its fields: nothing is edited, nothing reaches the device.
    m_window->resize(1280, 720);
    connectSim();
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    editor->setLivePush(true);
    QSignalSpy pushes(editor->model(), &TuningModel::pushRequested);
    const Tuning before = editor->tuning();
    const int undoSteps = editor->undoStack()->count();

    QAbstractSpinBox *kMin = editor->findChild<QAbstractSpinBox *>(QStringLiteral("spin_K_min"));
    QVERIFY(kMin && kMin->isVisible());
    for (int i = 0; i < 3; ++i)
        test::turnWheel(kMin, kMin->rect().center(), -120);
    QCOMPARE(editor->params().K_min, before.device.K_min);
    QVERIFY(!kMin->hasFocus());

    auto *scroll = editor->findChild<QScrollArea *>();
    QVERIFY(scroll);
    QScrollBar *bar = scroll->verticalScrollBar();
    QVERIFY2(bar->maximum() > 0, "the panel does not scroll at 1280×720");
    const QPoint pointer(scroll->viewport()->width() / 2, scroll->viewport()->height() / 2);
    int fieldsPassed = 0;
    for (int i = 0; i < 40 && bar->value() < bar->maximum(); ++i) {
        QWidget *under = scroll->viewport()->childAt(pointer);
        fieldsPassed += WheelGuard::isValueField(under) ||
                        (under && WheelGuard::isValueField(under->parentWidget()));
        test::turnWheel(scroll->viewport(), pointer, -120);
    }
    QCOMPARE(bar->value(), bar->maximum());
    QVERIFY2(fieldsPassed > 3, qPrintable(QString::number(fieldsPassed)));
    QTest::qWait(2 * ParameterEditor::kDefaultLivePushIntervalMs); // a live push would be out
    QVERIFY(editor->tuning() == before);
    QCOMPARE(editor->undoStack()->count(), undoSteps);
    QCOMPARE(pushes.size(), 0);
    QCOMPARE(editor->syncState(), SyncState::InSync);

    // A field the user chose (clicked into) takes the wheel, and live push sends it.
    scroll->ensureWidgetVisible(kMin);
    QTest::mouseClick(kMin->findChild<QLineEdit *>(), Qt::LeftButton);
    QTRY_VERIFY(kMin->hasFocus());
    test::turnWheel(kMin, kMin->rect().center(), 120);
    QVERIFY(editor->params().K_min > before.device.K_min);
    QTRY_COMPARE_WITH_TIMEOUT(pushes.size(), 1, kConnectMs);
}

void TestMainWindowUsability::settingsPersist()
{
    find<ConnectionBar>("connectionBar")
        ->setOptions(QStringLiteral("/dev/ttyTEST0"), 115200, ProtocolChoice::Legacy);
    find<QAction>("degreesAction")->setChecked(true);
    find<PlotPanel>("plotPanel")->setWindowLength(30);
    const QString profile = m_dir.filePath(QStringLiteral("Persisted.json"));
    QVERIFY(find<ProfileController>("profileController")->saveTo(profile));
    QVERIFY(m_window->close());

    m_window = std::make_unique<MainWindow>();
    ConnectionBar *bar = find<ConnectionBar>("connectionBar");
    QCOMPARE(bar->port(), QStringLiteral("/dev/ttyTEST0"));
    QCOMPARE(bar->baud(), 115200);
    QCOMPARE(bar->protocol(), ProtocolChoice::Legacy);
    QVERIFY(find<PlotPanel>("plotPanel")->angleInDegrees());
    QCOMPARE(find<PlotPanel>("plotPanel")->windowLength(), 30.0);
    QCOMPARE(find<ProfileController>("profileController")->filePath(), profile);
}

void TestMainWindowUsability::keyboardShortcuts()
{
    {
        // Every shortcut is in view at once: the table needs no scrolling.
        ShortcutsDialog dialog(m_window->shortcutActions(), m_window.get());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto *table = dialog.findChild<QTableWidget *>();
        QVERIFY(table);
        QVERIFY(table->rowCount() >= 15);
        QVERIFY2(!table->verticalScrollBar()->isVisible(),
                 qPrintable(QStringLiteral("%1 rows in %2 px")
                                .arg(table->rowCount())
                                .arg(table->viewport()->height())));
    }
    const QStringList lines = ShortcutsDialog::describe(m_window->shortcutActions());
    auto has = [&](const QKeySequence &key) {
        const QString text = key.toString(QKeySequence::NativeText);
        return std::any_of(lines.cbegin(), lines.cend(),
                           [&](const QString &l) { return l.contains(text); });
    };
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_K)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_Return)));
    QVERIFY(has(QKeySequence(Qt::Key_Space)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_R)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_Z)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
    QVERIFY(has(find<ProfileController>("profileController")->abToggleAction()->shortcut()));

    // Ctrl+K connects through the real shortcut machinery.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    find<PlotPanel>("plotPanel")->customPlot()->setFocus();
    QTest::keyClick(m_window.get(), Qt::Key_K, Qt::ControlModifier);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
    QTest::keyClick(find<PlotPanel>("plotPanel")->customPlot(), Qt::Key_Space);
    QVERIFY(find<PlotPanel>("plotPanel")->isPaused());
    QTest::keyClick(m_window.get(), Qt::Key_P, Qt::ControlModifier);
    QVERIFY(!find<PlotPanel>("plotPanel")->isPaused());
    QTest::keyClick(m_window.get(), Qt::Key_K, Qt::ControlModifier);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Disconnected, kConnectMs);
}

void TestMainWindowUsability::narrowWindowKeepsStateTagVisible()
{
    // On a laptop-sized window the long device identity must give way (elided), not push the
    // state tag — the one place LINK LOST shows — into the toolbar's overflow menu.
    m_window->resize(1000, 700);
    connectSim();
    auto *tag = m_window->findChild<QLabel *>(QStringLiteral("linkState"));
    QVERIFY(tag);
    QCOMPARE(tag->text(), QStringLiteral("connected"));
    QTRY_VERIFY(linkStatus()->identityText().contains(QStringLiteral("τ limit")));
    // Let the toolbars lay out the new identity (nested layouts: a few rounds).
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QVERIFY(tag->isVisible());
    const QRect inWindow(tag->mapTo(m_window.get(), QPoint(0, 0)), tag->size());
    QVERIFY2(m_window->rect().contains(inWindow),
             qPrintable(QStringLiteral("tag at x %1..%2, window %3 wide")
                            .arg(inWindow.left())
                            .arg(inWindow.right())
                            .arg(m_window->width())));
    auto *identity = m_window->findChild<QLabel *>(QStringLiteral("deviceIdentity"));
    QVERIFY(identity);
    QTRY_VERIFY(identity->isVisible());
    // The full identity stays available (tooltip, identityText()).
    QVERIFY(linkStatus()->identityText().contains(QStringLiteral("τ limit")));
    QCOMPARE(identity->toolTip(), linkStatus()->identityText());
}

void TestMainWindowUsability::oversizedSettingsAreFitted_data()
{
    QTest::addColumn<bool>("legacyKey"); // window/geometry as saved by earlier versions
    QTest::newRow("window/rect") << false;
    QTest::newRow("window/geometry") << true;
}

void TestMainWindowUsability::oversizedSettingsAreFitted()
{
    QFETCH(bool, legacyKey);
    m_window.reset();
    const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
    const QRect huge(available.topLeft() + QPoint(-3000, 50), QSize(6000, 4000));
    {
        QSettings settings;
        settings.clear();
        if (legacyKey) {
            QWidget big;
            big.setGeometry(huge);
            settings.setValue(QStringLiteral("window/geometry"), big.saveGeometry());
        } else {
            settings.setValue(QStringLiteral("window/rect"), huge);
        }
    }
    m_window = std::make_unique<MainWindow>();
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    const QSize least = m_window->minimumSize();
    QVERIFY2(m_window->width() <= std::max(available.width(), least.width()),
             qPrintable(QString::number(m_window->width())));
    QVERIFY2(m_window->height() <= std::max(available.height(), least.height()),
             qPrintable(QString::number(m_window->height())));
    // And what it saves fits too, whatever size it had.
    m_window->resize(6000, 4000);
    QVERIFY(m_window->close());
    const QRect saved = QSettings().value(QStringLiteral("window/rect")).toRect();
    QVERIFY2(available.contains(saved), qPrintable(QStringLiteral("%1 %2 %3×%4")
                                                       .arg(saved.x())
                                                       .arg(saved.y())
                                                       .arg(saved.width())
                                                       .arg(saved.height())));
}

void TestMainWindowUsability::handAndStiffnessInSightTogether()
{
    // Once tabs of one dock: the operating point could not be watched while the input changed.
    m_window->resize(1280, 720);
    connectSim();
    QTRY_VERIFY(find<QDockWidget>("simulatorDock")->isVisible());
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    auto *stiffness = find<QWidget>("stiffness_plot");
    auto *hand = find<QWidget>("simulatorPanel");
    QVERIFY(stiffness->isVisible() && !stiffness->visibleRegion().isEmpty());
    QVERIFY(hand->isVisible() && !hand->visibleRegion().isEmpty());
    // Never tabs of one dock with the stiffness view (at 1280×720 the hand is a tab of the
    // panels under the plots, none of them open here: bottomdocks.h).
    QVERIFY(!m_window->tabifiedDockWidgets(find<QDockWidget>("simulatorDock"))
                 .contains(find<QDockWidget>("stiffnessDock")));
    // The active input in the status bar, following the panel.
    auto *status = find<QLabel>("handStatus");
    QVERIFY(status->isVisible());
    QCOMPARE(status->text(), QStringLiteral("Hand: sine 0.06 N·m at 0.2 Hz"));
    HandInput still;
    still.kind = HandInput::Kind::Constant;
    still.amplitude = 0.01;
    find<SimulatorPanel>("simulatorPanel")->setHand(still);
    QCOMPARE(status->text(), QStringLiteral("Hand: constant 0.01 N·m"));
    m_window->disconnectDevice();
    QTRY_VERIFY(!status->isVisible());
}

void TestMainWindowUsability::keyboardReachesFieldsAndActions()
{
    connectSim();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    auto *editor = find<ParameterEditor>("parameterEditor");

    // Alt+4 goes to K_max; Tab goes from field to field (no sliders, no buttons between).
    QTest::keyClick(m_window.get(), Qt::Key_4, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_K_max"));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_N"));
    QTest::keyClick(m_window.get(), Qt::Key_1, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_D_adm"));
    for (const char *next : {"spin_M_adm", "spin_K_min", "spin_K_max"}) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), find<QWidget>(next));
    }

    // Space in a number field pauses; again resumes.
    auto *plots = find<PlotPanel>("plotPanel");
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(plots->isPaused());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(!plots->isPaused());

    // Ctrl+Z in a field: its own typing first, then the parameter edit.
    const double before = editor->params().K_max;
    auto *box = find<QAbstractSpinBox>("spin_K_max");
    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("0.7"));
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(editor->params().K_max, 0.7);
    QTest::keyClicks(box, QStringLiteral("5"));
    QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier); // the field's own undo: the "5"
    QCOMPARE(editor->params().K_max, 0.7);
    QTest::keyClick(box, Qt::Key_Return);
    for (int i = 0; i < 3 && editor->params().K_max != before; ++i)
        QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(editor->params().K_max, before);
    // Ctrl+Shift+Z in the field redoes the edit: the field has no typing of its own to redo.
    QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(editor->params().K_max, 0.7);

    // Read and window length by key.
    QSignalSpy reads(editor, &ParameterEditor::readRequested);
    QTest::keyClick(m_window.get(), Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(reads.count(), 1);
    QTest::keyClick(m_window.get(), Qt::Key_3, Qt::ControlModifier);
    QCOMPARE(plots->windowLength(), 30.0);
    const bool autoscale = plots->autoscale();
    QTest::keyClick(m_window.get(), Qt::Key_A, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(plots->autoscale(), !autoscale);

    // F1's dialog carries the user guide too.
    ShortcutsDialog dialog(m_window->shortcutActions(), m_window.get());
    auto *guide = dialog.findChild<QTextBrowser *>(QStringLiteral("userGuide"));
    QVERIFY(guide);
    QVERIFY(guide->toPlainText().contains(QStringLiteral("HATPIC Tuner — user guide")));
}

// Issue 27: Alt+1…9 put the cursor in a field without scrolling it into view; the user typed
// blind. Every Alt+N brings its field in sight, even when it had the focus already.
void TestMainWindowUsability::goToScrollsTheFieldIntoView()
{
    m_window->resize(1280, 560); // the Parameters panel scrolls
    connectSim();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    auto *scroll = find<QScrollArea>("parameterScroll");
    QScrollBar *bar = scroll->verticalScrollBar();
    QVERIFY2(bar->maximum() > 0, "the Parameters panel does not scroll");
    const auto inView = [scroll](const char *name) {
        auto *w = scroll->findChild<QWidget *>(QString::fromLatin1(name));
        return scroll->viewport()->rect().contains(
            QRect(w->mapTo(scroll->viewport(), QPoint()), w->size()));
    };
    bar->setValue(0);
    QVERIFY(!inView("spin_tau_limit"));
    QTest::keyClick(m_window.get(), Qt::Key_9, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_tau_limit"));
    QVERIFY(inView("spin_tau_limit"));
    // Scrolled away with the focus kept: Alt+9 brings it back.
    bar->setValue(0);
    QVERIFY(!inView("spin_tau_limit"));
    QTest::keyClick(m_window.get(), Qt::Key_9, Qt::AltModifier);
    QVERIFY(inView("spin_tau_limit"));
    QTest::keyClick(m_window.get(), Qt::Key_1, Qt::AltModifier);
    QVERIFY(inView("spin_D_adm"));
}

// Issue 27: toolbar buttons were Tab stops; Push handed the focus on to the simulated hand's
// selector; the panels under the plots had no keys; F1 named "Disconnect" for Ctrl+K.
void TestMainWindowUsability::keyboardFocusAndPanelKeys()
{
    m_window->resize(1280, 720);
    // Opened disconnected, the window says how to start (issue 27).
    QCOMPARE(find<LinkBanner>("linkBanner")->text(),
             u"Not connected. Press Connect (Ctrl+K) to try the simulated knob."_s);
    connectSim();
    QVERIFY(find<LinkBanner>("linkBanner")->text().isEmpty());
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    for (QToolBar *bar : m_window->findChildren<QToolBar *>()) {
        for (QAbstractButton *button : bar->findChildren<QAbstractButton *>())
            QVERIFY2(button->focusPolicy() == Qt::NoFocus, qPrintable(button->text()));
    }

    // F1 names what the keys do, whatever the actions' states.
    const QStringList lines = ShortcutsDialog::describe(m_window->shortcutActions());
    const auto line = [&](const QKeySequence &key) {
        const QString text = key.toString(QKeySequence::NativeText) + u'\t';
        for (const QString &l : lines) {
            if (l.startsWith(text) || l.contains(u" or "_s + text))
                return l.section(u'\t', 1);
        }
        return QString();
    };
    QCOMPARE(line(QKeySequence(Qt::CTRL | Qt::Key_K)), u"Connect or disconnect"_s);
    QCOMPARE(line(QKeySequence(Qt::CTRL | Qt::Key_R)), u"Record, or stop recording"_s);

    // A key for each panel under the plots: it comes to the front, again hides it.
    const std::pair<const char *, QKeyCombination> panels[] = {
        {"bridgeDock", Qt::CTRL | Qt::SHIFT | Qt::Key_B},
        {"experimentsDock", Qt::CTRL | Qt::SHIFT | Qt::Key_X},
        {"abDock", Qt::CTRL | Qt::SHIFT | Qt::Key_C},
        {"notesDock", Qt::CTRL | Qt::SHIFT | Qt::Key_N},
        {"logDock", Qt::CTRL | Qt::SHIFT | Qt::Key_L},
    };
    for (const auto &[name, key] : panels) {
        auto *dock = find<QDockWidget>(name);
        QVERIFY2(!line(QKeySequence(key)).isEmpty(), name);
        QTest::keySequence(m_window.get(), QKeySequence(key));
        QTRY_VERIFY2(dock->isVisible() && !dock->visibleRegion().isEmpty(), name);
        QTest::keySequence(m_window.get(), QKeySequence(key));
        QTRY_VERIFY2(!dock->isVisible(), name);
    }

    // A click on Push leaves the cursor in the field being tuned.
    auto *box = find<QAbstractSpinBox>("spin_K_max");
    QTest::keyClick(m_window.get(), Qt::Key_4, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), box);
    QTest::keyClicks(box, u"0.5"_s);
    QTest::keyClick(box, Qt::Key_Return);
    QSignalSpy done(find<DeviceParameterLink>("parameterLink"),
                    &DeviceParameterLink::commandFinished);
    QTest::mouseClick(find<QWidget>("button_push"), Qt::LeftButton);
    QVERIFY(done.wait(kConnectMs));
    QCOMPARE(QApplication::focusWidget(), box);
}

// Issue 27: a dock shrunk once stayed shrunk across launches; View → Reset layout.
void TestMainWindowUsability::resetLayoutRestoresTheDocks()
{
    m_window->resize(1280, 720);
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    auto *parameters = find<QDockWidget>("parametersDock");
    const int width = parameters->width();
    QVERIFY(width >= 400);
    m_window->resizeDocks({parameters}, {width - 120}, Qt::Horizontal);
    auto *bridge = find<QDockWidget>("bridgeDock");
    bridge->show();
    auto *stiffness = find<QDockWidget>("stiffnessDock");
    stiffness->hide();
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QVERIFY2(parameters->width() < width - 60, qPrintable(QString::number(parameters->width())));

    // Across a launch, the shrunk dock stays: saved, read back.
    m_window->close();
    m_window = std::make_unique<MainWindow>();
    m_window->resize(1280, 720);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    parameters = find<QDockWidget>("parametersDock");
    QVERIFY2(parameters->width() < width - 60, qPrintable(QString::number(parameters->width())));

    auto *reset = find<QAction>("resetLayoutAction");
    QVERIFY(reset);
    reset->trigger();
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QTRY_VERIFY2(parameters->width() >= 420, // resizeDocksToDefault: at least 420 px
                 qPrintable(QString::number(parameters->width())));
    QVERIFY(find<QDockWidget>("stiffnessDock")->isVisible());
    QVERIFY(!find<QDockWidget>("bridgeDock")->isVisible());
}

void TestMainWindowUsability::derivedFiguresInSightAtEverySize_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("1280x720") << QSize(1280, 720);
    QTest::newRow("1400x900") << QSize(1400, 900);
    QTest::newRow("1920x1080") << QSize(1920, 1080);
}

void TestMainWindowUsability::derivedFiguresInSightAtEverySize()
{
    // Once, at 1280×720 the editor showed D_adm to K_max only; the figures and warnings were
    // below, to be scrolled to. Now they sit under Push, wholly visible at every size.
    QFETCH(QSize, size);
    QVERIFY2(m_window->minimumSizeHint().width() <= 1280 &&
                 m_window->minimumSizeHint().height() <= 720,
             qPrintable(QStringLiteral("%1×%2")
                            .arg(m_window->minimumSizeHint().width())
                            .arg(m_window->minimumSizeHint().height())));
    m_window->resize(size);
    connectSim();
    auto *editor = find<ParameterEditor>("parameterEditor");
    // A set that both saturates and rings: both warnings show.
    DeviceParams p = editor->params();
    p.K_min = 1.0;
    p.K_max = 4.0;
    p.M_adm = 0.001;
    editor->setParams(p, editor->hostParams(), QStringLiteral("test"));
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QCOMPARE(m_window->size(), size);

    auto wholeInSight = [this](QWidget *w) {
        if (!w->isVisible())
            return false;
        const QRect inWindow(w->mapTo(m_window.get(), QPoint(0, 0)), w->size());
        return m_window->rect().contains(inWindow) && w->visibleRegion() == QRegion(w->rect());
    };
    auto *push = find<QWidget>("button_push");
    QVERIFY(wholeInSight(push));
    for (const char *name : {"derivedFiguresBox", "figure_zeta", "figure_peak_tau",
                             "warning_saturation", "warning_ringing"})
        QVERIFY2(wholeInSight(find<QWidget>(name)), name);
    // Next to Push: right below its row.
    const int pushBottom = push->mapTo(m_window.get(), QPoint(0, push->height())).y();
    const int boxTop = find<QWidget>("derivedFiguresBox")->mapTo(m_window.get(), QPoint(0, 0)).y();
    QVERIFY2(boxTop - pushBottom < 80, qPrintable(QString::number(boxTop - pushBottom)));
}

QTEST_MAIN(TestMainWindowUsability)
#include "tst_mainwindowusability.moc"
