// A plain-language banner above the plots when the link is lost (red, while the session tries
// to reconnect) or when connecting failed (amber, with the reason). Hidden otherwise.
#pragma once

#include "session/sessiontypes.h"

#include <QFrame>

class QLabel;

namespace hatpic {

class LinkBanner : public QFrame
{
    Q_OBJECT
public:
    explicit LinkBanner(QWidget *parent = nullptr);

    //! `port` names the port in the message; `detail` is the session's reason.
    void setState(SessionState state, const QString &detail, const QString &port);
    QString text() const;

private:
    void show(const QString &text, const char *background);

    QLabel *m_label = nullptr;
};

} // namespace hatpic
