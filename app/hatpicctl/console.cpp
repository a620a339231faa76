#include "console.h"

#include "model/params.h"

#include <QFileInfo>
#include <QRegularExpression>

#include <cstdio>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

void writeOut(const QByteArray &bytes)
{
    std::fwrite(bytes.constData(), 1, static_cast<size_t>(bytes.size()), stdout);
}

void writeOut(const QString &text)
{
    writeOut(text.toUtf8());
}

bool flushOut()
{
    return std::fflush(stdout) == 0 && !std::ferror(stdout);
}

QString outputTargetProblem(const QStringList &paths, bool force, const QString &ownFiles)
{
    for (const QString &path : paths) {
        const QFileInfo info(path);
        if (info.exists() && !info.isFile()) {
            return path + u" is not a regular file (" +
                   (info.isDir() ? u"a folder"_s : u"a device or pipe"_s) + u"); " + ownFiles +
                   u'.';
        }
    }
    for (const QString &path : paths) {
        if (QFileInfo::exists(path) && !force)
            return path + u" already exists; pass --force to overwrite it.";
    }
    if (!paths.isEmpty() && !QFileInfo(QFileInfo(paths.constFirst()).absolutePath()).isDir())
        return u"Cannot create " + paths.constFirst() + u": its folder does not exist.";
    return {};
}

void printError(const QString &sentence)
{
    const QByteArray line = "hatpicctl: " + sentence.toUtf8() + '\n';
    std::fflush(stdout);
    std::fwrite(line.constData(), 1, static_cast<size_t>(line.size()), stderr);
}

void printNote(const QString &text)
{
    QByteArray bytes = text.toUtf8();
    if (!bytes.endsWith('\n'))
        bytes += '\n';
    std::fwrite(bytes.constData(), 1, static_cast<size_t>(bytes.size()), stderr);
}

QString unreadNumber(const QString &what, const QString &text, bool whole)
{
    static const QRegularExpression integer(u"^[+-]?[0-9]+$"_s);
    static const QRegularExpression number(
        u"^[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?$"_s);
    const QString quoted = QString::fromStdString(echoedText(text.toStdString()));
    if ((whole ? integer : number).match(text.trimmed()).hasMatch())
        return u"is out of range: it must be " + what + u", got '" + quoted + u"'.";
    return u"must be " + what + u", got '" + quoted + u"'.";
}

QString asSentence(const QString &text)
{
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty() || trimmed.endsWith(u'.') || trimmed.endsWith(u'!') ||
        trimmed.endsWith(u'?'))
        return trimmed;
    return trimmed + u'.';
}

} // namespace hatpic::cli
