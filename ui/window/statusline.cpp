#include "window/statusline.h"

#include <QHBoxLayout>
#include <QSizeGrip>
#include <QStatusBar>

#include <algorithm>

namespace hatpic {

namespace {

//! Room QStatusBar leaves around a message: 6 px before it, 12 after (qstatusbar.cpp).
constexpr int kMessageMargins = 18;

} // namespace

StatusLine::StatusLine(QStatusBar *bar) : QObject(bar), m_bar(bar), m_readouts(new QWidget(bar))
{
    m_readouts->setObjectName(QStringLiteral("statusReadouts"));
    auto *layout = new QHBoxLayout(m_readouts);
    layout->setContentsMargins(0, 0, 0, 0);
    bar->addPermanentWidget(m_readouts);
    connect(bar, &QStatusBar::messageChanged, this, [this](const QString &text) {
        if (!text.isEmpty())
            return;
        m_message.clear(); // the message ended: the readouts are back
        m_readouts->show();
        m_bar->setToolTip({});
    });
}

int StatusLine::durationMs(const QString &message)
{
    return std::max<int>(kMinMs, static_cast<int>(message.size()) * kMsPerChar);
}

void StatusLine::show(const QString &message)
{
    const QFontMetrics metrics = m_bar->fontMetrics();
    int whole = m_bar->width() - kMessageMargins;
    if (const auto *grip = m_bar->findChild<QSizeGrip *>(); grip && grip->isVisible())
        whole = std::min(whole, grip->x() - kMessageMargins / 3);
    const int beside = whole - m_readouts->sizeHint().width();
    const int needed = metrics.horizontalAdvance(message);
    m_readouts->setVisible(needed <= beside);
    const QString shown = metrics.elidedText(message, Qt::ElideRight, whole);
    m_bar->setToolTip(shown == message ? QString() : message);
    m_message = message;
    m_bar->showMessage(shown, durationMs(message));
}

} // namespace hatpic
