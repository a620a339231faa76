// Help (F1): every action of the window that has a shortcut, in a table, and the user guide
// that ships inside the program.
#pragma once

#include <QDialog>

class QAction;

namespace hatpic {

class ShortcutsDialog : public QDialog
{
    Q_OBJECT
public:
    ShortcutsDialog(const QList<QAction *> &actions, QWidget *parent = nullptr);

    //! An action's name for the table, set as this property where its text says its state
    //! ("Disconnect", "Stop recording"): the table names what the keys do, not what is now.
    static constexpr const char *kNameProperty = "shortcutName";

    //! "Ctrl+K\tConnect or disconnect" lines, as shown (for tests and the user guide).
    static QStringList describe(const QList<QAction *> &actions);
    //! Gives `action` its name for the table (kNameProperty).
    static void setName(QAction *action, const QString &name);
};

} // namespace hatpic
