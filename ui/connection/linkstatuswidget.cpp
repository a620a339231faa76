#include "connection/linkstatuswidget.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>

namespace hatpic {

namespace {

struct StateLook
{
    QString text;
    const char *background;
};

StateLook look(SessionState state)
{
    switch (state) {
    case SessionState::Disconnected:
        return {LinkStatusWidget::tr("disconnected"), "#616161"};
    case SessionState::Opening:
        return {LinkStatusWidget::tr("opening…"), "#b26a00"};
    case SessionState::Detecting:
        return {LinkStatusWidget::tr("detecting…"), "#b26a00"};
    case SessionState::Connected:
        return {LinkStatusWidget::tr("connected"), "#2e7d32"};
    case SessionState::Lost:
        return {LinkStatusWidget::tr("LINK LOST"), "#c62828"};
    }
    return {};
}

} // namespace

LinkStatusWidget::LinkStatusWidget(QWidget *parent) : QWidget(parent)
{
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("linkState"));
    m_state->setAlignment(Qt::AlignCenter);
    m_state->setMinimumWidth(m_state->fontMetrics().horizontalAdvance(QStringLiteral("LINK LOST")) +
                             24);
    m_identity = new QLabel(this);
    m_identity->setObjectName(QStringLiteral("deviceIdentity"));
    m_identity->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The identity takes the room left and is elided in a narrow window, so that the state tag
    // (LINK LOST) never slides into the toolbar's overflow menu.
    m_identity->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_identity->installEventFilter(this);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    layout->addWidget(m_state);
    layout->addWidget(m_identity, 1);
    setState(SessionState::Disconnected);
    setDeviceInfo(std::nullopt);
}

void LinkStatusWidget::setState(SessionState state)
{
    const StateLook l = look(state);
    m_state->setText(l.text);
    m_state->setStyleSheet(QStringLiteral("QLabel { color: white; font-weight: bold; "
                                          "background: %1; border-radius: 4px; padding: 2px 8px; }")
                               .arg(QLatin1String(l.background)));
}

QString LinkStatusWidget::describe(const DeviceInfo &info)
{
    QStringList parts;
    if (info.simulated)
        parts << tr("Simulated HATPIC");
    parts << (info.protocol == WireProtocol::V2 ? tr("protocol v%1").arg(info.protocolVersion)
                                                : tr("legacy protocol"));
    if (!info.firmware.isEmpty())
        parts << tr("firmware %1").arg(info.firmware);
    if (info.deviceId != 0)
        parts << tr("id 0x%1").arg(
            QString::number(info.deviceId, 16).toUpper().rightJustified(8, u'0'));
    if (!info.simulated && !info.port.isEmpty())
        parts << (info.baud > 0 ? tr("%1 @ %2").arg(info.port).arg(info.baud) : info.port);
    if (info.protocol == WireProtocol::V2)
        parts << tr("τ limit %1 N·m").arg(info.tauLimit, 0, 'g', 3);
    else // the published firmware does not report it: the host assumes it
        parts << tr("τ limit %1 N·m (assumed)").arg(info.tauLimit, 0, 'g', 3);
    return parts.join(QStringLiteral(" · "));
}

void LinkStatusWidget::setDeviceInfo(const std::optional<DeviceInfo> &info)
{
    m_identityText = info ? describe(*info) : tr("no device");
    m_identity->setToolTip(m_identityText);
    elideIdentity();
}

void LinkStatusWidget::elideIdentity()
{
    m_identity->setText(m_identity->fontMetrics().elidedText(m_identityText, Qt::ElideRight,
                                                             m_identity->contentsRect().width()));
}

bool LinkStatusWidget::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_identity && event->type() == QEvent::Resize)
        elideIdentity();
    return QWidget::eventFilter(watched, event);
}

QString LinkStatusWidget::stateText() const
{
    return m_state->text();
}

QString LinkStatusWidget::identityText() const
{
    return m_identityText;
}

} // namespace hatpic
