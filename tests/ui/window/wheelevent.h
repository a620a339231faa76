// A turn of the mouse wheel as the window system delivers it, for the tests that need one
// (QTest has no wheel in Qt 6.4): a spontaneous QWheelEvent to the widget under the pointer,
// through QApplication::notify, which gives the focus by policy and offers an event the widget
// ignores to its parents — exactly what QTest does for its mouse events on widgets.
#pragma once

#include <QApplication>
#include <QWheelEvent>
#include <QWidget>
#include <QtTest/qtestspontaneevent.h>

namespace hatpic::test {

//! Turns the wheel by `delta` eighths of a degree (120 = one notch, negative = towards the
//! user, i.e. scroll down) with the pointer at `pos` in `widget`.
inline void turnWheel(QWidget *widget, QPoint pos, int delta)
{
    QWidget *target = widget;
    QPoint local = pos;
    if (QWidget *child = widget->childAt(pos)) {
        target = child;
        local = child->mapFrom(widget, pos);
    }
    QWheelEvent event(QPointF(local), QPointF(target->mapToGlobal(local)), QPoint(),
                      QPoint(0, delta), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QSpontaneKeyEvent::setSpontaneous(&event);
    QApplication::instance()->notify(target, &event);
}

} // namespace hatpic::test
