// The parameter editor's top bar: whether the device renders what the editor shows (a coloured
// dot and a sentence), undo/redo, Read, Revert and Push, and the live-push and degrees switches.
#pragma once

#include "editor/synctracker.h"

#include <QWidget>

class QAction;
class QCheckBox;
class QLabel;
class QUndoStack;

namespace hatpic {

class SyncBar : public QWidget
{
    Q_OBJECT
public:
    //! Buttons for the editor's actions; none is owned.
    SyncBar(QUndoStack *undo, QAction *read, QAction *revert, QAction *push,
            QWidget *parent = nullptr);

    void setState(SyncState state, const QString &text);
    //! Show a switch without emitting its signal.
    void setLivePush(bool on);
    void setAngleInDegrees(bool on);

Q_SIGNALS:
    void livePushToggled(bool on);
    void angleInDegreesToggled(bool on);

private:
    QLabel *m_label = nullptr;
    QCheckBox *m_liveCheck = nullptr;
    QCheckBox *m_degreesCheck = nullptr;
};

} // namespace hatpic
