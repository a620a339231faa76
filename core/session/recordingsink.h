// The session's recording: a RecordingWriter on the session thread, its periodic flush, and
// the status reports (recordingChanged) that go with opening, progress, errors and closing.
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "session/sessiontypes.h"
#include "telemetry/recordingwriter.h"
#include "telemetry/sample.h"

#include <QObject>
#include <QTimer>

#include <optional>

namespace hatpic {

class RecordingSink : public QObject
{
    Q_OBJECT
public:
    explicit RecordingSink(QObject *parent = nullptr);

    //! Opens `csvPath`; reports the status either way. False when the writer refused.
    bool open(const QString &csvPath, const RecordingMetadata &metadata);
    bool isOpen() const { return m_writer.isOpen(); }
    //! Reports that a recording to `csvPath` waits for `trigger` (nothing is written yet).
    void reportArmed(const QString &csvPath, const QString &trigger);
    //! Reports that an armed recording was called off.
    void reportDisarmed(const QString &csvPath);
    //! Closes; reports the final status when it was open or when `error` is given. A
    //! recording that waits after a loss lists its gap, ended by the close, in the .json.
    void close(const QString &error = {});

    // A link loss inside a recording (recording.md, "Link losses"). Event texts, as above.
    //! The link was lost after the row at `lostAfter_s` [s], `why` (StateDetail of the loss):
    //! the files stay open, no row comes until resume(), and the status says `waiting`.
    void suspend(double lostAfter_s, const StateDetail &why);
    //! The same device is back: the next row carries the gap's event, then `changes` (what the
    //! device holds differently from before the loss), or says its parameters were not read
    //! back (`unread`).
    void resume(const QStringList &changes, bool unread);
    //! A different device answered (`differences`): the recording closes at the loss, and its
    //! .json says why.
    void closeForOtherDevice(const QStringList &differences);
    //! Appends the samples; a write error closes the recording (and reports it).
    void append(const SampleBatch &batch);
    //! Attaches an event to the next sample (nothing when closed). The events' text is part
    //! of the file format (recording.md), so it is composed here.
    void addEvent(const QString &text);
    //! SET_PARAMS or SET_EFFECTS applied: `to` has the part it carried.
    void tuningApplied(const DeviceTuning &from, const DeviceTuning &to);
    //! PARAMS or EFFECTS differed from what was held: `to` has the parts told.
    void tuningReadBack(const DeviceTuning &from, const DeviceTuning &to);
    void zeroed(double theta0Before); //!< ZERO applied
    void hostChanged(const HostParams &from, const HostParams &to);
    void referenceReset();
Q_SIGNALS:
    void statusChanged(const hatpic::RecordingStatus &status);
    //! Before each periodic flush: the samples waiting elsewhere belong in it (direct call).
    void aboutToFlush();

private:
    void onFlushTick();
    //! Emits the writer's status, with `error` when given.
    void report(const QString &error);
    //! "gap: link lost after t_s 12.5 (port error: …)", the start of every gap event.
    QString gapText() const;

    struct Gap
    {
        double lostAfter_s = 0; //!< t_s of the last row before the loss [s]
        StateDetail why;
    };
    RecordingWriter m_writer;
    QTimer m_timer;
    std::optional<Gap> m_gap; //!< while the link is lost
    quint32 m_gaps = 0;       //!< link losses in this recording
};

} // namespace hatpic
