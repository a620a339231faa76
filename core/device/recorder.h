// Writes a recording: NAME.csv (one header row, one row per sample) and NAME.json (metadata).
//
// Owned by the session thread. Never throws; a write error stops the recording and is
// reported through error(), while the caller's session goes on.
#pragma once

#include "device/sample.h"
#include "device/sessiontypes.h"

#include <QDateTime>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

namespace hatpic {

//! Header of the CSV, in column order.
QStringList recordingColumns(); // t_s, theta, omega, tau, tau_rec, tau_ext, tau_total, v_ref,
                                // p_ref, flags, event

struct RecordingMetadata
{
    QDateTime start; //!< wall-clock start (UTC)
    DeviceInfo device;
    DeviceParams params; //!< parameters at start
    HostParams host;
    QString source; //!< "hatpic-tuner", "hatpicctl stream", …
};

struct RecordingEvent
{
    double t_s = 0; //!< sample time the event is attached to [s]
    QString text;   //!< e.g. "K_max 0.4 → 0.6"
};

class Recorder
{
public:
    static constexpr int kFlushIntervalMs = 500; //!< data reaches the disk at least this often
    //! Events kept per second of recording time; more are counted as dropped.
    static constexpr int kMaxEventsPerSecond = 50;
    //! Longest event text on one row [characters]; further events on that row are dropped.
    static constexpr qsizetype kMaxEventTextPerRow = 1024;
    //! Events the .json lists; later ones are in the CSV only (counted in the .json).
    static constexpr qsizetype kMaxMetadataEvents = 1000;

    Recorder();
    ~Recorder(); //!< closes cleanly
    Recorder(const Recorder &) = delete;
    Recorder &operator=(const Recorder &) = delete;

    //! Creates `csvPath` and its sibling .json. False (with error()) when they cannot be
    //! written; everything is checked first, so a refused start changes no file. Refused: a
    //! path that is not a regular file (a folder, /dev/null, a pipe), a missing folder, a
    //! read-only file, and a .json that exists but is not a recording's metadata.
    bool open(const QString &csvPath, const RecordingMetadata &metadata);
    bool isOpen() const;
    //! Attaches `text` to the next sample appended (joined with "; " if several). Bounded by
    //! kMaxEventsPerSecond and kMaxEventTextPerRow; what is dropped is counted, and the row
    //! says "(N more events not recorded)".
    void addEvent(const QString &text);
    //! Appends rows. False once a write failed: the recording is then closed, the CSV cut
    //! back to its last whole row, and status().samples equals the rows on disk.
    bool append(const SampleBatch &batch);
    //! Pushes buffered rows to disk and rewrites the .json when events changed.
    bool flush();
    //! Flushes and closes both files; safe to call twice.
    void close();

    QString error() const;
    RecordingStatus status() const;
    static QString metadataPath(const QString &csvPath); //!< NAME.csv → NAME.json

private:
    class Private;
    std::unique_ptr<Private> d;
};

//! A recording read back for replay (written by the tuner or by hatpicctl stream).
struct Recording
{
    RecordingMetadata metadata; //!< defaults when the .json is missing
    bool hasMetadata = false;
    QList<Sample> samples;
    QList<RecordingEvent> events; //!< from the event column (and the .json)
};

struct RecordingReadResult
{
    std::optional<Recording> recording;
    QString error; //!< "line 12: …" when the file is refused
    QStringList warnings;
};

//! Reads a recording CSV (and its .json beside it when present). Bounded: refuses files
//! over `maxBytes`.
RecordingReadResult readRecording(const QString &csvPath, qint64 maxBytes = 2LL << 30);
//! The same reading from memory: `csv` holds the CSV file, `metadata` its .json (std::nullopt
//! when there is none); `name` stands for the CSV's path in messages.
RecordingReadResult parseRecording(const QByteArray &csv, const std::optional<QByteArray> &metadata,
                                   const QString &name = QStringLiteral("recording.csv"));

} // namespace hatpic
