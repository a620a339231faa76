// ByteLink over a QSerialPort: 8N1, no flow control, fully asynchronous (no waitFor*).
#pragma once

#include "device/bytelink.h"

#include <QSerialPort>

namespace hatpic {

class SerialLink : public ByteLink
{
    Q_OBJECT
public:
    SerialLink(const QString &portName, qint32 baud, QObject *parent = nullptr);
    ~SerialLink() override;

    bool open() override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray &bytes) override;
    QString errorString() const override;
    qint32 baud() const override { return m_baud; }
    bool setBaud(qint32 baud) override;

private:
    void onError(QSerialPort::SerialPortError error);

    QSerialPort m_port;
    qint32 m_baud;
    QString m_error;
};

} // namespace hatpic
