#include "window/bottomdocks.h"

#include <QAction>
#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>
#include <QStyle>
#include <QTimer>

#include <algorithm>

namespace hatpic {

namespace {

//! Whether the user has the dock open (shown, maybe behind another tab).
bool isOpen(const QDockWidget *dock)
{
    return dock->toggleViewAction()->isChecked();
}

//! Whether the dock is in sight: a dock behind another's tab is "visible" but moved away.
bool inFront(const QDockWidget *dock)
{
    return dock->isVisible() && !dock->visibleRegion().isEmpty();
}

//! Room left and right of the hand when it stands beside the panels, so that a window a few
//! pixels wider or narrower does not move it back and forth [px].
constexpr int kHysteresis = 40;

} // namespace

BottomDocks::BottomDocks(QMainWindow *window, QDockWidget *hand)
    : QObject(window), m_window(window), m_hand(hand)
{
    // Placed once shown (after the saved layout is restored), and whenever the window resizes.
    m_window->installEventFilter(this);
}

void BottomDocks::add(QDockWidget *panel)
{
    m_panels.append(panel);
    connect(panel->toggleViewAction(), &QAction::triggered, this, [this, panel](bool on) {
        if (on)
            open(panel);
    });
    connect(panel, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible || m_handHeight <= 0)
            return;
        // The last panel closed: the hand alone again, at the height it had.
        QTimer::singleShot(0, this, [this] {
            if (std::none_of(m_panels.cbegin(), m_panels.cend(), isOpen) && isOpen(m_hand) &&
                m_handHeight > 0) {
                m_window->resizeDocks({m_hand}, {m_handHeight}, Qt::Vertical);
                m_handHeight = 0;
            }
        });
    });
}

bool BottomDocks::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_window && (event->type() == QEvent::Resize || event->type() == QEvent::Show) &&
        !m_placeQueued) {
        m_placeQueued = true; // once the layout has taken the new size in
        QTimer::singleShot(0, this, [this] {
            m_placeQueued = false;
            placeHand();
        });
    }
    return QObject::eventFilter(watched, event);
}

void BottomDocks::placeHand()
{
    if (m_panels.isEmpty() || m_hand->isFloating() ||
        m_window->dockWidgetArea(m_hand) != Qt::BottomDockWidgetArea)
        return;
    // The area under the plots is as wide as the plots: the docks on the right take the corner.
    const int room = m_window->centralWidget()->width();
    int widest = 0;
    for (const QDockWidget *panel : std::as_const(m_panels))
        widest = std::max(widest, panel->sizeHint().width());
    const int separator = m_window->style()->pixelMetric(QStyle::PM_DockWidgetSeparatorExtent);
    const int needed = m_hand->sizeHint().width() + separator + widest;
    if (!m_handTabbed && needed > room) {
        QDockWidget *front = nullptr; // the open panel in front keeps its place
        for (QDockWidget *panel : std::as_const(m_panels)) {
            if (inFront(panel))
                front = panel;
        }
        m_window->tabifyDockWidget(m_panels.first(), m_hand);
        m_handTabbed = true;
        if (front)
            front->raise();
    } else if (m_handTabbed && needed + kHysteresis <= room) {
        // Out of the tabs, beside them (splitting a tabbed dock would only add a tab).
        const bool open = isOpen(m_hand);
        m_window->removeDockWidget(m_hand);
        m_window->addDockWidget(Qt::BottomDockWidgetArea, m_hand, Qt::Horizontal);
        m_hand->setVisible(open);
        m_handTabbed = false;
    }
}

void BottomDocks::open(QDockWidget *panel)
{
    panel->show();
    panel->raise();
    if (panel->isFloating() || m_window->dockWidgetArea(panel) != Qt::BottomDockWidgetArea)
        return;
    const bool handBeside = isOpen(m_hand) && !m_handTabbed;
    if (handBeside) {
        const int room = m_window->centralWidget()->width();
        const int hand = m_hand->sizeHint().width();
        m_window->resizeDocks({m_hand, panel}, {hand, room - hand}, Qt::Horizontal);
    }
    // Tall enough for its controls: its preferred height and its tab bar's. The area's height
    // now is the other open docks' (the panel itself is laid out later).
    int height = 0;
    for (const QDockWidget *dock : std::as_const(m_panels) + QList<QDockWidget *>{m_hand}) {
        if (dock != panel && inFront(dock))
            height = std::max(height, dock->height());
    }
    const int tabBar = panel->fontMetrics().height() + 12;
    const int wanted = std::min(panel->sizeHint().height() + tabBar,
                                static_cast<int>(m_window->height() * kMaxHeightShare));
    if (height < wanted) {
        if (isOpen(m_hand) && m_handHeight <= 0)
            m_handHeight = m_hand->height();
        m_window->resizeDocks({panel}, {wanted}, Qt::Vertical);
    }
}

} // namespace hatpic
