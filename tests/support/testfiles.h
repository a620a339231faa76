// A whole file read or written in a test: the one home of what several tests did by hand.
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>

namespace hatpic::test {

//! The file's bytes; empty when it cannot be read.
inline QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

//! Writes `bytes` as the whole file (replacing it); false when it could not be written in full.
inline bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

} // namespace hatpic::test
