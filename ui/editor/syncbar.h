// The parameter editor's top bar: whether the device renders what the editor shows (a coloured
// dot and a sentence), undo/redo, Read, Revert and Push, and the live-push and degrees switches.
#pragma once

#include "tuning/tuningmodel.h"

#include <QWidget>

class QAction;
class QCheckBox;
class QComboBox;
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
    //! The device's knobs: a selector of the one tuned (knob 1 … `count`), shown for two or
    //! more. A new count selects knob 1 without emitting knobSelected.
    void setKnobs(int count);
    //! The knob tuned: 0 for knob 1.
    int knob() const;

Q_SIGNALS:
    void livePushToggled(bool on);
    void angleInDegreesToggled(bool on);
    void showProblemRequested(); //!< the problem line's "Show": bring its field into sight
    void knobSelected(int knob); //!< the user chose another knob to tune (0 for knob 1)

private:
    QLabel *m_label = nullptr;
    QLabel *m_problem = nullptr;
    QCheckBox *m_liveCheck = nullptr;
    QCheckBox *m_degreesCheck = nullptr;
    QLabel *m_knobLabel = nullptr;
    QComboBox *m_knobBox = nullptr;
};

} // namespace hatpic
