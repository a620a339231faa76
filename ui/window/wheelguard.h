// The mouse wheel scrolls; it changes a value only in the field that has the keyboard focus.
//
// One application-wide event filter for every spin box, slider and combo box (issue 21): a
// pointer resting on a field, or a panel scrolled past its fields, never edits a value (and,
// with live push on, never reaches the device). A wheel turned over a field without focus goes
// on to what holds the field (the Parameters panel's scroll area scrolls); a field that has
// the focus (clicked, or reached with Tab) takes the wheel as Qt makes it. Fields no longer
// take the focus from the wheel itself, which would otherwise hand them the next turn. A plot
// that does not zoom with the wheel passes it on likewise.
#pragma once

#include <QObject>

class QWidget;

namespace hatpic {

class WheelGuard : public QObject
{
    Q_OBJECT
public:
    //! Installs the guard on the application, once however often it is called; it covers the
    //! widgets that exist and every widget made afterwards.
    static void install();
    //! A field whose value the wheel changes: a spin box, a slider (not a scroll bar) or a
    //! combo box.
    static bool isValueField(const QWidget *widget);
    //! A plot the wheel does not zoom (the Bridge panel's energy plot): QCustomPlot takes every
    //! wheel event, so without the guard a panel did not scroll over it (issue 27).
    static bool isStillPlot(const QWidget *widget);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    explicit WheelGuard(QObject *parent);
    //! Takes the wheel out of a field's focus policy (Qt's spin boxes take the focus on a turn).
    static void noWheelFocus(QWidget *widget);
};

} // namespace hatpic
