// The window's own commands, with their texts, keys, tooltips and object names, and when each
// is enabled. The other parts bring their own actions (editor, profiles, plots, recording);
// WindowMenus puts all of them into the menus and toolbars, the window connects what these
// trigger.
#pragma once

#include "session/sessiontypes.h"

#include <QObject>

class QAction;
class QWidget;

namespace hatpic {

class WindowActions : public QObject
{
    Q_OBJECT
public:
    //! The actions belong to `window` (so that their shortcuts work in all of it).
    explicit WindowActions(QWidget *window);

    //! Enables what the state allows; the pause action plays and pauses a replay.
    void update(SessionState state, bool canSetParams, bool replaying, bool paused);

    QAction *connectDevice = nullptr;  //!< "connectAction", Ctrl+K
    QAction *pause = nullptr;          //!< "pauseAction", Space and Ctrl+P
    QAction *degrees = nullptr;        //!< "degreesAction", Ctrl+D
    QAction *resetReference = nullptr; //!< "resetReferenceAction", Ctrl+0
    QAction *zero = nullptr;
    QAction *saveInDevice = nullptr;
    QAction *openRecording = nullptr; //!< Ctrl+Shift+O
    QAction *backToLive = nullptr;    //!< Ctrl+L
    QAction *resetLayout = nullptr;   //!< "resetLayoutAction": View → Reset layout
    QAction *quit = nullptr;
    QAction *shortcuts = nullptr; //!< F1
    QAction *about = nullptr;
};

} // namespace hatpic
