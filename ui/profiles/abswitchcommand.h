// Switching the A/B slot as an undo step, so undo/redo never puts one slot's values into the
// other: undoing past a switch switches back.
#pragma once

#include <QUndoCommand>

namespace hatpic {

class ProfileController;

class AbSwitchCommand : public QUndoCommand
{
public:
    AbSwitchCommand(ProfileController *controller, int fromSlot, int toSlot);

    void undo() override;
    void redo() override;

private:
    ProfileController *m_controller;
    int m_from;
    int m_to;
};

} // namespace hatpic
