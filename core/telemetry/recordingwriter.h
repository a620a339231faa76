// Writes a recording: NAME.csv (one header row, one row per sample) and NAME.json (metadata).
//
// Owned by the session thread. Never throws; a write error stops the recording and is
// reported through error(), while the caller's session goes on.
#pragma once

#include "telemetry/recording.h"

#include <memory>

namespace hatpic {

class RecordingWriter
{
public:
    static constexpr int kFlushIntervalMs = 500; //!< data reaches the disk at least this often
    //! Events kept per second of recording time; more are counted as dropped.
    static constexpr int kMaxEventsPerSecond = 50;
    //! Longest event text on one row [characters]; further events on that row are dropped.
    static constexpr qsizetype kMaxEventTextPerRow = 1024;
    //! Events the .json lists; later ones are in the CSV only (counted in the .json).
    static constexpr qsizetype kMaxMetadataEvents = 1000;

    RecordingWriter();
    ~RecordingWriter(); //!< closes cleanly
    RecordingWriter(const RecordingWriter &) = delete;
    RecordingWriter &operator=(const RecordingWriter &) = delete;

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
    //! Flushes and closes both files; safe to call twice. An event added since the last row
    //! (no row followed it) is listed in the .json only, at the last row's t_s.
    void close();

    QString error() const;
    RecordingStatus status() const;

private:
    class Private;
    std::unique_ptr<Private> d;
};

} // namespace hatpic
