#include "profiles/noteseditcommand.h"

#include "profiles/profilecontroller.h"

#include <QCoreApplication>

namespace hatpic {

NotesEditCommand::NotesEditCommand(ProfileController *controller, const QString &before,
                                   const QString &after)
    : m_controller(controller), m_before(before), m_after(after)
{
    setText(QCoreApplication::translate("hatpic::ProfileController", "Edit notes"));
}

void NotesEditCommand::undo()
{
    m_controller->applyNotes(m_before);
}

void NotesEditCommand::redo()
{
    m_controller->applyNotes(m_after);
}

bool NotesEditCommand::mergeWith(const QUndoCommand *other)
{
    // Only typing in a row merges: a switch or a parameter edit in between is another command,
    // so undo never takes back notes of the other slot.
    m_after = static_cast<const NotesEditCommand *>(other)->m_after;
    setObsolete(m_after == m_before);
    return true;
}

} // namespace hatpic
