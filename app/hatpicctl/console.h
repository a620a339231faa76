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

//! Ensures `text` ends like a sentence (adds a full stop if it has no final punctuation).
QString asSentence(const QString &text);

} // namespace hatpic::cli
