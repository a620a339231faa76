#include "connection/linkbanner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace hatpic {

LinkBanner::LinkBanner(QWidget *parent) : QFrame(parent)
{
    setObjectName(QStringLiteral("linkBanner"));
    m_label = new QLabel(this);
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *close = new QToolButton(this);
    close->setText(QStringLiteral("✕"));
    close->setAutoRaise(true);
    close->setToolTip(tr("Hide this message"));
    connect(close, &QToolButton::clicked, this, &QWidget::hide);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 6, 6);
    layout->addWidget(m_label, 1);
    layout->addWidget(close, 0, Qt::AlignTop);
    hide();
}

void LinkBanner::show(const QString &text, const char *background)
{
    m_label->setText(text);
    setStyleSheet(QStringLiteral("#linkBanner { background: %1; border-radius: 4px; }"
                                 "#linkBanner QLabel { color: white; font-weight: bold; }")
                      .arg(QLatin1String(background)));
    setVisible(true);
}

void LinkBanner::setState(SessionState state, const QString &detail, const QString &port)
{
    const QString where = port.isEmpty() ? tr("the device") : port;
    switch (state) {
    case SessionState::Lost:
        show(tr("Link lost on %1%2. Reconnecting as soon as the port returns; the plots keep "
                "the data received so far.")
                 .arg(where, detail.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(detail)),
             "#c62828");
        break;
    case SessionState::Disconnected:
        if (detail.isEmpty())
            hide();
        else
            show(tr("Not connected to %1: %2").arg(where, detail), "#ef6c00");
        break;
    case SessionState::Connected:
        hide();
        break;
    case SessionState::Opening:
    case SessionState::Detecting:
        break; // keep a "lost" banner up while reconnecting
    }
}

QString LinkBanner::text() const
{
    return isVisibleTo(parentWidget()) ? m_label->text() : QString();
}

} // namespace hatpic
