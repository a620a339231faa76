#include "recordingwriter.h"

#include "profile/paramsjson.h"
#include "telemetry/recordingformat.h"
#include "telemetry/samplecolumns.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

#include <cerrno>
#include <cmath>
#include <limits>
#include <vector>

namespace hatpic {

namespace {

using recording::kFormatTag;
using recording::kFormatVersion;
constexpr qsizetype kFlushThresholdBytes = 256 * 1024; //!< write out earlier when this full

QByteArray deviceInfoJson(const DeviceInfo &d, int indent)
{
    JsonObjectWriter json(indent);
    json.add("port", jsonString(d.port))
        .add("baud", QByteArray::number(d.baud))
        .add("simulated", jsonBool(d.simulated))
        .add("protocol_version", QByteArray::number(d.protocolVersion))
        .add("max_stream_hz", QByteArray::number(d.maxStreamHz))
        .add("device_id", QByteArray::number(d.deviceId))
        .add("tau_limit", jsonNumber(d.tauLimit))
        .add("firmware", jsonString(d.firmware));
    // Said only by a device that has them: a single knob's metadata stays as it always was.
    if (d.axes > 1)
        json.add("axes", QByteArray::number(d.axes));
    if (d.tilt)
        json.add("tilt", jsonBool(d.tilt));
    return json.text();
}

// ---- CSV ----

QByteArray csvQuoted(const QString &text)
{
    QString clean = text;
    clean.replace(u'\n', u' ').replace(u'\r', u' ');
    clean.replace(u'"', QStringLiteral("\"\""));
    return '"' + clean.toUtf8() + '"';
}

} // namespace

class RecordingWriter::Private
{
public:
    bool writeOut();
    QByteArray metadataText(bool closing) const;
    bool writeMetadata(bool closing);
    void fail(const QString &message);
    QString checkTargets() const;
    void dropEvent();

    QFile csv;
    QString csvPath;
    RecordingMetadata metadata;
    QByteArray buffer;
    std::vector<double> bufferTimes;    //!< t_s of each row in `buffer`, in order [s]
    QList<RecordingEvent> bufferEvents; //!< events of rows in `buffer`
    QString pendingEvent;
    int droppedOnRow = 0;    //!< events not recorded since the last row with an event
    double eventSecond = -1; //!< whole second of t_s the event rate is counted in [s]
    int eventsThisSecond = 0;
    double noteSecond = -std::numeric_limits<double>::infinity(); //!< last note's second [s]
    quint64 eventsDropped = 0;
    quint64 eventsNotListed = 0;  //!< in the CSV, beyond the .json's list
    QList<RecordingEvent> events; //!< events on rows on disk (at most kMaxMetadataEvents)
    bool eventsDirty = false;
    bool open = false;
    quint64 samples = 0; //!< whole rows on disk
    double firstT = 0;
    double lastT = 0;
    double lastSeenT = 0; //!< t_s of the last sample appended (written or not) [s]
    qint64 bytes = 0;     //!< size of the CSV on disk: whole rows only
    QString error;
};

bool RecordingWriter::Private::writeOut()
{
    if (buffer.isEmpty())
        return true;
    qsizetype done = 0;
    while (done < buffer.size()) {
        errno = 0;
        const qint64 n = csv.write(buffer.constData() + done, buffer.size() - done);
        if (n <= 0) {
            const int systemError = errno;
            const QString reason =
                systemError != 0 ? qt_error_string(systemError) : csv.errorString();
            // Keep whole rows only: cut the file after the last complete row that reached it,
            // so a reader never meets half a row and the counts equal the rows on disk.
            const qsizetype whole = done > 0 ? buffer.lastIndexOf('\n', done - 1) + 1 : 0;
            const auto rows = static_cast<std::size_t>(buffer.left(whole).count('\n'));
            csv.resize(bytes + whole);
            bytes += whole;
            for (std::size_t r = 0; r < rows && r < bufferTimes.size(); ++r) {
                if (samples++ == 0)
                    firstT = bufferTimes[r];
                lastT = bufferTimes[r];
            }
            const double lastWritten = rows > 0 && rows <= bufferTimes.size()
                                           ? bufferTimes[rows - 1]
                                           : -std::numeric_limits<double>::infinity();
            for (const RecordingEvent &e : std::as_const(bufferEvents)) {
                if (e.t_s <= lastWritten && events.size() < kMaxMetadataEvents)
                    events.append(e);
            }
            fail(u"Writing " % csvPath % u" failed: " % reason %
                 u"; the rows written before are kept.");
            return false;
        }
        done += n;
    }
    bytes += buffer.size();
    for (double t : bufferTimes) {
        if (samples++ == 0)
            firstT = t;
        lastT = t;
    }
    for (const RecordingEvent &e : std::as_const(bufferEvents)) {
        if (events.size() < kMaxMetadataEvents) {
            events.append(e);
            eventsDirty = true;
        } else {
            ++eventsNotListed;
        }
    }
    buffer.clear();
    bufferTimes.clear();
    bufferEvents.clear();
    return true;
}

QByteArray RecordingWriter::Private::metadataText(bool closing) const
{
    QByteArray events_;
    {
        QByteArrayList items;
        for (const RecordingEvent &e : std::as_const(events)) {
            items.append("    " + JsonObjectWriter(4)
                                      .add("t_s", jsonNumber(e.t_s))
                                      .add("text", jsonString(e.text))
                                      .text());
        }
        events_ = items.isEmpty() ? QByteArrayLiteral("[]") : "[\n" + items.join(",\n") + "\n  ]";
    }
    JsonObjectWriter parametersWriter(2);
    parametersWriter.add("device", deviceParamsJson(metadata.params, 4))
        .add("host", hostParamsJson(metadata.host, 4));
    if (metadata.effects)
        parametersWriter.add("effects", effectParamsJson(*metadata.effects, 4));
    if (metadata.passivity)
        parametersWriter.add("passivity", passivityParamsJson(*metadata.passivity, 4));
    const QByteArray parameters = parametersWriter.text();
    JsonObjectWriter root(0);
    root.add("format", jsonString(QString::fromLatin1(kFormatTag)))
        .add("version", QByteArray::number(kFormatVersion))
        .add("start", jsonString(metadata.start.toUTC().toString(Qt::ISODateWithMs)))
        .add("source", jsonString(metadata.source))
        .add("csv", jsonString(QFileInfo(csvPath).fileName()))
        .add("protocol", jsonString(wireProtocolName(metadata.device.protocol)))
        .add("device", deviceInfoJson(metadata.device, 2))
        .add("parameters", parameters)
        .add("events", events_);
    if (eventsNotListed > 0)
        root.add("events_not_listed", QByteArray::number(eventsNotListed));
    if (eventsDropped > 0)
        root.add("events_dropped", QByteArray::number(eventsDropped));
    root.add("samples", QByteArray::number(samples))
        .add("duration_s", jsonNumber(samples ? std::round((lastT - firstT) * 1e6) / 1e6 : 0.0))
        .add("closed", jsonBool(closing));
    if (!error.isEmpty())
        root.add("error", jsonString(error));
    return root.text() + '\n';
}

bool RecordingWriter::Private::writeMetadata(bool closing)
{
    QSaveFile file(recordingMetadataPath(csvPath));
    if (!file.open(QIODevice::WriteOnly)) {
        if (error.isEmpty())
            fail(u"Cannot write " % file.fileName() % u": " % file.errorString());
        return false;
    }
    // Flush and check before commit(), as the profile writer does: Qt 6.4's commit() does not
    // notice a failed final flush (ENOSPC, EFBIG) and would rename a truncated file over the
    // good one. On failure the previous .json stays as it was.
    const QByteArray text = metadataText(closing);
    errno = 0;
    if (file.write(text) != text.size() || !file.flush()) {
        const int systemError = errno;
        file.cancelWriting();
        file.commit(); // discards the temporary file
        if (error.isEmpty()) {
            fail(u"Writing " % file.fileName() % u" failed: " %
                 (systemError != 0 ? qt_error_string(systemError) : file.errorString()));
        }
        return false;
    }
    if (!file.commit()) {
        if (error.isEmpty())
            fail(u"Writing " % file.fileName() % u" failed: " % file.errorString());
        return false;
    }
    eventsDirty = false;
    return true;
}

void RecordingWriter::Private::fail(const QString &message)
{
    if (error.isEmpty())
        error = message;
    if (!open)
        return;
    open = false;
    buffer.clear();
    bufferTimes.clear();
    bufferEvents.clear();
    csv.close();
    // Best effort: say in the metadata why the recording ended (the disk may be full; then
    // the last good .json stays).
    writeMetadata(true);
}

//! Why the recording cannot be written to `csvPath` and its .json, checked before either
//! file is touched; empty when both can be.
QString RecordingWriter::Private::checkTargets() const
{
    if (csvPath.isEmpty())
        return QStringLiteral("No file name was given for the recording.");
    const QString jsonPath = recordingMetadataPath(csvPath);
    for (const QString &path : {csvPath, jsonPath}) {
        const QFileInfo info(path);
        if (info.exists() && !info.isFile()) {
            return path % u" is not a regular file (" %
                   (info.isDir() ? QStringLiteral("a folder")
                                 : QStringLiteral("a device or pipe")) %
                   u"); a recording needs files of its own.";
        }
        if (info.exists() && !info.isWritable())
            return u"Cannot write " % path % u": it is read-only.";
    }
    const QFileInfo folder(QFileInfo(csvPath).absolutePath());
    if (!folder.isDir())
        return u"Cannot create " % csvPath % u": the folder " % folder.filePath() %
               u" does not exist.";
    // A .json that is not an earlier recording's metadata (a profile, say) is never replaced.
    QFile json(jsonPath);
    if (json.exists() && json.size() > 0) {
        bool ours = false;
        if (json.open(QIODevice::ReadOnly)) {
            const QJsonDocument doc =
                QJsonDocument::fromJson(json.read(recording::kMaxMetadataBytes));
            ours = doc.isObject() &&
                   doc.object().value(u"format").toString() == QLatin1String(kFormatTag);
        }
        if (!ours) {
            return jsonPath % u" exists and is not a HATPIC recording's metadata; it was left "
                              u"untouched. Choose another name for the recording.";
        }
    }
    return {};
}

void RecordingWriter::Private::dropEvent()
{
    ++eventsDropped;
    ++droppedOnRow;
}

RecordingWriter::RecordingWriter() : d(std::make_unique<Private>()) {}

RecordingWriter::~RecordingWriter()
{
    close();
}

bool RecordingWriter::open(const QString &csvPath, const RecordingMetadata &metadata)
{
    close();
    d = std::make_unique<Private>();
    d->csvPath = csvPath;
    d->metadata = metadata;
    // Everything is checked before anything is touched: a refused start leaves existing files
    // as they were.
    if (const QString problem = d->checkTargets(); !problem.isEmpty()) {
        d->error = problem;
        return false;
    }
    QSaveFile json(recordingMetadataPath(csvPath));
    const QByteArray text = d->metadataText(false);
    errno = 0;
    if (!json.open(QIODevice::WriteOnly) || json.write(text) != text.size() || !json.flush()) {
        const int systemError = errno;
        d->error = u"Cannot write " % json.fileName() % u": " %
                   (systemError != 0 ? qt_error_string(systemError) : json.errorString());
        json.cancelWriting();
        return false;
    }
    d->csv.setFileName(csvPath);
    // Unbuffered: the row buffer is ours, and a write error shows at the write that failed.
    if (!d->csv.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered)) {
        d->error = u"Cannot create " % csvPath % u": " % d->csv.errorString();
        json.cancelWriting();
        return false;
    }
    d->open = true;
    d->buffer =
        recordingColumns(metadata.device.axes, metadata.device.tilt).join(u',').toUtf8() + '\n';
    if (!d->writeOut())
        return false;
    if (!json.commit()) {
        d->fail(u"Writing " % json.fileName() % u" failed: " % json.errorString());
        return false;
    }
    return true;
}

bool RecordingWriter::isOpen() const
{
    return d->open;
}

void RecordingWriter::addEvent(const QString &text)
{
    if (!d->open || text.isEmpty())
        return;
    // Bounded per second of recording time and per row, so a device flooding changes cannot
    // grow a row (or the .json) without limit; what is left out is counted.
    const double second = std::floor(d->lastSeenT);
    if (second != d->eventSecond) {
        d->eventSecond = second;
        d->eventsThisSecond = 0;
    }
    if (d->eventsThisSecond >= kMaxEventsPerSecond ||
        d->pendingEvent.size() + text.size() + 2 > kMaxEventTextPerRow) {
        d->dropEvent();
        return;
    }
    ++d->eventsThisSecond;
    if (d->pendingEvent.isEmpty())
        d->pendingEvent = text;
    else
        d->pendingEvent += u"; " + text;
}

bool RecordingWriter::append(const SampleBatch &batch)
{
    if (!d->open)
        return false;
    QByteArray &out = d->buffer;
    for (const Sample &s : batch) {
        d->lastSeenT = s.t_s;
        d->bufferTimes.push_back(s.t_s);
        appendSampleCsvRow(out, s);
        appendExtraCsvFields(out, s, d->metadata.device.axes, d->metadata.device.tilt);
        out += ',';
        // Events left out are noted on the next row with a kept event, or at most once per
        // second of recording time, so the note itself cannot flood the file.
        const bool note = d->droppedOnRow > 0 &&
                          (!d->pendingEvent.isEmpty() || std::floor(s.t_s) > d->noteSecond);
        if (!d->pendingEvent.isEmpty() || note) {
            if (note)
                d->noteSecond = std::floor(s.t_s);
            QString text = d->pendingEvent;
            if (note) {
                text += (text.isEmpty() ? QString() : QStringLiteral("; ")) % u'(' %
                        QString::number(d->droppedOnRow) % u" more events not recorded)";
            }
            out += csvQuoted(text);
            d->bufferEvents.append({s.t_s, text});
            d->pendingEvent.clear();
            d->droppedOnRow = 0;
        }
        out += '\n';
    }
    if (out.size() >= kFlushThresholdBytes)
        return d->writeOut();
    return true;
}

bool RecordingWriter::flush()
{
    if (!d->open)
        return false;
    if (!d->writeOut())
        return false;
    if (d->eventsDirty && !d->writeMetadata(false))
        return false;
    return true;
}

void RecordingWriter::close()
{
    if (!d->open)
        return;
    if (!d->writeOut())
        return;
    // An event that no row followed (the recording closed first: during a link loss, right
    // after a push) is kept in the JSON, at the time of the last row.
    if (!d->pendingEvent.isEmpty()) {
        if (d->events.size() < kMaxMetadataEvents)
            d->events.append({d->samples > 0 ? d->lastT : d->lastSeenT, d->pendingEvent});
        else
            ++d->eventsNotListed;
        d->pendingEvent.clear();
    }
    d->csv.close();
    d->open = false;
    d->writeMetadata(true);
}

QString RecordingWriter::error() const
{
    return d->error;
}

RecordingStatus RecordingWriter::status() const
{
    RecordingStatus s;
    s.active = d->open;
    s.path = d->csvPath;
    s.samples = d->samples;
    s.seconds = d->samples ? std::round((d->lastT - d->firstT) * 1e6) / 1e6 : 0.0;
    s.bytes = d->bytes;
    s.eventsDropped = d->eventsDropped;
    s.error = d->error;
    return s;
}

} // namespace hatpic
