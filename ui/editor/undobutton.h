// An Undo or Redo tool button with a short fixed label; what it would undo is its tooltip.
#pragma once

#include <QToolButton>

class QUndoStack;

namespace hatpic {

class UndoButton : public QToolButton
{
    Q_OBJECT
public:
    enum class Direction { Undo, Redo };

    UndoButton(QUndoStack *stack, Direction direction, QWidget *parent = nullptr);

private:
    void refresh();

    QUndoStack *m_stack;
    Direction m_direction;
};

} // namespace hatpic
