#include "editor/parametereditcommand.h"

#include "editor/parametereditor.h"

namespace hatpic {

ParameterEditCommand::ParameterEditCommand(ParameterEditor *editor, const Tuning &before,
                                           const Tuning &after, const QString &text,
                                           const QString &field, quint64 gesture)
    : m_editor(editor), m_before(before), m_after(after), m_field(field), m_gesture(gesture)
{
    setText(text);
}

void ParameterEditCommand::undo()
{
    m_editor->applyTuning(m_before);
}

void ParameterEditCommand::redo()
{
    m_editor->applyTuning(m_after);
}

int ParameterEditCommand::id() const
{
    return m_field.isEmpty() ? -1 : kMergeId;
}

bool ParameterEditCommand::mergeWith(const QUndoCommand *other)
{
    if (other->id() != id())
        return false;
    const auto *next = static_cast<const ParameterEditCommand *>(other);
    if (next->m_field != m_field || next->m_gesture != m_gesture || next->m_editor != m_editor)
        return false;
    m_after = next->m_after;
    setText(next->text());
    // Dragging back to where the gesture started leaves nothing to undo.
    setObsolete(m_after == m_before);
    return true;
}

} // namespace hatpic
