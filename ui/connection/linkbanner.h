// A plain-language banner above the plots when the link is lost (red, while the session tries
// to reconnect) or when connecting failed (amber, with the reason). Hidden otherwise. It says
// what happened in the user's words; the system's own text (e.g. "Inappropriate ioctl for
// device") stays in the details, behind a "Details" button and in the tooltip.
#pragma once

#include "session/sessiontypes.h"

#include <QFrame>

class QLabel;
class QToolButton;

namespace hatpic {

class LinkBanner : public QFrame
{
    Q_OBJECT
public:
    explicit LinkBanner(QWidget *parent = nullptr);

    //! `port` names the port in the message; `detail` is the session's structured reason;
    //! `simulated`: the port is a simulated joystick's (ConnectOptions::link's simulated()).
    void setState(SessionState state, const StateDetail &detail, const QString &port,
                  bool simulated = false);
    QString text() const; //!< the sentence shown
    //! While disconnected: how to start, on `port` (a simulated one: try it).
    static QString startHint(const QString &port, bool simulated);
    QString detailsText() const; //!< the system's and the session's own text; may be empty

private:
    void show(const QString &text, const QString &details, const char *background);

    QLabel *m_label = nullptr;
    QLabel *m_details = nullptr;
    QToolButton *m_detailsButton = nullptr;
};

} // namespace hatpic
