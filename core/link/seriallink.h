// ByteLink over a QSerialPort: 8N1, no flow control, fully asynchronous (no waitFor*).
#pragma once

#include "link/bytelink.h"

#include <QSerialPort>

namespace hatpic {

class SerialLink : public ByteLink
{
    Q_OBJECT
public:
    //! Bytes QSerialPort may hold unsent; a write beyond that is dropped whole, so a port
    //! that stops draining never makes memory grow (feedback is a stream, commands retry).
    static constexpr qint64 kMaxPendingWriteBytes = 16 * 1024;

    SerialLink(const QString &portName, qint32 baud, QObject *parent = nullptr);
    ~SerialLink() override;

    bool open() override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray &bytes) override;
    QString errorString() const override;
    qint32 baud() const override { return m_baud; }
    bool setBaud(qint32 baud) override;

    qint64 bytesToWrite() const { return m_port.bytesToWrite(); } //!< not yet sent [B]
    quint64 droppedWrites() const { return m_droppedWrites; }     //!< writes refused when full

private:
    void onError(QSerialPort::SerialPortError error);

    QSerialPort m_port;
    qint32 m_baud;
    QString m_error;
    quint64 m_droppedWrites = 0;
};

} // namespace hatpic
