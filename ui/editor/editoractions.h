// The parameter editor's commands, with their texts, keys, tooltips and object names, and when
// each is enabled: Push, Read, Revert, Undo/Redo (the undo stack's, given keys by the window)
// and "Go to <field>" (Alt+1 … Alt+9). The editor connects what they trigger.
#pragma once

#include <functional>

#include <QList>
#include <QObject>

class QAction;
class QUndoStack;
class QWidget;

namespace hatpic {

class ParameterField;
class ParameterForm;

class EditorActions : public QObject
{
    Q_OBJECT
public:
    //! The actions belong to `editor`, which carries Push's and the Go-to shortcuts.
    EditorActions(QWidget *editor, QUndoStack *undoStack);

    //! Alt+1 … Alt+9 put the cursor in the device fields, v_max and tau_limit, in the order
    //! they are shown, through `goTo` (which scrolls the field into view first).
    void addGoTo(const ParameterForm *form, std::function<void(ParameterField *)> goTo);
    //! Read, Revert and the Go-to actions, for the shortcut table.
    QList<QAction *> keyboardActions() const;

    //! Push needs a valid set (else its tooltip lists `problems`) and Read a device that takes
    //! parameters, both with no push in flight; Revert a device tuning that `differs`.
    void update(bool valid, const QStringList &problems, bool canPush, bool pushing, bool differs);

    QAction *push = nullptr;   //!< "action_push", Ctrl+Return
    QAction *read = nullptr;   //!< "action_read", Ctrl+Shift+R
    QAction *revert = nullptr; //!< "action_revert", Ctrl+Shift+Backspace
    QAction *undo = nullptr;   //!< no shortcut of its own
    QAction *redo = nullptr;   //!< no shortcut of its own

private:
    QWidget *m_editor;
    QList<QAction *> m_goTo;
};

} // namespace hatpic
