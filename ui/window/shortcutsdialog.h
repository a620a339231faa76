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

    //! "Ctrl+K\tConnect / disconnect" lines, as shown (for tests and the user guide).
    static QStringList describe(const QList<QAction *> &actions);
};

} // namespace hatpic
