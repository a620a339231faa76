#include "roscore.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QThread>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <limits>

using namespace Qt::StringLiterals;

namespace hatpic::test {

namespace {

sockaddr_in loopback(int port)
{
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(quint16(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return address;
}

// A port nothing listens on now (the kernel's pick for port 0).
int freePort()
{
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in address = loopback(0);
    socklen_t length = sizeof address;
    ::bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address);
    ::getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length);
    ::close(fd);
    return ntohs(address.sin_port);
}

bool groupAlive(qint64 pid)
{
    return ::kill(-pid_t(pid), 0) == 0 || errno != ESRCH;
}

} // namespace

RosCore::RosCore(ThisProcess thisProcess) : m_port(freePort())
{
    if (thisProcess == ThisProcess::Exported)
        exportEnvironment();
}

RosCore::~RosCore()
{
    stop();
}

QString RosCore::uri() const
{
    return u"http://127.0.0.1:"_s + QString::number(m_port);
}

QProcessEnvironment RosCore::environment(QProcessEnvironment base) const
{
    base.insert(u"ROS_MASTER_URI"_s, uri());
    base.insert(u"ROS_IP"_s, u"127.0.0.1"_s);
    base.insert(u"ROS_HOME"_s, m_home.path());
    base.insert(u"ROS_LOG_DIR"_s, m_home.filePath(u"log"_s));
    base.remove(u"ROS_HOSTNAME"_s);
    base.remove(u"ROS_NAMESPACE"_s);
    return base;
}

void RosCore::exportEnvironment() const
{
    const QProcessEnvironment env = environment(QProcessEnvironment());
    for (const QString &key : env.keys())
        qputenv(key.toLocal8Bit().constData(), env.value(key).toLocal8Bit());
    qunsetenv("ROS_HOSTNAME");
    qunsetenv("ROS_NAMESPACE");
}

QString RosCore::start(int timeoutMs)
{
    if (isRunning())
        return {};
    m_process = std::make_unique<QProcess>();
    m_process->setProcessEnvironment(environment());
    m_process->setProcessChannelMode(QProcess::MergedChannels);
    m_process->setStandardOutputFile(m_home.filePath(u"roscore.out"_s), QIODevice::Append);
    m_process->setChildProcessModifier([] { ::setpgid(0, 0); });
    m_process->start(QStringLiteral(HATPIC_ROSCORE_PATH), {u"-p"_s, QString::number(m_port)});
    if (!m_process->waitForStarted(5000))
        return u"roscore (" HATPIC_ROSCORE_PATH ") does not start: "_s + m_process->errorString() +
               u" (install ros-core; scripts/setup does)"_s;
    m_pid = m_process->processId();
    const QDeadlineTimer deadline(timeoutMs);
    while (!answers()) {
        if (m_process->state() == QProcess::NotRunning || deadline.hasExpired()) {
            stop();
            QFile log(m_home.filePath(u"roscore.out"_s));
            log.open(QIODevice::ReadOnly);
            return u"roscore did not answer at "_s + uri() + u": "_s +
                   QString::fromLocal8Bit(log.readAll().right(2000));
        }
        QThread::msleep(100);
    }
    return {};
}

void RosCore::stop()
{
    if (m_pid <= 0)
        return;
    ::kill(-pid_t(m_pid), SIGINT);
    QDeadlineTimer deadline(10000);
    while (groupAlive(m_pid) && !deadline.hasExpired()) {
        m_process->waitForFinished(100); // reaps roscore itself
    }
    if (groupAlive(m_pid))
        ::kill(-pid_t(m_pid), SIGKILL);
    m_process->waitForFinished(5000);
    m_process.reset();
    m_pid = 0;
}

bool RosCore::answers() const
{
    // The master's getPid over XML-RPC, by hand: HTTP/1.0, so the reply ends with the
    // connection.
    const QByteArray body = "<?xml version=\"1.0\"?><methodCall><methodName>getPid</methodName>"
                            "<params><param><value><string>/test</string></value></param>"
                            "</params></methodCall>";
    const QByteArray request = "POST / HTTP/1.0\r\nContent-Type: text/xml\r\nContent-Length: " +
                               QByteArray::number(body.size()) + "\r\n\r\n" + body;
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const sockaddr_in address = loopback(m_port);
    QByteArray reply;
    if (::connect(fd, reinterpret_cast<const sockaddr *>(&address), sizeof address) == 0 &&
        ::send(fd, request.constData(), size_t(request.size()), MSG_NOSIGNAL) == request.size()) {
        const QDeadlineTimer deadline(2000);
        pollfd p{fd, POLLIN, 0};
        char buffer[4096];
        while (!deadline.hasExpired() && ::poll(&p, 1, 100) >= 0) {
            if (!(p.revents & (POLLIN | POLLHUP)))
                continue;
            const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
            if (n <= 0)
                break;
            reply.append(buffer, n);
        }
    }
    ::close(fd);
    return reply.contains("<int>1</int>");
}

QStringList RosCore::registrations(const QString &node, QString *error) const
{
    // Python's XML-RPC client, as rosnode uses it.
    static const QString script = uR"(
import sys, xmlrpc.client
code, text, state = xmlrpc.client.ServerProxy(sys.argv[1]).getSystemState('/hatpic_test')
if code != 1:
    sys.exit(text)
for kind, entries in zip(('publishes', 'subscribes', 'provides'), state):
    for name, nodes in entries:
        if sys.argv[2] in nodes:
            print(kind, name)
)"_s;
    QProcess python;
    python.start(u"python3"_s, {u"-c"_s, script, uri(), node});
    QStringList lines;
    if (!python.waitForFinished(10000) || python.exitStatus() != QProcess::NormalExit ||
        python.exitCode() != 0) {
        if (error)
            *error = u"getSystemState failed: "_s +
                     QString::fromLocal8Bit(python.readAllStandardError()).trimmed();
        return lines;
    }
    lines = QString::fromUtf8(python.readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
    lines.sort();
    return lines;
}

Ros1Peer::~Ros1Peer()
{
    stop();
}

QString Ros1Peer::start(const QProcessEnvironment &environment, const QStringList &arguments,
                        int timeoutMs)
{
    stop();
    m_process = std::make_unique<QProcess>();
    m_process->setProcessEnvironment(environment);
    connect(m_process.get(), &QProcess::readyReadStandardOutput, this, &Ros1Peer::read);
    connect(m_process.get(), &QProcess::readyReadStandardError, this,
            [this] { m_stderr += m_process->readAllStandardError(); });
    m_process->start(QStringLiteral(HATPIC_ROS1_PEER), arguments);
    if (!m_process->waitForStarted(5000))
        return u"ros1peer.py does not start: "_s + m_process->errorString();
    const QDeadlineTimer deadline(timeoutMs);
    while (m_uri.isEmpty()) {
        if (m_process->state() == QProcess::NotRunning || deadline.hasExpired())
            return u"ros1peer.py is not ready: "_s + QString::fromLocal8Bit(m_stderr.right(2000));
        m_process->waitForReadyRead(100);
    }
    return {};
}

void Ros1Peer::stop()
{
    if (!m_process)
        return;
    if (m_process->state() != QProcess::NotRunning) {
        m_process->write("quit\n");
        m_process->closeWriteChannel();
        if (!m_process->waitForFinished(5000)) {
            m_process->kill();
            m_process->waitForFinished(2000);
        }
    }
    m_process.reset();
    m_uri.clear();
}

void Ros1Peer::send(const QString &line)
{
    if (!m_process)
        return;
    m_process->write(line.toUtf8() + '\n');
    m_process->waitForBytesWritten(1000); // a caller may wait without an event loop
}

void Ros1Peer::read()
{
    m_partial += m_process->readAllStandardOutput();
    for (qsizetype end; (end = m_partial.indexOf('\n')) >= 0;) {
        const QByteArray line = m_partial.left(end);
        m_partial.remove(0, end + 1);
        const QJsonObject object = QJsonDocument::fromJson(line).object();
        if (object.value(u"event"_s) == u"ready"_s)
            m_uri = object.value(u"uri"_s).toString();
        m_lines.append(object);
    }
}

QList<QJsonObject> Ros1Peer::received(const QString &topic) const
{
    QList<QJsonObject> messages;
    for (const QJsonObject &line : m_lines) {
        if (line.value(u"topic"_s) == topic && line.contains(u"msg"_s))
            messages.append(line);
    }
    return messages;
}

void Ros1Peer::clear()
{
    m_lines.removeIf([](const QJsonObject &line) { return line.contains(u"msg"_s); });
}

QJsonObject Ros1Peer::lastEvent(const QString &kind) const
{
    for (auto it = m_lines.crbegin(); it != m_lines.crend(); ++it) {
        if (it->value(u"event"_s) == kind)
            return *it;
    }
    return {};
}

int Ros1Peer::connections(const QString &topic) const
{
    for (auto it = m_lines.crbegin(); it != m_lines.crend(); ++it) {
        if (it->value(u"event"_s) == u"connections"_s && it->value(u"topic"_s) == topic)
            return it->value(u"count"_s).toInt();
    }
    return -1;
}

double field(const QJsonObject &message, const QString &path)
{
    QJsonValue value = message.value(u"msg"_s);
    for (const QString &part : path.split(u'.')) {
        bool index = false;
        const int i = part.toInt(&index);
        value = index ? value.toArray().at(i) : value.toObject().value(part);
    }
    return value.isDouble() ? value.toDouble() : std::numeric_limits<double>::quiet_NaN();
}

} // namespace hatpic::test
