// Reading a JSON object from a file: the one set of rules that profiles and hatpic-bridge's
// --config file share (profile.md § Reading). Only a regular file is read (a pipe would block
// the open, a device such as /dev/zero never ends), and never more than a bound, whatever size
// the file claims; the text must be one JSON object that names each key once (Qt's reader
// would keep the last of two, silently).
#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QString>

#include <optional>

namespace hatpic {

//! The bytes of the file at `path`, or nullopt and one sentence in `*error` that names the file
//! as `<noun> "<path>"` (noun: "profile", "config file"): it cannot be opened or read
//! (`cannot open profile "p": No such file or directory`), it is a folder, a device or a pipe,
//! or it holds more than `maxBytes` (`profile "p" is larger than 1 MiB (1048576 bytes), got
//! 1048577 bytes; refused`). At most one byte past the bound is ever read.
std::optional<QByteArray> readBoundedFile(const QString &path, const QString &noun, qint64 maxBytes,
                                          QString *error);

//! The outcome of parseJsonObject().
struct JsonObjectRead
{
    std::optional<QJsonObject> object; //!< set when `error` is empty
    //! "not valid JSON: illegal number at byte offset 17 (1e999 is beyond …)", "the top level
    //! must be a JSON object, got an array", or "duplicate key \"device.K_max\": …".
    QString error;
    bool notAnObject = false; //!< valid JSON whose top level is not an object
};

//! `json` as one JSON object whose every object names each key once.
JsonObjectRead parseJsonObject(const QByteArray &json);

//! Writes `data` to `path` through a temporary file in its folder that is renamed over it
//! (QSaveFile): a write that fails (a full disk, the file-size limit) leaves the old file as it
//! was, never cut short. Empty on success, else why, in the system's words ("No space left on
//! device").
QString replaceFileContents(const QString &path, const QByteArray &data);

//! A size limit as people read it: "1 MiB", "64 KiB", else "N bytes".
QString byteLimitText(qint64 bytes);

} // namespace hatpic
