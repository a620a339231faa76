#include "pseudoterminal.h"

#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

namespace hatpic {

namespace {

QString errnoText(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

void makeRaw(int fd)
{
    termios tio{};
    if (::tcgetattr(fd, &tio) == 0) {
        ::cfmakeraw(&tio);
        ::tcsetattr(fd, TCSANOW, &tio);
    }
}

void setFlag(int fd, int getCmd, int setCmd, int flag)
{
    const int flags = ::fcntl(fd, getCmd);
    if (flags >= 0)
        ::fcntl(fd, setCmd, flags | flag);
}

} // namespace

PseudoTerminal::~PseudoTerminal()
{
    close();
}

QString PseudoTerminal::open()
{
    if (isOpen())
        return {};
    int master = -1;
    int slave = -1;
    if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0)
        return QStringLiteral("Cannot open a pseudo-terminal: %1.").arg(errnoText(errno));
    char name[256] = {};
    if (::ttyname_r(slave, name, sizeof name) != 0) {
        const int error = errno;
        ::close(master);
        ::close(slave);
        return QStringLiteral("Cannot name the pseudo-terminal: %1.").arg(errnoText(error));
    }
    // Raw on both sides: the line discipline must not translate CR/LF, echo or eat bytes.
    makeRaw(master);
    makeRaw(slave);
    setFlag(master, F_GETFL, F_SETFL, O_NONBLOCK);
    setFlag(master, F_GETFD, F_SETFD, FD_CLOEXEC);
    setFlag(slave, F_GETFD, F_SETFD, FD_CLOEXEC);
    m_master = master;
    m_slave = slave;
    m_slavePath = QFile::decodeName(name);
    return {};
}

void PseudoTerminal::close()
{
    removeLink();
    if (m_master >= 0)
        ::close(m_master);
    if (m_slave >= 0)
        ::close(m_slave);
    m_master = -1;
    m_slave = -1;
    m_slavePath.clear();
}

QString PseudoTerminal::createLink(const QString &path)
{
    if (!isOpen())
        return QStringLiteral("Cannot create link %1: no pseudo-terminal is open.").arg(path);
    const QFileInfo info(path);
    if (info.exists() && !info.isSymLink())
        return QStringLiteral("Cannot create link %1: a file that is not a symlink is in the "
                              "way.")
            .arg(path);
    // Make the link beside its final place, then rename over any old one (atomic).
    const QByteArray target = QFile::encodeName(m_slavePath);
    const QByteArray finalName = QFile::encodeName(path);
    const QByteArray temp = finalName + ".tmp" + QByteArray::number(qint64(::getpid()));
    ::unlink(temp.constData());
    if (::symlink(target.constData(), temp.constData()) != 0)
        return QStringLiteral("Cannot create link %1: %2.").arg(path, errnoText(errno));
    if (::rename(temp.constData(), finalName.constData()) != 0) {
        const int error = errno;
        ::unlink(temp.constData());
        return QStringLiteral("Cannot create link %1: %2.").arg(path, errnoText(error));
    }
    m_linkPath = path;
    m_linkName.fill('\0');
    m_slaveName.fill('\0');
    if (finalName.size() < qsizetype(kMaxName) && target.size() < qsizetype(kMaxName)) {
        std::memcpy(m_linkName.data(), finalName.constData(), std::size_t(finalName.size()));
        std::memcpy(m_slaveName.data(), target.constData(), std::size_t(target.size()));
    }
    return {};
}

void PseudoTerminal::removeLink()
{
    m_linkName[0] = '\0';
    if (m_linkPath.isEmpty())
        return;
    const QFileInfo info(m_linkPath);
    if (info.isSymLink() && info.symLinkTarget() == m_slavePath)
        QFile::remove(m_linkPath);
    m_linkPath.clear();
}

void PseudoTerminal::removeLinkNow() const noexcept
{
    if (m_linkName[0] == '\0')
        return;
    std::array<char, kMaxName> target{};
    const ssize_t n = ::readlink(m_linkName.data(), target.data(), target.size() - 1);
    if (n > 0 && std::strcmp(target.data(), m_slaveName.data()) == 0)
        ::unlink(m_linkName.data());
}

} // namespace hatpic
