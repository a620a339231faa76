#include "seriallink.h"

namespace hatpic {

SerialLink::SerialLink(const QString &portName, qint32 baud, QObject *parent)
    : ByteLink(parent), m_port(this), m_baud(baud)
{
    m_port.setPortName(portName);
    connect(&m_port, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = m_port.readAll();
        if (!bytes.isEmpty())
            Q_EMIT bytesReceived(bytes);
    });
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialLink::onError);
}

SerialLink::~SerialLink()
{
    close();
}

bool SerialLink::open()
{
    m_error.clear();
    if (m_port.isOpen())
        return true;
    if (!m_port.open(QIODevice::ReadWrite)) {
        m_error = m_port.errorString();
        return false;
    }
    // Settings after open(): on Linux they are applied to the open descriptor.
    const bool ok = m_port.setBaudRate(m_baud) && m_port.setDataBits(QSerialPort::Data8) &&
                    m_port.setParity(QSerialPort::NoParity) &&
                    m_port.setStopBits(QSerialPort::OneStop) &&
                    m_port.setFlowControl(QSerialPort::NoFlowControl);
    if (!ok) {
        m_error = m_port.errorString();
        m_port.close();
        return false;
    }
    return true;
}

bool SerialLink::setBaud(qint32 baud)
{
    m_baud = baud;
    if (!m_port.isOpen() || m_port.setBaudRate(baud))
        return true;
    m_error = m_port.errorString();
    return false;
}

void SerialLink::close()
{
    if (m_port.isOpen())
        m_port.close();
}

bool SerialLink::isOpen() const
{
    return m_port.isOpen();
}

void SerialLink::write(const QByteArray &bytes)
{
    if (!m_port.isOpen())
        return;
    if (m_port.bytesToWrite() + bytes.size() > kMaxPendingWriteBytes) {
        ++m_droppedWrites;
        return;
    }
    m_port.write(bytes);
}

QString SerialLink::errorString() const
{
    return m_error;
}

void SerialLink::onError(QSerialPort::SerialPortError error)
{
    // A vanished device shows as ResourceError (USB unplugged) or, for a pseudo-terminal whose
    // master side closed, as a ReadError that QSerialPort repeats in a tight loop until the
    // port is closed (measured on Linux, Qt 6.4). Both close the port at once.
    QString what;
    switch (error) {
    case QSerialPort::ResourceError:
        what = QStringLiteral("the port vanished");
        break;
    case QSerialPort::ReadError:
        what = QStringLiteral("reading from the port failed; the device (or the program behind "
                              "the pseudo-terminal) is gone");
        break;
    case QSerialPort::WriteError:
        what = QStringLiteral("writing to the port failed");
        break;
    default:
        return;
    }
    if (!m_port.isOpen())
        return;
    m_error = what % u" (system: " % m_port.errorString() % u')';
    m_port.close();
    Q_EMIT failed(m_error);
}

} // namespace hatpic
