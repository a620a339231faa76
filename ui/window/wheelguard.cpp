#include "window/wheelguard.h"

#include "plots/qcp.h"

#include <QAbstractScrollArea>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QPointer>
#include <QScrollBar>
#include <QWheelEvent>

namespace hatpic {

WheelGuard::WheelGuard(QObject *parent) : QObject(parent) {}

void WheelGuard::install()
{
    static QPointer<WheelGuard> guard;
    if (guard || !qApp)
        return;
    guard = new WheelGuard(qApp);
    qApp->installEventFilter(guard);
    for (QWidget *widget : QApplication::allWidgets()) {
        if (isValueField(widget))
            noWheelFocus(widget);
    }
}

bool WheelGuard::isValueField(const QWidget *widget)
{
    if (qobject_cast<const QAbstractSpinBox *>(widget) || qobject_cast<const QComboBox *>(widget))
        return true;
    return qobject_cast<const QAbstractSlider *>(widget) &&
           !qobject_cast<const QScrollBar *>(widget);
}

void WheelGuard::noWheelFocus(QWidget *widget)
{
    constexpr int wheelBit = int(Qt::WheelFocus) & ~int(Qt::StrongFocus);
    const int policy = int(widget->focusPolicy());
    if (policy & wheelBit)
        widget->setFocusPolicy(Qt::FocusPolicy(policy & ~wheelBit));
}

bool WheelGuard::isStillPlot(const QWidget *widget)
{
    const auto *plot = qobject_cast<const QCustomPlot *>(widget);
    return plot && !plot->interactions().testFlag(QCP::iRangeZoom);
}

bool WheelGuard::eventFilter(QObject *watched, QEvent *event)
{
    if (!watched->isWidgetType())
        return false;
    auto *widget = static_cast<QWidget *>(watched);
    if (event->type() == QEvent::Polish && isValueField(widget)) {
        noWheelFocus(widget);
    } else if (event->type() == QEvent::Wheel && isStillPlot(widget)) {
        // QCustomPlot stops the wheel going to its parents (WA_NoMousePropagation): the scroll
        // area that holds it gets the turn directly.
        for (QWidget *p = widget->parentWidget(); p; p = p->parentWidget()) {
            auto *area = qobject_cast<QAbstractScrollArea *>(p);
            if (!area)
                continue;
            const auto *wheel = static_cast<QWheelEvent *>(event);
            const QPointF at = widget->mapTo(area->viewport(), wheel->position().toPoint());
            QWheelEvent turn(at, wheel->globalPosition(), wheel->pixelDelta(), wheel->angleDelta(),
                             wheel->buttons(), wheel->modifiers(), wheel->phase(),
                             wheel->inverted(), wheel->source());
            QCoreApplication::sendEvent(area->viewport(), &turn);
            break;
        }
        return true;
    } else if (event->type() == QEvent::Wheel && isValueField(widget) && !widget->hasFocus()) {
        // Ignored and consumed: Qt offers the wheel to the field's parents, as it does for a
        // widget that has no use for it.
        event->ignore();
        return true;
    }
    return false;
}

} // namespace hatpic
