// What a recording is: its columns, its metadata, its events and the status of one being
// written. RecordingWriter (recordingwriter.h) writes NAME.csv + NAME.json; readRecording
// (recordingreader.h) reads them back; docs/recording.md describes the format.
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"
#include "protocol/deviceinfo.h"
#include "telemetry/sample.h"

#include <QDateTime>
#include <QMetaType>
#include <QString>
#include <QStringList>

#include <optional>

namespace hatpic {

//! Header of the CSV, in column order: the sample columns (samplecolumns.h), the columns a
//! device with `axes` axes and a tilt sensor adds (extraSampleColumns; none for a single knob),
//! then "event", the text of what the device applied (or what happened) on that sample.
QStringList recordingColumns(int axes = 1, bool tilt = false);

struct RecordingMetadata
{
    QDateTime start; //!< wall-clock start (UTC)
    DeviceInfo device;
    DeviceParams params; //!< parameters at start
    //! The effect block at start (effects.md); none for a device without the effects capability
    std::optional<EffectParams> effects;
    //! The passivity block at start (passivity.md); none for a device without the controller
    std::optional<PassivityParams> passivity;
    HostParams host;
    QString source; //!< "hatpic-tuner", "hatpicctl stream", …
};

struct RecordingEvent
{
    double t_s = 0; //!< sample time the event is attached to [s]
    QString text;   //!< e.g. "K_max 0.4 → 0.6"
};

struct RecordingStatus
{
    bool active = false;
    QString path;              //!< the CSV file
    double seconds = 0;        //!< recorded duration [s]
    quint64 samples = 0;       //!< whole rows on disk
    qint64 bytes = 0;          //!< bytes written to the CSV so far
    quint64 eventsDropped = 0; //!< events left out by the recorder's bounds
    QString error;             //!< why the recording stopped, if it failed
    bool armed = false;        //!< waiting for its trigger (no file written yet)
    QString trigger;           //!< what an armed recording waits for (triggerEventText)
    //! Open, but the link is lost: rows resume in the same file when the device is back.
    bool waiting = false;
    quint32 gaps = 0; //!< link losses inside this recording so far (each an event in it)
};

//! NAME.csv → NAME.json: where a recording's metadata lives.
QString recordingMetadataPath(const QString &csvPath);

} // namespace hatpic
