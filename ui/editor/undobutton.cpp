#include "editor/undobutton.h"

#include <QUndoStack>

namespace hatpic {

using namespace Qt::StringLiterals;

UndoButton::UndoButton(QUndoStack *stack, Direction direction, QWidget *parent)
    : QToolButton(parent), m_stack(stack), m_direction(direction)
{
    const bool undo = direction == Direction::Undo;
    setText(undo ? tr("Undo") : tr("Redo"));
    setObjectName(undo ? u"button_undo"_s : u"button_redo"_s);
    connect(stack, &QUndoStack::indexChanged, this, &UndoButton::refresh);
    connect(stack, &QUndoStack::cleanChanged, this, &UndoButton::refresh);
    connect(this, &QToolButton::clicked, stack, undo ? &QUndoStack::undo : &QUndoStack::redo);
    refresh();
}

void UndoButton::refresh()
{
    const bool undo = m_direction == Direction::Undo;
    setEnabled(undo ? m_stack->canUndo() : m_stack->canRedo());
    const QString what = undo ? m_stack->undoText() : m_stack->redoText();
    setToolTip(what.isEmpty() ? QString() : text() + u": "_s + what);
}

} // namespace hatpic
