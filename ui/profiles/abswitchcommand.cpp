#include "profiles/abswitchcommand.h"

#include "profiles/profilecontroller.h"

#include <QCoreApplication>

namespace hatpic {

AbSwitchCommand::AbSwitchCommand(ProfileController *controller, int fromSlot, int toSlot)
    : m_controller(controller), m_from(fromSlot), m_to(toSlot)
{
    setText(QCoreApplication::translate("hatpic::ProfileController", "Switch to %1")
                .arg(ProfileController::slotName(toSlot)));
}

void AbSwitchCommand::undo()
{
    m_controller->activateSlot(m_from);
}

void AbSwitchCommand::redo()
{
    m_controller->activateSlot(m_to);
}

} // namespace hatpic
