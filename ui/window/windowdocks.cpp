#include "window/windowdocks.h"

#include "editor/parametereditor.h"
#include "simulator/simulatorpanel.h"
#include "stiffness/stiffnessview.h"
#include "window/abdock.h"
#include "window/bottomdocks.h"
#include "window/bridgedock.h"
#include "window/experimentsdock.h"
#include "window/measuredocks.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QPlainTextEdit>

#include <algorithm>
#include <utility>

namespace hatpic {

namespace {

//! An action of `window` with `key` that brings `dock` to the front, or hides it when it is in
//! front already (a dock behind another's tab is shown, not hidden, as its toggle would).
QAction *panelShortcut(QMainWindow *window, QDockWidget *dock, QKeyCombination key)
{
    auto *action =
        new QAction(QObject::tr("Show or hide the %1 panel").arg(dock->windowTitle()), window);
    action->setObjectName(dock->objectName() + QStringLiteral("Shortcut"));
    action->setShortcut(QKeySequence(key));
    action->setShortcutContext(Qt::WindowShortcut);
    window->addAction(action);
    QObject::connect(action, &QAction::triggered, dock, [dock] {
        if (dock->isVisible() && !dock->visibleRegion().isEmpty()) {
            dock->hide();
            return;
        }
        dock->show();
        dock->raise();
        // The keyboard follows: the panel's first field that takes Tab.
        for (QWidget *w : dock->findChildren<QWidget *>()) {
            if ((w->focusPolicy() & Qt::TabFocus) && w->isVisibleTo(dock) && w->isEnabled()) {
                w->setFocus(Qt::ShortcutFocusReason);
                break;
            }
        }
    });
    // The View menu's entry shows the keys too.
    dock->toggleViewAction()->setToolTip(QStringLiteral("%1 (%2)").arg(
        action->text(), action->shortcut().toString(QKeySequence::NativeText)));
    return action;
}

} // namespace

void resizeDocksToDefault(QMainWindow *window, const WindowDocks &docks)
{
    // As wide as the editor wants (within reason): its rows are long.
    window->resizeDocks({docks.parameters},
                        {std::clamp(docks.editor->sizeHint().width() + 24, 420, 600)},
                        Qt::Horizontal);
    // The stiffness view's two plots stay readable at 720 px (issue 21: once 40 px each).
    window->resizeDocks({docks.parameters, docks.stiffness}, {500, 360}, Qt::Vertical);
}

WindowDocks addWindowDocks(QMainWindow *window, const WindowDockParts &parts)
{
    auto makeDock = [window](const QString &title, const QString &name, QWidget *widget,
                             Qt::DockWidgetArea area) {
        auto *dock = new QDockWidget(title, window);
        dock->setObjectName(name);
        dock->setWidget(widget);
        window->addDockWidget(area, dock);
        return dock;
    };
    WindowDocks docks;
    docks.parameters = makeDock(QObject::tr("Parameters"), QStringLiteral("parametersDock"),
                                parts.editor, Qt::RightDockWidgetArea);
    docks.stiffness = makeDock(QObject::tr("Stiffness"), QStringLiteral("stiffnessDock"),
                               parts.stiffness, Qt::RightDockWidgetArea);
    // Under the plots, so that the hand and the stiffness view are in sight together.
    docks.simulator = makeDock(QObject::tr("Simulated hand"), QStringLiteral("simulatorDock"),
                               parts.simPanel, Qt::BottomDockWidgetArea);
    docks.logView = new QPlainTextEdit(window);
    docks.logView->setReadOnly(true);
    docks.logView->setMaximumBlockCount(2000);
    docks.log = makeDock(QObject::tr("Device log"), QStringLiteral("logDock"), docks.logView,
                         Qt::BottomDockWidgetArea);
    docks.log->hide();
    window->setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea); // the hand's: plots only
    // The robot bridge is opened from View → Bridge, beside the device log: never in front of
    // the hand, which must stay in sight with the stiffness view.
    docks.bridge = addBridgeDock(window, parts.client, parts.profiles, parts.tuning, docks.log);
    docks.bridge->hide();
    // Tuning experiments (docs/experiments.md): View → Experiments, beside the device log.
    QDockWidget *experiments = addExperimentsDock(window, parts, docks.log);
    docks.editor = parts.editor;
    resizeDocksToDefault(window, docks);

    for (QDockWidget *dock :
         {docks.parameters, docks.stiffness, docks.simulator, docks.bridge, docks.log})
        parts.view->addAction(dock->toggleViewAction());
    parts.view->addAction(experiments->toggleViewAction());
    // A/B comparison and the profile's notes, opened from the View menu, beside the log.
    for (QDockWidget *dock :
         addAbDocks(window, parts.profiles, parts.tuning, parts.editor, parts.stiffness, docks.log))
        parts.view->addAction(dock->toggleViewAction());
    addMeasureDocks(window, parts.plots, parts.plotActions, parts.profiles, parts.tuning,
                    parts.stiffness, parts.view, docks.log);
    // Keys for the panels under the plots (issue 27: none had one).
    const std::pair<const char *, QKeyCombination> keys[] = {
        {"bridgeDock", Qt::CTRL | Qt::SHIFT | Qt::Key_B},
        {"experimentsDock", Qt::CTRL | Qt::SHIFT | Qt::Key_X},
        {"abDock", Qt::CTRL | Qt::SHIFT | Qt::Key_C},
        {"notesDock", Qt::CTRL | Qt::SHIFT | Qt::Key_N},
        {"logDock", Qt::CTRL | Qt::SHIFT | Qt::Key_L},
    };
    for (const auto &[name, key] : keys) {
        if (auto *dock = window->findChild<QDockWidget *>(QString::fromLatin1(name)))
            docks.panelShortcuts << panelShortcut(window, dock, key);
    }
    // The panels under the plots open usable, beside the hand or tabbed with it.
    auto *bottom = new BottomDocks(window, docks.simulator);
    for (QDockWidget *dock : window->findChildren<QDockWidget *>()) {
        if (dock != docks.simulator && window->dockWidgetArea(dock) == Qt::BottomDockWidgetArea)
            bottom->add(dock);
    }
    return docks;
}

} // namespace hatpic
