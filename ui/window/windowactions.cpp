#include "window/windowactions.h"

#include <QAction>
#include <QStyle>
#include <QWidget>

namespace hatpic {

WindowActions::WindowActions(QWidget *window) : QObject(window)
{
    auto make = [window](const QString &text, const char *name = nullptr) {
        auto *action = new QAction(text, window);
        if (name)
            action->setObjectName(QString::fromLatin1(name));
        return action;
    };
    connectDevice = make(tr("&Connect"), "connectAction");
    connectDevice->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    connectDevice->setToolTip(tr("Connect to the chosen port, or disconnect (Ctrl+K)"));

    pause = make(tr("&Pause"), "pauseAction");
    pause->setIcon(window->style()->standardIcon(QStyle::SP_MediaPause));
    pause->setCheckable(true);
    pause->setShortcuts({QKeySequence(Qt::Key_Space), QKeySequence(Qt::CTRL | Qt::Key_P)});
    pause->setToolTip(tr("Freeze the plots (the link keeps recording); in replay, "
                         "play or pause (Space, Ctrl+P)"));

    degrees = make(tr("Angles in &degrees"), "degreesAction");
    degrees->setCheckable(true);
    degrees->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    degrees->setToolTip(tr("Show angles in degrees; data and files stay in radians (Ctrl+D)"));

    resetReference = make(tr("Reset &p_ref"), "resetReferenceAction");
    resetReference->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    resetReference->setToolTip(tr("Set the reference position p_ref to 0 (Ctrl+0)"));

    zero = make(tr("Set θ0 to the current &angle (ZERO)"), "zeroAction");
    saveInDevice = make(tr("Save parameters in the &device"), "saveInDeviceAction");
    saveInDevice->setToolTip(tr("SAVE_PARAMS: the device restores them at power-up"));

    openRecording = make(tr("Ope&n Recording…"), "openRecordingAction");
    openRecording->setIcon(window->style()->standardIcon(QStyle::SP_DialogOpenButton));
    openRecording->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    openRecording->setToolTip(tr("Replay a recording (Ctrl+Shift+O)"));
    backToLive = make(tr("Back to &Live"), "backToLiveAction");
    backToLive->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));

    resetLayout = make(tr("&Reset Layout"), "resetLayoutAction");
    resetLayout->setToolTip(tr("The panels where and as large as at a first launch"));

    quit = make(tr("&Quit"));
    quit->setShortcut(QKeySequence::Quit);
    shortcuts = make(tr("&User Guide and Shortcuts"));
    shortcuts->setShortcut(QKeySequence(Qt::Key_F1));
    about = make(tr("&About HATPIC Tuner"));
}

void WindowActions::update(SessionState state, bool canSetParams, bool replaying, bool paused)
{
    const bool connected = state == SessionState::Connected;
    connectDevice->setText(state == SessionState::Disconnected ? tr("&Connect")
                                                               : tr("&Disconnect"));
    resetReference->setEnabled(connected);
    zero->setEnabled(connected && canSetParams);
    saveInDevice->setEnabled(connected && canSetParams);
    backToLive->setEnabled(replaying);
    pause->setText(replaying ? tr("&Play / Pause Replay") : tr("&Pause"));
    pause->setChecked(paused);
}

} // namespace hatpic
