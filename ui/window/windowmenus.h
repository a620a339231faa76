// The window's menus and toolbars: which action sits where, the shortcut table's order, and the
// Help menu's dialogs. The actions belong to the parts (editor, profiles, plots, recording) and
// to WindowActions; the docks add their toggles at the end of the View menu.
#pragma once

#include <QList>
#include <QObject>

class QAction;
class QMainWindow;
class QMenu;

namespace hatpic {

class ConnectionBar;
class LinkStatusWidget;
class ParameterEditor;
class PlotActions;
class ProfileController;
class RecordingControls;
class ThemeController;
class WindowActions;

class WindowMenus : public QObject
{
    Q_OBJECT
public:
    //! What the menus and toolbars hold.
    struct Parts
    {
        WindowActions *actions = nullptr;
        ParameterEditor *editor = nullptr;
        ProfileController *profiles = nullptr;
        PlotActions *plotActions = nullptr;
        RecordingControls *recording = nullptr; //!< its actions, and the widget in the toolbar
        ThemeController *theme = nullptr;
        ConnectionBar *connection = nullptr;    //!< in the Connection toolbar
        LinkStatusWidget *linkStatus = nullptr; //!< in the Connection toolbar
    };

    //! Fills `window`'s menu bar and adds its toolbars; Help's actions open their dialogs.
    WindowMenus(QMainWindow *window, const Parts &parts);

    //! View: the docks' toggles go at its end.
    QMenu *viewMenu() const { return m_view; }
    //! Actions with a shortcut, in menu order (the Help → Keyboard shortcuts table).
    QList<QAction *> shortcutActions() const;

private:
    void createMenus();
    void createToolBars();
    void showShortcuts();
    void showAbout();

    QMainWindow *m_window;
    Parts m_parts;
    QMenu *m_view = nullptr;
};

} // namespace hatpic
