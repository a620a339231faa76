#include "window/focusreveal.h"

#include <QApplication>
#include <QFocusEvent>
#include <QPainter>
#include <QScrollArea>

namespace hatpic {

namespace {

constexpr int kMargin = 12; //!< room around the revealed widget, so its label shows too [px]

QPointer<FocusReveal> &instance()
{
    static QPointer<FocusReveal> filter;
    return filter;
}

bool fromKeyboard(Qt::FocusReason reason)
{
    return reason == Qt::TabFocusReason || reason == Qt::BacktabFocusReason ||
           reason == Qt::ShortcutFocusReason;
}

} // namespace

//! The ring: a frame in the highlight colour, over the focused widget's edge, taking no input.
class FocusRing : public QWidget
{
public:
    explicit FocusRing(QWidget *parent) : QWidget(parent)
    {
        setObjectName(QStringLiteral("focusRing"));
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
        setFocusPolicy(Qt::NoFocus);
    }

protected:
    void paintEvent(QPaintEvent *) override
    {
        QPainter painter(this);
        painter.setRenderHint(QPainter::Antialiasing);
        const int w = FocusReveal::kRingWidth;
        painter.setPen(QPen(palette().color(QPalette::Highlight), w));
        painter.setBrush(Qt::NoBrush);
        painter.drawRoundedRect(QRectF(rect()).adjusted(w / 2.0, w / 2.0, -w / 2.0, -w / 2.0), 3,
                                3);
    }
};

FocusReveal::FocusReveal(QObject *parent) : QObject(parent) {}

void FocusReveal::install()
{
    if (instance() || !qApp)
        return;
    instance() = new FocusReveal(qApp);
    qApp->installEventFilter(instance());
}

QWidget *FocusReveal::ring()
{
    const FocusReveal *filter = instance();
    return filter && filter->m_ring && filter->m_ring->isVisible() ? filter->m_ring.data()
                                                                   : nullptr;
}

void FocusReveal::reveal(QWidget *widget)
{
    for (QWidget *p = widget ? widget->parentWidget() : nullptr; p; p = p->parentWidget()) {
        auto *area = qobject_cast<QScrollArea *>(p);
        if (area && area->widget() && area->widget()->isAncestorOf(widget))
            area->ensureWidgetVisible(widget, kMargin, kMargin);
    }
}

void FocusReveal::ringAround(QWidget *widget)
{
    m_target = widget;
    if (!widget || !widget->parentWidget() || widget->isWindow()) {
        if (m_ring)
            m_ring->hide();
        return;
    }
    if (!m_ring || m_ring->parentWidget() != widget->parentWidget()) {
        delete m_ring;
        m_ring = new FocusRing(widget->parentWidget());
    }
    placeRing();
}

void FocusReveal::placeRing()
{
    if (!m_ring)
        return;
    if (!m_target || !m_target->isVisible()) {
        m_ring->hide();
        return;
    }
    const int w = kRingWidth;
    m_ring->setGeometry(m_target->geometry().adjusted(-w, -w, w, w));
    m_ring->show();
    m_ring->raise();
}

bool FocusReveal::eventFilter(QObject *watched, QEvent *event)
{
    if (!watched->isWidgetType() || watched == m_ring.data())
        return false;
    auto *widget = static_cast<QWidget *>(watched);
    switch (event->type()) {
    case QEvent::FocusIn: {
        const Qt::FocusReason reason = static_cast<QFocusEvent *>(event)->reason();
        if (reason != Qt::MouseFocusReason && reason != Qt::ActiveWindowFocusReason &&
            reason != Qt::PopupFocusReason)
            reveal(widget);
        if (fromKeyboard(reason))
            ringAround(widget);
        else if (reason != Qt::ActiveWindowFocusReason && reason != Qt::PopupFocusReason)
            ringAround(nullptr);
        break;
    }
    case QEvent::FocusOut: {
        const Qt::FocusReason reason = static_cast<QFocusEvent *>(event)->reason();
        // The window losing the focus (a menu, a dialog) keeps the ring for its return.
        if (widget == m_target && reason != Qt::ActiveWindowFocusReason &&
            reason != Qt::PopupFocusReason)
            ringAround(nullptr);
        break;
    }
    case QEvent::Move:
    case QEvent::Resize:
    case QEvent::Show:
    case QEvent::Hide:
        if (widget == m_target)
            placeRing();
        break;
    default:
        break;
    }
    return false;
}

} // namespace hatpic
