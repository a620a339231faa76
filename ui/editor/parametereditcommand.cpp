#include "editor/parametereditcommand.h"

#include "editor/parametereditor.h"

namespace hatpic {

ParameterEditCommand::ParameterEditCommand(ParameterEditor *editor,
                                           const DeviceParams &beforeDevice,
                                           const HostParams &beforeHost,
                                           const DeviceParams &afterDevice,
                                           const HostParams &afterHost, const QString &text,
                                           const QString &field, quint64 gesture)
    : m_editor(editor), m_beforeDevice(beforeDevice), m_beforeHost(beforeHost),
      m_afterDevice(afterDevice), m_afterHost(afterHost), m_field(field), m_gesture(gesture)
{
    setText(text);
}

void ParameterEditCommand::undo()
{
    m_editor->applyParams(m_beforeDevice, m_beforeHost);
}

void ParameterEditCommand::redo()
{
    m_editor->applyParams(m_afterDevice, m_afterHost);
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
    m_afterDevice = next->m_afterDevice;
    m_afterHost = next->m_afterHost;
    setText(next->text());
    // Dragging back to where the gesture started leaves nothing to undo.
    setObsolete(m_afterDevice == m_beforeDevice && m_afterHost == m_beforeHost);
    return true;
}

} // namespace hatpic
