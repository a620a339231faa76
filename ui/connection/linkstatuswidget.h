// Always-visible link state: a coloured state tag and the device's identity (protocol,
// firmware, id, port and baud).
#pragma once

#include "session/sessiontypes.h"

#include <QWidget>

#include <optional>

class QLabel;

namespace hatpic {

class LinkStatusWidget : public QWidget
{
    Q_OBJECT
public:
    explicit LinkStatusWidget(QWidget *parent = nullptr);

    void setState(SessionState state);
    void setDeviceInfo(const std::optional<DeviceInfo> &info);

    QString stateText() const;    //!< "connected", "link lost", …
    QString identityText() const; //!< "v2 · firmware … · id 0x53494D31 · sim"

    //! One line describing a device, as the title bar tag and the status show it.
    static QString describe(const DeviceInfo &info);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void elideIdentity();

    QLabel *m_state = nullptr;
    QLabel *m_identity = nullptr;
    QString m_identityText; //!< in full; the label may show it elided
};

} // namespace hatpic
