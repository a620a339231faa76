#include "jsonfile.h"

#include "jsonkeys.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QSaveFile>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace hatpic {

namespace {

constexpr qint64 kKiB = 1024;
constexpr qint64 kMiB = 1024 * 1024;
constexpr qsizetype kMaxNumberEcho = 40; //!< longest number quoted in a message [bytes]

QString named(const QString &noun, const QString &path)
{
    return noun + u" \"" + path + u'"';
}

// Qt says only "illegal number" for a number it cannot hold (1e999, 1e-999) and for one that
// is not written as JSON writes numbers ("1e", "-"). The number ends where Qt stopped.
QString illegalNumberDetail(const QByteArray &json, qsizetype end)
{
    qsizetype start = std::min(end, json.size());
    while (start > 0 && QByteArrayView("0123456789+-.eE").contains(json.at(start - 1)))
        --start;
    const QByteArray token = json.mid(start, std::min(end - start, kMaxNumberEcho));
    if (token.isEmpty())
        return {};
    const std::string text = token.toStdString();
    char *parsed = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &parsed);
    const bool whole = parsed == text.c_str() + text.size();
    const QString quoted = QString::fromLatin1(token);
    if (whole && errno == ERANGE && std::isinf(value))
        return quoted + u" is beyond the largest double, about 1.8e308";
    if (whole && errno == ERANGE)
        return quoted + u" is too close to 0 for a double";
    return u'"' + quoted + u"\" is not a number as JSON writes them";
}

} // namespace

QString replaceFileContents(const QString &path, const QByteArray &data)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return file.errorString();
    // Flush and check before commit(): Qt 6.4's QSaveFile::commit() does not notice when the
    // final flush of its write buffer fails (e.g. EFBIG, ENOSPC) and renames the truncated
    // temporary file over the good one. A short write also comes back without an error text,
    // so the system's errno is kept for the message. See docs/profile.md.
    errno = 0;
    if (file.write(data) != data.size() || !file.flush()) {
        const int systemError = errno;
        file.cancelWriting();
        file.commit(); // discards the temporary file
        return systemError != 0 ? qt_error_string(systemError) : file.errorString();
    }
    if (!file.commit())
        return file.errorString();
    return {};
}

QString byteLimitText(qint64 bytes)
{
    if (bytes > 0 && bytes % kMiB == 0)
        return QString::number(bytes / kMiB) + u" MiB";
    if (bytes > 0 && bytes % kKiB == 0)
        return QString::number(bytes / kKiB) + u" KiB";
    return QString::number(bytes) + u" bytes";
}

std::optional<QByteArray> readBoundedFile(const QString &path, const QString &noun, qint64 maxBytes,
                                          QString *error)
{
    // size() says 0 for a device and a pipe, and opening a pipe blocks until a writer comes:
    // only a regular file is opened at all.
    const QFileInfo info(path);
    if (info.exists() && !info.isFile()) {
        *error = named(noun, path) + (info.isDir() ? QStringLiteral(" is a folder, not a file")
                                                   : QStringLiteral(" is not a regular file (a "
                                                                    "device or a pipe); refused"));
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = u"cannot open " + named(noun, path) + u": " + file.errorString();
        return std::nullopt;
    }
    // One byte past the limit tells that the file is too large, whatever its size claims.
    const QByteArray data = file.read(maxBytes + 1);
    if (file.error() != QFileDevice::NoError) {
        *error = u"cannot read " + named(noun, path) + u": " + file.errorString();
        return std::nullopt;
    }
    if (data.size() > maxBytes) {
        const qint64 size = file.size();
        const QString got =
            size > maxBytes ? QString::number(size) + u" bytes" : QStringLiteral("more than that");
        *error = named(noun, path) + u" is larger than " + byteLimitText(maxBytes) + u" (" +
                 QString::number(maxBytes) + u" bytes), got " + got + u"; refused";
        return std::nullopt;
    }
    return data;
}

JsonObjectRead parseJsonObject(const QByteArray &json)
{
    JsonObjectRead result;
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        result.error = u"not valid JSON: " + parseError.errorString() + u" at byte offset " +
                       QString::number(parseError.offset);
        if (parseError.error == QJsonParseError::IllegalNumber) {
            if (const QString detail = illegalNumberDetail(json, parseError.offset);
                !detail.isEmpty())
                result.error += u" (" + detail + u')';
        }
        return result;
    }
    if (!document.isObject()) {
        result.notAnObject = true;
        result.error =
            u"the top level must be a JSON object, got " +
            (document.isArray() ? QStringLiteral("an array") : QStringLiteral("nothing"));
        return result;
    }
    if (const QString key = firstDuplicateKey(json); !key.isEmpty()) {
        result.error =
            u"duplicate key \"" + key + u"\": a key may appear once (which value was meant?)";
        return result;
    }
    result.object = document.object();
    return result;
}

} // namespace hatpic
