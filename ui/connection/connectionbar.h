// The row that opens a device: port chooser (the link sources the window adds — the simulated
// joystick — first, then the serial ports, refreshed as devices come and go; a pty path can be
// typed), baud, protocol, connect button.
#pragma once

#include "link/linksource.h"
#include "session/sessiontypes.h"

#include <QWidget>

#include <utility>
#include <vector>

class QComboBox;
class QPushButton;
class QTimer;

namespace hatpic {

class ConnectionBar : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kRefreshMs = 1500; //!< port list refresh period while disconnected [ms]

    explicit ConnectionBar(QWidget *parent = nullptr);

    //! Lists `source` before the serial ports as `label`; choosing it (or typing `name`)
    //! connects through it, with `name` as the port the session words and records.
    void addSource(const QString &label, const QString &name, LinkSourcePtr source);
    //! The source listed as `name`, else null (a serial port's path).
    LinkSourcePtr sourceNamed(const QString &name) const;

    //! The options the controls describe: a listed source's name and link, or a serial port's
    //! path and no link.
    ConnectOptions options() const;
    //! Selects port (adding it when the list does not have it), baud and protocol.
    void setOptions(const QString &port, qint32 baud, ProtocolChoice protocol);

    QString port() const;
    qint32 baud() const; //!< 0 = the protocol's default
    ProtocolChoice protocol() const;

    //! Follows the session: the button says Connect or Disconnect, the choosers lock, and the
    //! port list is refreshed only while disconnected (at once when the session ends).
    void setState(SessionState state);

    //! Re-reads the serial ports now (the timer does it every kRefreshMs while disconnected).
    void refreshPorts();
    QStringList listedPorts() const; //!< the sources' names first, then device paths

    //! What the button does: connect with options(), or disconnect.
    void toggleConnection();

    QPushButton *connectButton() const { return m_button; }
    QComboBox *portBox() const { return m_port; }

Q_SIGNALS:
    void connectRequested(const hatpic::ConnectOptions &options);
    void disconnectRequested();

private:
    QComboBox *m_port = nullptr;
    QComboBox *m_baud = nullptr;
    QComboBox *m_protocol = nullptr;
    QPushButton *m_button = nullptr;
    QTimer *m_refresh = nullptr;
    SessionState m_state = SessionState::Disconnected;
    std::vector<std::pair<QString, LinkSourcePtr>> m_sources; //!< (name, source), as listed
};

} // namespace hatpic
