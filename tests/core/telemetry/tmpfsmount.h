// A small tmpfs mounted for one test: a real filesystem that really fills up. Needs root
// (CAP_SYS_ADMIN); isValid() is false otherwise and the test skips itself.
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

#include <sys/mount.h>

class TmpfsMount
{
public:
    explicit TmpfsMount(int kib)
    {
        const QByteArray options = "size=" + QByteArray::number(kib) + 'k';
        m_mounted = m_dir.isValid() && ::mount("tmpfs", QFile::encodeName(m_dir.path()).constData(),
                                               "tmpfs", 0, options.constData()) == 0;
    }
    ~TmpfsMount()
    {
        if (m_mounted)
            ::umount2(QFile::encodeName(m_dir.path()).constData(), MNT_DETACH);
    }
    TmpfsMount(const TmpfsMount &) = delete;
    TmpfsMount &operator=(const TmpfsMount &) = delete;

    bool isValid() const { return m_mounted; }
    QString path() const { return m_dir.path(); }
    QString filePath(const QString &name) const { return m_dir.filePath(name); }

    //! Writes a filler file until the filesystem is full, leaving about `leaveBytes` free.
    void fill(qint64 leaveBytes = 0)
    {
        QFile filler(filePath(QStringLiteral("filler")));
        if (!filler.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
            return;
        const QByteArray block(512, 'x');
        while (filler.write(block) == block.size()) {
        }
        filler.resize(std::max<qint64>(0, filler.size() - leaveBytes));
    }

private:
    QTemporaryDir m_dir;
    bool m_mounted = false;
};
