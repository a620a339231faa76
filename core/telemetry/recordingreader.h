// Reads a recording (NAME.csv and NAME.json beside it) back for replay and for the CLI.
// Bounded and strict: a malformed line is refused with its line number.
#pragma once

#include "telemetry/recording.h"

#include <QByteArray>
#include <QList>

#include <optional>

namespace hatpic {

//! A recording read back for replay (written by the tuner or by hatpicctl stream).
struct Recording
{
    RecordingMetadata metadata; //!< defaults when the .json is missing
    bool hasMetadata = false;
    QList<Sample> samples;
    QList<RecordingEvent> events; //!< from the event column (and the .json)
    //! Set when the file holds more samples than a reader holds (recordingformat.h): the time
    //! of the last sample read; the rest of the file was not read [s].
    std::optional<double> heldUntil_s;
};

struct RecordingReadResult
{
    std::optional<Recording> recording;
    QString error; //!< "line 12: …" when the file is refused
    QStringList warnings;
};

//! Reads a recording CSV (and its .json beside it when present). Bounded: refuses files
//! over `maxBytes`, and holds at most recording::kMaxReadSamples samples and kMaxReadEvents
//! events (kMaxReadEventChars of their text); a file with more is read up to there, with a
//! warning that says so first.
RecordingReadResult readRecording(const QString &csvPath, qint64 maxBytes = 2LL << 30);
//! The same reading from memory: `csv` holds the CSV file, `metadata` its .json (std::nullopt
//! when there is none); `name` stands for the CSV's path in messages.
RecordingReadResult parseRecording(const QByteArray &csv, const std::optional<QByteArray> &metadata,
                                   const QString &name = QStringLiteral("recording.csv"));

} // namespace hatpic
