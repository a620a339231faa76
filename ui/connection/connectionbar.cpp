#include "connection/connectionbar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QTimer>

namespace hatpic {

ConnectionBar::ConnectionBar(QWidget *parent) : QWidget(parent)
{
    m_port = new QComboBox(this);
    m_port->setObjectName(QStringLiteral("port"));
    m_port->setEditable(true); // hatpic-sim's pseudo-terminals are not listed by the system
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumContentsLength(18);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_port->setToolTip(tr("Serial port of the joystick, or the built-in simulated HATPIC.\n"
                          "A path such as /dev/pts/3 can be typed."));

    m_baud = new QComboBox(this);
    m_baud->setObjectName(QStringLiteral("baud"));
    m_baud->setEditable(true);
    m_baud->setInsertPolicy(QComboBox::NoInsert);
    m_baud->addItem(tr("default"), 0);
    for (int rate : {921600, 1000000, 460800, 230400, 115200})
        m_baud->addItem(QString::number(rate), rate);
    m_baud->setToolTip(tr("Baud rate; default is 921600 for v2 and 115200 for legacy. Auto listens "
                          "for the published firmware at 115200, then asks for v2 at 921600."));

    m_protocol = new QComboBox(this);
    m_protocol->setObjectName(QStringLiteral("protocol"));
    m_protocol->addItem(tr("auto"), int(ProtocolChoice::Auto));
    m_protocol->addItem(tr("v2"), int(ProtocolChoice::V2));
    m_protocol->addItem(tr("legacy"), int(ProtocolChoice::Legacy));
    m_protocol->setToolTip(tr("auto listens for legacy frames first, then asks for v2."));

    m_button = new QPushButton(tr("Connect"), this);
    m_button->setObjectName(QStringLiteral("connect"));
    m_button->setDefault(true);
    connect(m_button, &QPushButton::clicked, this, &ConnectionBar::toggleConnection);

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    auto *portLabel = new QLabel(tr("&Port"), this);
    portLabel->setBuddy(m_port);
    auto *baudLabel = new QLabel(tr("&Baud"), this);
    baudLabel->setBuddy(m_baud);
    auto *protocolLabel = new QLabel(tr("P&rotocol"), this);
    protocolLabel->setBuddy(m_protocol);
    layout->addWidget(portLabel);
    layout->addWidget(m_port);
    layout->addWidget(baudLabel);
    layout->addWidget(m_baud);
    layout->addWidget(protocolLabel);
    layout->addWidget(m_protocol);
    layout->addWidget(m_button);

    refreshPorts();
    m_refresh = new QTimer(this);
    m_refresh->setInterval(kRefreshMs);
    connect(m_refresh, &QTimer::timeout, this, &ConnectionBar::refreshPorts);
    m_refresh->start();
}

void ConnectionBar::addSource(const QString &label, const QString &name, LinkSourcePtr source)
{
    const int at = int(m_sources.size());
    const bool first = at == 0;
    m_sources.emplace_back(name, std::move(source));
    const QSignalBlocker blocker(m_port);
    m_port->insertItem(at, label, name);
    if (first)
        m_port->setCurrentIndex(0); // the first source is the default choice
}

LinkSourcePtr ConnectionBar::sourceNamed(const QString &name) const
{
    for (const auto &[sourceName, source] : m_sources) {
        if (sourceName == name)
            return source;
    }
    return nullptr;
}

void ConnectionBar::refreshPorts()
{
    QStringList found;
    const QList<QSerialPortInfo> infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : infos)
        found << info.systemLocation();
    found.sort();

    // Keep the current choice (also a typed path) and the sources; swap the rest.
    const QString current = port();
    const QString typed = m_port->currentText();
    const int fixed = int(m_sources.size());
    QStringList listed;
    for (int i = fixed; i < m_port->count(); ++i)
        listed << m_port->itemData(i).toString();
    QStringList wanted = found;
    if (!sourceNamed(current) && !current.isEmpty() && !wanted.contains(current))
        wanted.prepend(current);
    if (listed == wanted)
        return;

    const QSignalBlocker blocker(m_port);
    while (m_port->count() > fixed)
        m_port->removeItem(fixed);
    for (const QString &path : std::as_const(wanted)) {
        QString label = path;
        for (const QSerialPortInfo &info : infos) {
            if (info.systemLocation() == path && !info.description().isEmpty())
                label = path % u"  (" % info.description() % u')';
        }
        m_port->addItem(label, path);
    }
    const int index = m_port->findData(current);
    if (index >= 0)
        m_port->setCurrentIndex(index);
    else
        m_port->setEditText(typed);
}

QStringList ConnectionBar::listedPorts() const
{
    QStringList ports;
    for (int i = 0; i < m_port->count(); ++i)
        ports << m_port->itemData(i).toString();
    return ports;
}

QString ConnectionBar::port() const
{
    const QString text = m_port->currentText().trimmed();
    const int index = m_port->currentIndex();
    if (index >= 0 && m_port->itemText(index) == text)
        return m_port->itemData(index).toString();
    // A typed path, or a source's typed name.
    return text;
}

qint32 ConnectionBar::baud() const
{
    const int index = m_baud->currentIndex();
    const QString text = m_baud->currentText().trimmed();
    if (index >= 0 && m_baud->itemText(index) == text)
        return m_baud->itemData(index).toInt();
    bool ok = false;
    const int value = text.toInt(&ok);
    return ok && value > 0 ? value : 0;
}

ProtocolChoice ConnectionBar::protocol() const
{
    return static_cast<ProtocolChoice>(m_protocol->currentData().toInt());
}

ConnectOptions ConnectionBar::options() const
{
    ConnectOptions options;
    options.port = port();
    options.baud = baud();
    options.protocol = protocol();
    options.link = sourceNamed(options.port);
    return options;
}

void ConnectionBar::setOptions(const QString &port, qint32 baud, ProtocolChoice protocol)
{
    if (!port.isEmpty()) {
        int index = m_port->findData(port);
        if (index < 0) {
            m_port->addItem(port, port);
            index = m_port->count() - 1;
        }
        m_port->setCurrentIndex(index);
    }
    int baudIndex = m_baud->findData(baud);
    if (baudIndex < 0) {
        m_baud->addItem(QString::number(baud), baud);
        baudIndex = m_baud->count() - 1;
    }
    m_baud->setCurrentIndex(baudIndex);
    m_protocol->setCurrentIndex(m_protocol->findData(int(protocol)));
}

void ConnectionBar::setState(SessionState state)
{
    m_state = state;
    const bool idle = state == SessionState::Disconnected;
    m_button->setText(idle ? tr("Connect") : tr("Disconnect"));
    m_port->setEnabled(idle);
    m_baud->setEnabled(idle);
    m_protocol->setEnabled(idle);
    // The list is locked while a session runs: reading every tty in /sys each 1.5 s then was
    // a few percent of the tuner's CPU for nothing.
    if (idle && !m_refresh->isActive()) {
        refreshPorts();
        m_refresh->start();
    } else if (!idle) {
        m_refresh->stop();
    }
}

void ConnectionBar::toggleConnection()
{
    if (m_state == SessionState::Disconnected)
        Q_EMIT connectRequested(options());
    else
        Q_EMIT disconnectRequested();
}

} // namespace hatpic
