// Editing a profile's notes as an undo step on the window's stack, so Ctrl+Z takes back typing
// in the notes like any parameter edit. Consecutive typing merges into one step.
#pragma once

#include <QString>
#include <QUndoCommand>

namespace hatpic {

class ProfileController;

class NotesEditCommand : public QUndoCommand
{
public:
    static constexpr int kId = 0x4e4f5445; //!< "NOTE": merges with the previous notes edit

    NotesEditCommand(ProfileController *controller, const QString &before, const QString &after);

    void undo() override;
    void redo() override;
    int id() const override { return kId; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    ProfileController *m_controller;
    QString m_before;
    QString m_after;
};

} // namespace hatpic
