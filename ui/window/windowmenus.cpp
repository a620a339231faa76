#include "window/windowmenus.h"

#include "connection/connectionbar.h"
#include "connection/linkstatuswidget.h"
#include "editor/parametereditor.h"
#include "plots/plotactions.h"
#include "profiles/profilecontroller.h"
#include "recording/recordingcontrols.h"
#include "window/shortcutsdialog.h"
#include "window/theme.h"
#include "window/windowactions.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QToolBar>

namespace hatpic {

WindowMenus::WindowMenus(QMainWindow *window, const Parts &parts)
    : QObject(window), m_window(window), m_parts(parts)
{
    connect(m_parts.actions->shortcuts, &QAction::triggered, this, &WindowMenus::showShortcuts);
    connect(m_parts.actions->about, &QAction::triggered, this, &WindowMenus::showAbout);
    createMenus();
    createToolBars();
    // The table names what the keys do; these actions' texts say their state.
    ShortcutsDialog::setName(m_parts.actions->connectDevice, tr("Connect or disconnect"));
    ShortcutsDialog::setName(m_parts.actions->pause, tr("Pause or resume (replay: play/pause)"));
    ShortcutsDialog::setName(m_parts.recording->recordAction(), tr("Record, or stop recording"));
}

void WindowMenus::createMenus()
{
    const WindowActions *actions = m_parts.actions;
    ProfileController *profiles = m_parts.profiles;
    ParameterEditor *editor = m_parts.editor;
    PlotActions *plotActions = m_parts.plotActions;
    QMenuBar *bar = m_window->menuBar();

    QMenu *file = bar->addMenu(tr("&File"));
    file->addAction(profiles->openAction());
    file->addMenu(profiles->recentMenu());
    file->addMenu(profiles->presetsMenu());
    file->addAction(profiles->saveAction());
    file->addAction(profiles->saveAsAction());
    file->addSeparator();
    file->addAction(actions->openRecording);
    file->addAction(plotActions->exportImageAction());
    file->addAction(plotActions->exportCsvAction());
    file->addSeparator();
    file->addAction(actions->quit);

    QMenu *edit = bar->addMenu(tr("&Edit"));
    edit->addAction(editor->undoAction());
    edit->addAction(editor->redoAction());
    edit->addSeparator();
    edit->addAction(profiles->abToggleAction());
    edit->addAction(profiles->pushOnSwitchAction());

    QMenu *device = bar->addMenu(tr("&Device"));
    device->addAction(actions->connectDevice);
    device->addSeparator();
    device->addAction(editor->pushAction());
    device->addAction(editor->readAction());
    device->addAction(editor->revertAction());
    device->addSeparator();
    device->addAction(actions->resetReference);
    device->addAction(actions->zero);
    device->addAction(actions->saveInDevice);
    device->addSeparator();
    device->addAction(m_parts.recording->recordAction());
    device->addAction(m_parts.recording->planAction());

    m_view = bar->addMenu(tr("&View"));
    m_view->addAction(actions->pause);
    m_view->addAction(actions->backToLive);
    QMenu *window = m_view->addMenu(tr("&Window Length"));
    window->addActions(plotActions->windowActions());
    m_view->addAction(plotActions->autoscaleAction());
    m_view->addAction(actions->degrees);
    m_view->addAction(plotActions->measureAction());
    plotActions->addSeriesActions(m_view->addMenu(tr("&Series")));
    m_view->addMenu(m_parts.theme->menu());
    m_view->addAction(actions->resetLayout);
    m_view->addSeparator(); // the docks' toggles follow

    QMenu *help = bar->addMenu(tr("&Help"));
    help->addAction(actions->shortcuts);
    help->addAction(actions->about);
}

void WindowMenus::createToolBars()
{
    const WindowActions *actions = m_parts.actions;
    PlotActions *plotActions = m_parts.plotActions;

    QToolBar *link = m_window->addToolBar(tr("Connection"));
    link->setObjectName(QStringLiteral("connectionToolBar"));
    link->addWidget(m_parts.connection);
    link->addSeparator();
    link->addWidget(m_parts.linkStatus);

    m_window->addToolBarBreak();
    QToolBar *plots = m_window->addToolBar(tr("Plots"));
    plots->setObjectName(QStringLiteral("plotsToolBar"));
    plots->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    plots->addAction(actions->pause);
    plots->addSeparator();
    plots->addActions(plotActions->windowActions());
    plots->addSeparator();
    plots->addAction(plotActions->autoscaleAction());
    plots->addAction(actions->degrees);
    plots->addAction(plotActions->measureAction());
    plots->addAction(actions->resetReference);
    plots->addSeparator();
    plots->addWidget(m_parts.recording);
    plots->addAction(actions->openRecording);
    // The toolbars' buttons are no Tab stops (their actions have menus and keys, docs/user-
    // guide.md): Tab goes from field to field.
    for (QToolBar *bar : {link, plots}) {
        for (QAbstractButton *button : bar->findChildren<QAbstractButton *>())
            button->setFocusPolicy(Qt::NoFocus);
    }
}

QList<QAction *> WindowMenus::shortcutActions() const
{
    const WindowActions *actions = m_parts.actions;
    ParameterEditor *editor = m_parts.editor;
    ProfileController *profiles = m_parts.profiles;
    PlotActions *plotActions = m_parts.plotActions;
    return QList<QAction *>{actions->connectDevice,
                            editor->pushAction(),
                            actions->pause,
                            m_parts.recording->recordAction(),
                            editor->undoAction(),
                            editor->redoAction(),
                            profiles->abToggleAction(),
                            profiles->openAction(),
                            profiles->saveAction(),
                            profiles->saveAsAction(),
                            actions->openRecording,
                            actions->backToLive,
                            plotActions->autoscaleAction(),
                            actions->degrees,
                            actions->resetReference,
                            plotActions->exportImageAction(),
                            plotActions->exportCsvAction(),
                            plotActions->measureAction(),
                            actions->shortcuts,
                            actions->quit} +
           editor->keyboardActions() + plotActions->windowActions();
}

void WindowMenus::showShortcuts()
{
    ShortcutsDialog dialog(shortcutActions(), m_window);
    dialog.exec();
}

void WindowMenus::showAbout()
{
    QMessageBox::about(
        m_window, tr("About HATPIC Tuner"),
        tr("<b>HATPIC Tuner %1</b><p>Tuning and live plots for the HATPIC single-axis haptic "
           "joystick (Mellet, Ruggiero, Lippiello).</p>")
            .arg(QApplication::applicationVersion()));
}

} // namespace hatpic
