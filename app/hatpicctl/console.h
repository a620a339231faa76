// Where hatpicctl writes: data to stdout (CSV, JSON, tables), messages to stderr.
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace hatpic::cli {

//! Writes raw bytes to stdout (buffered; flushed at exit and by flushOut()).
void writeOut(const QByteArray &bytes);
void writeOut(const QString &text); //!< UTF-8
//! Pushes stdout's buffer out; false when writing failed (e.g. a full disk).
bool flushOut();

//! Writes one line to stderr, prefixed with "hatpicctl: ".
void printError(const QString &sentence);
//! Writes lines to stderr as they are (for lists under an error sentence, notes, statistics).
void printNote(const QString &text);

//! Why the files `paths` (FILE first, then what is written beside it) cannot be written:
//! one is a folder, a device or a pipe ("…; `ownFiles`", e.g. "a recording needs files of its
//! own"), one exists and `force` is not given, or FILE's folder does not exist. Empty when they
//! can. Checked before the port is opened, so that no measurement is lost to a bad target.
QString outputTargetProblem(const QStringList &paths, bool force, const QString &ownFiles);

//! The rest of the sentence for an option whose value `text` did not read as `what` ("a whole
//! number from 1 to 1000"): "must be <what>, got 'abc'." — or, for a number too large for its
//! type ("99999999999", "1e999"), "is out of range: it must be <what>, got '…'." A long integer
//! is a number, only not one that fits; for a `whole` option, "2.5" is not one at all.
QString unreadNumber(const QString &what, const QString &text, bool whole = false);

//! Ensures `text` ends like a sentence (adds a full stop if it has no final punctuation).
QString asSentence(const QString &text);

} // namespace hatpic::cli
