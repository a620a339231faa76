// ByteLink over a QSerialPort: 8N1, no flow control, fully asynchronous (no waitFor*).
//
// The port is opened by its resolved path (symlinks followed), so every name of one device
// takes the same lock file: a /dev/pts/N alias of a port in use is refused as in use. A name
// with a '/' is a path (relative to the working directory); only a bare name ("ttyUSB0") is
// looked up under /dev.
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
    //! Times the port said "try again" (EAGAIN: its buffer full, e.g. another process floods
    //! the terminal): back-pressure, which QSerialPort retries on its own, never a lost port.
    quint64 backPressureEvents() const { return m_backPressure; }

    //! The file a port name opens: a name with a '/' is a path (relative to the working
    //! directory), a bare name is under /dev; symlinks resolved when the file exists.
    static QString resolvedPath(const QString &portName);
    //! Who holds the lock of the port at `path` ("hatpicctl, PID 1234"), empty when unknown.
    static QString lockHolder(const QString &path);

private:
    void forwardReceived();
    void onError(QSerialPort::SerialPortError error);

    QSerialPort m_port;
    QString m_portName; //!< as given
    qint32 m_baud;
    QString m_error;
    quint64 m_droppedWrites = 0;
    quint64 m_backPressure = 0;
};

} // namespace hatpic
