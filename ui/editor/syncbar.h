// The parameter editor's top bar: whether the device renders what the editor shows (a coloured
// dot and a sentence), undo/redo, Read, Revert and Push, and the live-push and degrees switches.
#pragma once

#include "tuning/tuningmodel.h"

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
    //! Why Push is off, beside it: the first broken rule ("K_min: must be ≤ K_max (0.4), got
    //! 0.9") and how many more; empty hides the line. Its "Show" link asks for the field.
    void setProblems(const QStringList &problems);
    //! Show a switch without emitting its signal.
    void setLivePush(bool on);
    void setAngleInDegrees(bool on);

Q_SIGNALS:
    void livePushToggled(bool on);
    void angleInDegreesToggled(bool on);
    void showProblemRequested(); //!< the problem line's "Show": bring its field into sight

private:
    QLabel *m_label = nullptr;
    QLabel *m_problem = nullptr;
    QCheckBox *m_liveCheck = nullptr;
    QCheckBox *m_degreesCheck = nullptr;
};

} // namespace hatpic
