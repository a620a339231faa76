#include "editor/editoractions.h"

#include "editor/parameterfield.h"
#include "editor/parameterform.h"
#include "editor/scientificspinbox.h"
#include "model/params.h"

#include <QAction>
#include <QUndoStack>
#include <QWidget>

#include <algorithm>

namespace hatpic {

using namespace Qt::StringLiterals;

EditorActions::EditorActions(QWidget *editor, QUndoStack *undoStack)
    : QObject(editor), m_editor(editor)
{
    push = new QAction(tr("Push"), editor);
    push->setObjectName(u"action_push"_s);
    push->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::Key_Return), QKeySequence(Qt::CTRL | Qt::Key_Enter)});
    push->setToolTip(tr("Send the edited parameters to the device (Ctrl+Return)"));
    read = new QAction(tr("Read"), editor);
    read->setObjectName(u"action_read"_s);
    read->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    read->setToolTip(
        tr("Read from device: ask the device for its current parameters (Ctrl+Shift+R)"));
    revert = new QAction(tr("Revert"), editor);
    revert->setObjectName(u"action_revert"_s);
    revert->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Backspace));
    revert->setToolTip(tr("Revert to device values (undoable; Ctrl+Shift+Backspace)"));
    undo = undoStack->createUndoAction(editor, tr("Undo"));
    redo = undoStack->createRedoAction(editor, tr("Redo"));
    editor->addAction(push);
}

void EditorActions::addGoTo(const ParameterForm *form, std::function<void(ParameterField *)> goTo)
{
    QStringList order;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        order << QString::fromLatin1(deviceFieldName(i));
    order << u"v_max"_s << u"tau_limit"_s;
    for (qsizetype i = 0; i < std::min<qsizetype>(order.size(), 9); ++i) {
        ParameterField *f = form->field(order[i]);
        auto *go = new QAction(tr("Go to %1").arg(f->spec().symbol), m_editor);
        go->setObjectName(u"action_goto_"_s + order[i]);
        go->setShortcut(QKeySequence(Qt::ALT | Qt::Key(Qt::Key_1 + int(i))));
        connect(go, &QAction::triggered, this, [f, goTo] { goTo(f); });
        m_editor->addAction(go);
        m_goTo << go;
    }
}

QList<QAction *> EditorActions::keyboardActions() const
{
    return QList<QAction *>{read, revert} + m_goTo;
}

void EditorActions::update(bool valid, const QStringList &problems, bool canPush, bool pushing,
                           bool differs)
{
    push->setEnabled(valid && canPush && !pushing);
    push->setToolTip(valid ? tr("Send the edited parameters to the device (Ctrl+Return)")
                           : tr("Fix the invalid fields first:\n%1").arg(problems.join(u'\n')));
    read->setEnabled(canPush && !pushing);
    revert->setEnabled(!pushing && differs);
}

} // namespace hatpic
