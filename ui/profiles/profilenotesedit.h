// The active profile's notes ("notes" in the file), visible and editable in the window. Typing
// goes to the ProfileController as undoable edits (the '*' counts them, Save writes them); a
// load, a switch or an undo shows the notes it brings.
#pragma once

#include <QPlainTextEdit>

namespace hatpic {

class ProfileController;

class ProfileNotesEdit : public QPlainTextEdit
{
    Q_OBJECT
public:
    explicit ProfileNotesEdit(ProfileController *profiles, QWidget *parent = nullptr);

    QSize sizeHint() const override;

protected:
    //! Leaves Undo and Redo to the window's actions (the notes' typing is on their stack).
    bool event(QEvent *event) override;

private:
    void showNotes(const QString &notes);

    ProfileController *m_profiles;
};

} // namespace hatpic
