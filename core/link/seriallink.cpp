#include "seriallink.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QStandardPaths>
#include <QStringBuilder>

#include <cerrno>

namespace hatpic {

namespace {

//! The system's text for `code`, as QSerialPort words it (qt_error_string).
bool systemTextIs(const QString &text, std::initializer_list<int> codes)
{
    for (const int code : codes) {
        if (text == qt_error_string(code))
            return true;
    }
    return false;
}

//! The lock file QSerialPort (Qt 6, Unix) takes for the port at `path`: "LCK.." and the name
//! without /dev/, '/' as '_', in the first of these folders where it exists.
QString existingLockFile(const QString &path)
{
    QString name = path.startsWith(u"/dev/") ? path.mid(5) : path;
    name.replace(u'/', u'_');
    const QStringList folders{QStringLiteral("/var/lock"),
                              QStringLiteral("/etc/locks"),
                              QStringLiteral("/var/spool/locks"),
                              QStringLiteral("/var/spool/uucp"),
                              QStringLiteral("/tmp"),
                              QStandardPaths::writableLocation(QStandardPaths::TempLocation)};
    for (const QString &folder : folders) {
        const QString file = folder % u"/LCK.." % name;
        if (QFileInfo::exists(file))
            return file;
    }
    return {};
}

} // namespace

QString SerialLink::resolvedPath(const QString &portName)
{
    // QSerialPort would put a relative path with a '/' ("rel/k") under /dev; it is a path.
    const QString path =
        portName.contains(u'/') ? QFileInfo(portName).absoluteFilePath() : u"/dev/" % portName;
    const QString canonical = QFileInfo(path).canonicalFilePath();
    return canonical.isEmpty() ? path : canonical;
}

QString SerialLink::lockHolder(const QString &path)
{
    const QString file = existingLockFile(path);
    if (file.isEmpty())
        return {};
    qint64 pid = 0;
    QString host;
    QString application;
    if (!QLockFile(file).getLockInfo(&pid, &host, &application) || pid <= 0)
        return {};
    // The running process's own name, else the one the lock file recorded.
    QFile comm(u"/proc/" % QString::number(pid) % u"/comm");
    QString process = comm.open(QIODevice::ReadOnly)
                          ? QString::fromLocal8Bit(comm.readAll()).trimmed()
                          : QString();
    if (process.isEmpty())
        process = application;
    const QString id = u"PID " % QString::number(pid);
    return process.isEmpty() ? id : QString(process % u", " % id);
}

SerialLink::SerialLink(const QString &portName, qint32 baud, QObject *parent)
    : ByteLink(parent), m_port(this), m_portName(portName), m_baud(baud)
{
    connect(&m_port, &QSerialPort::readyRead, this, &SerialLink::forwardReceived);
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialLink::onError);
}

SerialLink::~SerialLink()
{
    close();
}

void SerialLink::forwardReceived()
{
    const QByteArray bytes = m_port.readAll();
    if (!bytes.isEmpty())
        Q_EMIT bytesReceived(bytes);
}

bool SerialLink::open()
{
    m_error.clear();
    if (m_port.isOpen())
        return true;
    // Resolved at each open: a reconnect follows a symlink that now points elsewhere.
    const QString path = resolvedPath(m_portName);
    m_port.setPortName(path);
    if (!m_port.open(QIODevice::ReadWrite)) {
        m_error = m_port.errorString();
        // QSerialPort says "Permission error while locking the device" when another program
        // holds the port's lock file: say that, and who it is.
        if (m_port.error() == QSerialPort::PermissionError && !existingLockFile(path).isEmpty()) {
            const QString holder = lockHolder(path);
            const QString named =
                path == m_portName ? path : QString(m_portName % u" (" % path % u')');
            m_error = named % u" is in use by another program" %
                      (holder.isEmpty() ? QString() : QString(u" (" % holder % u')'));
        }
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
    // EAGAIN (QSerialPort maps it to ResourceError) is back-pressure: the terminal's buffer
    // is full (the device reads slowly, or another process floods it). QSerialPort keeps the
    // unsent bytes and retries when the port is writable again; reading resumes on the next
    // read. Nothing is lost, so the port stays open. (EINTR is retried inside Qt.)
    if ((error == QSerialPort::ResourceError || error == QSerialPort::WriteError ||
         error == QSerialPort::ReadError) &&
        systemTextIs(m_port.errorString(), {EAGAIN, EWOULDBLOCK, EINTR})) {
        ++m_backPressure;
        m_port.clearError();
        if (error != QSerialPort::WriteError && m_port.isOpen())
            forwardReceived(); // a read re-enables the notifier QSerialPort turned off
        return;
    }
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
    // The system's text only when it names a loss: a read that found the end of the file
    // leaves a stale errno ("Unknown error", "File exists"), which says nothing.
    const QString system = m_port.errorString();
    m_error = systemTextIs(system, {EIO, ENXIO, ENODEV, ENOENT, EBADF, EPIPE})
                  ? QString(what % u" (system: " % system % u')')
                  : what;
    m_port.close();
    Q_EMIT failed(m_error);
}

} // namespace hatpic
