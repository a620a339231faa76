// The main window's menus and toolbars: which action sits where. The actions themselves belong
// to the parts (editor, profiles, plots, recording) and to WindowActions.
#include "window/mainwindow.h"

#include "connection/connectionbar.h"
#include "connection/linkstatuswidget.h"
#include "editor/parametereditor.h"
#include "plots/plotactions.h"
#include "profiles/profilecontroller.h"
#include "recording/recordingcontrols.h"
#include "window/theme.h"
#include "window/windowactions.h"

#include <QMenu>
#include <QMenuBar>
#include <QToolBar>

namespace hatpic {

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_profiles->openAction());
    file->addMenu(m_profiles->recentMenu());
    file->addMenu(m_profiles->presetsMenu());
    file->addAction(m_profiles->saveAction());
    file->addAction(m_profiles->saveAsAction());
    file->addSeparator();
    file->addAction(m_actions->openRecording);
    file->addAction(m_plotActions->exportImageAction());
    file->addAction(m_plotActions->exportCsvAction());
    file->addSeparator();
    file->addAction(m_actions->quit);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_editor->undoAction());
    edit->addAction(m_editor->redoAction());
    edit->addSeparator();
    edit->addAction(m_profiles->abToggleAction());
    edit->addAction(m_profiles->pushOnSwitchAction());

    QMenu *device = menuBar()->addMenu(tr("&Device"));
    device->addAction(m_actions->connectDevice);
    device->addSeparator();
    device->addAction(m_editor->pushAction());
    device->addAction(m_editor->readAction());
    device->addAction(m_editor->revertAction());
    device->addSeparator();
    device->addAction(m_actions->resetReference);
    device->addAction(m_actions->zero);
    device->addAction(m_actions->saveInDevice);
    device->addSeparator();
    device->addAction(m_recording->recordAction());
    device->addAction(m_recording->planAction());

    QMenu *view = menuBar()->addMenu(tr("&View"));
    m_viewMenu = view;
    view->addAction(m_actions->pause);
    view->addAction(m_actions->backToLive);
    QMenu *window = view->addMenu(tr("&Window Length"));
    window->addActions(m_plotActions->windowActions());
    view->addAction(m_plotActions->autoscaleAction());
    view->addAction(m_actions->degrees);
    view->addAction(m_plotActions->measureAction());
    m_plotActions->addSeriesActions(view->addMenu(tr("&Series")));
    view->addMenu(m_theme->menu());
    view->addSeparator(); // the docks' toggles follow (createDocks)

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_actions->shortcuts);
    help->addAction(m_actions->about);
}

void MainWindow::createToolBars()
{
    QToolBar *link = addToolBar(tr("Connection"));
    link->setObjectName(QStringLiteral("connectionToolBar"));
    link->addWidget(m_connection);
    link->addSeparator();
    link->addWidget(m_linkStatus);

    addToolBarBreak();
    QToolBar *plots = addToolBar(tr("Plots"));
    plots->setObjectName(QStringLiteral("plotsToolBar"));
    plots->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    plots->addAction(m_actions->pause);
    plots->addSeparator();
    plots->addActions(m_plotActions->windowActions());
    plots->addSeparator();
    plots->addAction(m_plotActions->autoscaleAction());
    plots->addAction(m_actions->degrees);
    plots->addAction(m_plotActions->measureAction());
    plots->addAction(m_actions->resetReference);
    plots->addSeparator();
    plots->addWidget(m_recording);
    plots->addAction(m_actions->openRecording);
}

} // namespace hatpic
