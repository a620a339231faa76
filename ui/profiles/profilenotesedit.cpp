#include "profiles/profilenotesedit.h"

#include "profiles/profilecontroller.h"

#include <QKeyEvent>
#include <QSignalBlocker>

namespace hatpic {

ProfileNotesEdit::ProfileNotesEdit(ProfileController *profiles, QWidget *parent)
    : QPlainTextEdit(parent), m_profiles(profiles)
{
    setObjectName(QStringLiteral("profileNotes"));
    setPlaceholderText(tr("Notes on this profile: what it is for, what it feels like…"));
    setToolTip(tr("The profile's notes, saved in its file. Undo (Ctrl+Z) takes back typing here "
                  "like any parameter edit."));
    // One undo history for the window: the notes' typing is on the window's stack.
    setUndoRedoEnabled(false);
    setTabChangesFocus(true);
    showNotes(profiles->notes());
    connect(this, &QPlainTextEdit::textChanged, this,
            [this] { m_profiles->setNotes(toPlainText()); });
    connect(profiles, &ProfileController::notesChanged, this, &ProfileNotesEdit::showNotes);
}

QSize ProfileNotesEdit::sizeHint() const
{
    return {QPlainTextEdit::sizeHint().width(), fontMetrics().lineSpacing() * 4 + 12};
}

bool ProfileNotesEdit::event(QEvent *event)
{
    if (event->type() == QEvent::ShortcutOverride) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
            event->ignore(); // the shortcut goes to the window's Undo / Redo
            return false;
        }
    }
    return QPlainTextEdit::event(event);
}

void ProfileNotesEdit::showNotes(const QString &notes)
{
    if (notes == toPlainText())
        return; // typing here: the cursor stays where it is
    const QSignalBlocker block(this);
    setPlainText(notes);
    moveCursor(QTextCursor::End);
}

} // namespace hatpic
