#include "connection/linkbanner.h"

#include "session/sessionwording.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QStringBuilder>
#include <QToolButton>
#include <QVBoxLayout>

namespace hatpic {

LinkBanner::LinkBanner(QWidget *parent) : QFrame(parent)
{
    setObjectName(QStringLiteral("linkBanner"));
    m_label = new QLabel(this);
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details = new QLabel(this);
    m_details->setObjectName(QStringLiteral("linkBannerDetails"));
    m_details->setWordWrap(true);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details->hide();
    m_detailsButton = new QToolButton(this);
    m_detailsButton->setObjectName(QStringLiteral("linkBannerDetailsButton"));
    m_detailsButton->setText(tr("Details"));
    m_detailsButton->setCheckable(true);
    m_detailsButton->setAutoRaise(true);
    m_detailsButton->setToolTip(tr("Show what the system reported"));
    connect(m_detailsButton, &QToolButton::toggled, m_details, &QWidget::setVisible);
    auto *close = new QToolButton(this);
    close->setText(QStringLiteral("✕"));
    close->setAutoRaise(true);
    close->setToolTip(tr("Hide this message"));
    connect(close, &QToolButton::clicked, this, &QWidget::hide);
    auto *texts = new QVBoxLayout;
    texts->addWidget(m_label);
    texts->addWidget(m_details);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 6, 6);
    layout->addLayout(texts, 1);
    layout->addWidget(m_detailsButton, 0, Qt::AlignTop);
    layout->addWidget(close, 0, Qt::AlignTop);
    hide();
}

void LinkBanner::show(const QString &text, const QString &details, const char *background)
{
    m_label->setText(text);
    m_details->setText(details);
    m_details->setVisible(!details.isEmpty() && m_detailsButton->isChecked());
    m_detailsButton->setVisible(!details.isEmpty());
    m_label->setToolTip(details);
    setStyleSheet(
        QStringLiteral("#linkBanner { background: %1; border-radius: 4px; }"
                       "#linkBanner QLabel { color: white; background: %1; font-weight: bold; }"
                       "#linkBanner #linkBannerDetails { font-weight: normal; }")
            .arg(QLatin1String(background)));
    setVisible(true);
}

namespace {

QString lostSentence(const StateDetail &d, const QString &where)
{
    if (d.is<state::Silent>())
        return LinkBanner::tr("The device on %1 stopped sending data.").arg(where);
    if (d.is<state::LinkFailed>())
        return LinkBanner::tr("The connection to %1 was cut: the cable may have come loose, or "
                              "the device was reset or switched off.")
            .arg(where);
    return LinkBanner::tr("The connection to %1 was lost.").arg(where);
}

} // namespace

void LinkBanner::setState(SessionState state, const StateDetail &detail, const QString &port,
                          bool simulated)
{
    const QString where = port.isEmpty() ? tr("the device") : port;
    // The session's full account (with the system's text, when there is one) is the details.
    const QString details = SessionWording::stateDetail(detail);
    switch (state) {
    case SessionState::Lost:
        show(lostSentence(detail, where) %
                 tr(" Reconnecting as soon as the port returns; the plots keep the data received "
                    "so far."),
             details, "#c62828");
        break;
    case SessionState::Disconnected:
        if (detail.is<state::None>())
            show(startHint(port, simulated), QString(), "#1565c0"); // how to start, not an alarm
        else if (detail.is<state::OpenFailed>())
            show(tr("Could not open %1: it may be missing, in use by another program, or not "
                    "open to your user.")
                     .arg(where),
                 details, "#ef6c00");
        else
            show(tr("Not connected to %1: %2").arg(where, details), QString(), "#ef6c00");
        break;
    case SessionState::Connected:
        hide();
        break;
    case SessionState::Opening:
    case SessionState::Detecting:
        break; // keep a "lost" banner up while reconnecting
    }
}
QString LinkBanner::startHint(const QString &port, bool simulated)
{
    // Issue 27: the window opened disconnected with nothing saying how to begin.
    if (port.isEmpty() || simulated)
        return tr("Not connected. Press Connect (Ctrl+K) to try the simulated knob.");
    return tr("Not connected. Press Connect (Ctrl+K) to open %1, or choose the simulated "
              "joystick in the port list to try the simulated knob.")
        .arg(port);
}

QString LinkBanner::text() const
{
    return isVisibleTo(parentWidget()) ? m_label->text() : QString();
}

QString LinkBanner::detailsText() const
{
    return m_details->text();
}

} // namespace hatpic
