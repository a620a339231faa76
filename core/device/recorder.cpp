#include "recorder.h"

#include "device/numbertext.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSet>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <vector>

namespace hatpic {

namespace {

constexpr char kFormatTag[] = "hatpic-recording";
constexpr int kFormatVersion = 1;
constexpr qsizetype kFlushThresholdBytes = 256 * 1024; //!< write out earlier when this full
constexpr qsizetype kMaxLineBytes = 8192;              //!< longest CSV line a reader accepts
constexpr qint64 kMaxMetadataBytes = 16 * 1024 * 1024;
constexpr int kMaxWarnings = 20; //!< warnings a reader lists before it stops listing

// ---- JSON text with a fixed, readable key order (QJsonObject would sort the keys) ----

QByteArray jsonString(const QString &text)
{
    QByteArray array = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return array.mid(1, array.size() - 2); // strip [ ]
}

//! JSON number that reads back as the identical double (as profiles do); "null" for NaN and
//! ±Inf. The parameters a device reports are float32 values, so they show their full digits
//! (0.4000000059604645): a reader gets exactly what the device holds.
QByteArray jsonDouble(double value)
{
    if (!std::isfinite(value))
        return QByteArrayLiteral("null");
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
    QByteArray text(buffer, r.ptr - buffer);
    if (!text.contains('.') && !text.contains('e'))
        text += ".0";
    return text;
}

QByteArray jsonBool(bool value)
{
    return value ? QByteArrayLiteral("true") : QByteArrayLiteral("false");
}

class JsonObjectWriter
{
public:
    explicit JsonObjectWriter(int indent) : m_indent(indent) {}
    JsonObjectWriter &add(const char *key, const QByteArray &rawValue)
    {
        m_items.append(QByteArray(m_indent + 2, ' ') + '"' + key + "\": " + rawValue);
        return *this;
    }
    QByteArray text() const
    {
        if (m_items.isEmpty())
            return QByteArrayLiteral("{}");
        return "{\n" + m_items.join(",\n") + '\n' + QByteArray(m_indent, ' ') + '}';
    }

private:
    int m_indent;
    QByteArrayList m_items;
};

QByteArray deviceParamsJson(const DeviceParams &p, int indent)
{
    JsonObjectWriter w(indent);
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const std::string_view name = deviceFieldName(i);
        w.add(name.data(), jsonDouble(p.field(i)));
    }
    return w.text();
}

QByteArray hostParamsJson(const HostParams &h, int indent)
{
    return JsonObjectWriter(indent)
        .add("mode", jsonString(QString::fromLatin1(referenceModeName(h.mode))))
        .add("v_max", jsonDouble(h.v_max))
        .add("ref_deadzone", jsonBool(h.ref_deadzone))
        .add("tau_limit", jsonDouble(h.tau_limit))
        .text();
}

QByteArray deviceInfoJson(const DeviceInfo &d, int indent)
{
    return JsonObjectWriter(indent)
        .add("port", jsonString(d.port))
        .add("baud", QByteArray::number(d.baud))
        .add("simulated", jsonBool(d.simulated))
        .add("protocol_version", QByteArray::number(d.protocolVersion))
        .add("max_stream_hz", QByteArray::number(d.maxStreamHz))
        .add("device_id", QByteArray::number(d.deviceId))
        .add("tau_limit", jsonDouble(d.tauLimit))
        .add("firmware", jsonString(d.firmware))
        .text();
}

// ---- CSV ----

void appendNumber(QByteArray &row, double value)
{
    if (!std::isnan(value)) // NaN stays an empty field
        row += compactNumber(value);
}

QByteArray csvQuoted(const QString &text)
{
    QString clean = text;
    clean.replace(u'\n', u' ').replace(u'\r', u' ');
    clean.replace(u'"', QStringLiteral("\"\""));
    return '"' + clean.toUtf8() + '"';
}

} // namespace

QStringList recordingColumns()
{
    return {QStringLiteral("t_s"),       QStringLiteral("theta"),   QStringLiteral("omega"),
            QStringLiteral("tau"),       QStringLiteral("tau_rec"), QStringLiteral("tau_ext"),
            QStringLiteral("tau_total"), QStringLiteral("v_ref"),   QStringLiteral("p_ref"),
            QStringLiteral("flags"),     QStringLiteral("event")};
}

class Recorder::Private
{
public:
    bool writeOut();
    bool writeMetadata(bool closing);
    void fail(const QString &message);

    QFile csv;
    QString csvPath;
    RecordingMetadata metadata;
    QByteArray buffer;
    QString pendingEvent;
    QList<RecordingEvent> events;
    bool eventsDirty = false;
    bool open = false;
    quint64 samples = 0;
    double firstT = 0;
    double lastT = 0;
    qint64 bytes = 0;
    QString error;
};

bool Recorder::Private::writeOut()
{
    qsizetype done = 0;
    while (done < buffer.size()) {
        const qint64 n = csv.write(buffer.constData() + done, buffer.size() - done);
        if (n <= 0) {
            fail(u"Writing " % csvPath % u" failed: " % csv.errorString() %
                 u". The recording stopped; what was written before is kept.");
            return false;
        }
        done += n;
        bytes += n;
    }
    buffer.clear();
    return true;
}

bool Recorder::Private::writeMetadata(bool closing)
{
    QByteArray events_;
    {
        QByteArrayList items;
        for (const RecordingEvent &e : std::as_const(events)) {
            items.append("    " + JsonObjectWriter(4)
                                      .add("t_s", jsonDouble(e.t_s))
                                      .add("text", jsonString(e.text))
                                      .text());
        }
        events_ = items.isEmpty() ? QByteArrayLiteral("[]") : "[\n" + items.join(",\n") + "\n  ]";
    }
    const QByteArray parameters = JsonObjectWriter(2)
                                      .add("device", deviceParamsJson(metadata.params, 4))
                                      .add("host", hostParamsJson(metadata.host, 4))
                                      .text();
    JsonObjectWriter root(0);
    root.add("format", jsonString(QString::fromLatin1(kFormatTag)))
        .add("version", QByteArray::number(kFormatVersion))
        .add("start", jsonString(metadata.start.toUTC().toString(Qt::ISODateWithMs)))
        .add("source", jsonString(metadata.source))
        .add("csv", jsonString(QFileInfo(csvPath).fileName()))
        .add("protocol", jsonString(wireProtocolName(metadata.device.protocol)))
        .add("device", deviceInfoJson(metadata.device, 2))
        .add("parameters", parameters)
        .add("events", events_)
        .add("samples", QByteArray::number(samples))
        .add("duration_s", jsonDouble(samples ? std::round((lastT - firstT) * 1e6) / 1e6 : 0.0))
        .add("closed", jsonBool(closing));
    if (!error.isEmpty())
        root.add("error", jsonString(error));

    QSaveFile file(Recorder::metadataPath(csvPath));
    if (!file.open(QIODevice::WriteOnly)) {
        if (error.isEmpty())
            fail(u"Cannot write " % file.fileName() % u": " % file.errorString());
        return false;
    }
    file.write(root.text() + '\n');
    if (!file.commit()) {
        if (error.isEmpty())
            fail(u"Writing " % file.fileName() % u" failed: " % file.errorString());
        return false;
    }
    eventsDirty = false;
    return true;
}

void Recorder::Private::fail(const QString &message)
{
    if (error.isEmpty())
        error = message;
    if (!open)
        return;
    open = false;
    buffer.clear();
    csv.close();
    // Best effort: say in the metadata why the recording ended (the disk may be full).
    writeMetadata(true);
}

Recorder::Recorder() : d(std::make_unique<Private>()) {}

Recorder::~Recorder()
{
    close();
}

QString Recorder::metadataPath(const QString &csvPath)
{
    const QFileInfo info(csvPath);
    const QString base = info.suffix().compare(u"csv", Qt::CaseInsensitive) == 0
                             ? info.completeBaseName()
                             : info.fileName();
    return info.dir().filePath(base + u".json");
}

bool Recorder::open(const QString &csvPath, const RecordingMetadata &metadata)
{
    close();
    d = std::make_unique<Private>();
    d->csvPath = csvPath;
    d->metadata = metadata;
    d->csv.setFileName(csvPath);
    // Unbuffered: the row buffer is ours, and a write error shows at the write that failed.
    if (!d->csv.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered)) {
        d->error = u"Cannot create " % csvPath % u": " % d->csv.errorString();
        return false;
    }
    d->open = true;
    d->buffer = recordingColumns().join(u',').toUtf8() + '\n';
    if (!d->writeOut())
        return false;
    if (!d->writeMetadata(false))
        return false;
    return true;
}

bool Recorder::isOpen() const
{
    return d->open;
}

void Recorder::addEvent(const QString &text)
{
    if (!d->open || text.isEmpty())
        return;
    if (d->pendingEvent.isEmpty())
        d->pendingEvent = text;
    else
        d->pendingEvent += u"; " + text;
}

bool Recorder::append(const SampleBatch &batch)
{
    if (!d->open)
        return false;
    QByteArray &out = d->buffer;
    for (const Sample &s : batch) {
        if (d->samples == 0)
            d->firstT = s.t_s;
        d->lastT = s.t_s;
        ++d->samples;
        appendNumber(out, s.t_s);
        for (double v :
             {s.theta, s.omega, s.tau, s.tau_rec, s.tau_ext, s.tau_total, s.v_ref, s.p_ref}) {
            out += ',';
            appendNumber(out, v);
        }
        out += ',';
        out += QByteArray::number(s.flags);
        out += ',';
        if (!d->pendingEvent.isEmpty()) {
            out += csvQuoted(d->pendingEvent);
            d->events.append({s.t_s, d->pendingEvent});
            d->pendingEvent.clear();
            d->eventsDirty = true;
        }
        out += '\n';
    }
    if (out.size() >= kFlushThresholdBytes)
        return d->writeOut();
    return true;
}

bool Recorder::flush()
{
    if (!d->open)
        return false;
    if (!d->writeOut())
        return false;
    if (d->eventsDirty && !d->writeMetadata(false))
        return false;
    return true;
}

void Recorder::close()
{
    if (!d->open)
        return;
    if (!d->writeOut())
        return;
    d->csv.close();
    d->writeMetadata(true);
    d->open = false;
}

QString Recorder::error() const
{
    return d->error;
}

RecordingStatus Recorder::status() const
{
    RecordingStatus s;
    s.active = d->open;
    s.path = d->csvPath;
    s.samples = d->samples;
    s.seconds = d->samples ? std::round((d->lastT - d->firstT) * 1e6) / 1e6 : 0.0;
    s.bytes = d->bytes;
    s.error = d->error;
    return s;
}

// ================================================================ reading

namespace {

//! Splits one CSV line (no line break) into fields; false on a broken quote.
bool splitCsvLine(QByteArrayView line, QList<QByteArray> &fields, QString &problem)
{
    fields.clear();
    QByteArray field;
    qsizetype i = 0;
    const qsizetype n = line.size();
    while (true) {
        field.clear();
        if (i < n && line[i] == '"') {
            ++i;
            bool closed = false;
            while (i < n) {
                const char c = line[i++];
                if (c == '"') {
                    if (i < n && line[i] == '"') {
                        field += '"';
                        ++i;
                    } else {
                        closed = true;
                        break;
                    }
                } else {
                    field += c;
                }
            }
            if (!closed) {
                problem = QStringLiteral("a quoted field is not closed");
                return false;
            }
            if (i < n && line[i] != ',') {
                problem = QStringLiteral("text follows a closing quote");
                return false;
            }
        } else {
            while (i < n && line[i] != ',') {
                if (line[i] == '"') {
                    problem = QStringLiteral("a quote inside an unquoted field");
                    return false;
                }
                field += line[i++];
            }
        }
        fields.append(field);
        if (i >= n)
            return true;
        ++i; // the comma
        if (i == n) {
            fields.append(QByteArray());
            return true;
        }
    }
}

bool parseDouble(const QByteArray &text, double &value)
{
    const QByteArray t = text.trimmed();
    if (t.isEmpty()) {
        value = std::numeric_limits<double>::quiet_NaN();
        return true;
    }
    const char *begin = t.constData();
    const char *end = begin + t.size();
    if (*begin == '+')
        ++begin;
    const auto r = std::from_chars(begin, end, value);
    return r.ec == std::errc() && r.ptr == end;
}

enum Column {
    ColT,
    ColTheta,
    ColOmega,
    ColTau,
    ColTauRec,
    ColTauExt,
    ColTauTotal,
    ColVRef,
    ColPRef,
    ColFlags,
    ColEvent,
    ColCount
};

//! Applies the metadata JSON `json` (read from `fileName`) to `rec`.
void applyMetadata(const QByteArray &json, const QString &fileName, Recording &rec,
                   QStringList &warnings)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !doc.isObject()) {
        warnings << fileName % u" is not valid JSON (offset " % QString::number(parseError.offset) %
                        u": " % parseError.errorString() % u"); metadata ignored.";
        return;
    }
    const QJsonObject root = doc.object();
    if (root.value(u"format").toString() != QLatin1String(kFormatTag)) {
        warnings << fileName + u" is not HATPIC recording metadata; ignored.";
        return;
    }
    if (root.value(u"version").toInt() > kFormatVersion) {
        warnings << fileName % u" was written by a newer version (format version " %
                        QString::number(root.value(u"version").toInt()) %
                        u"); reading what this build knows.";
    }
    RecordingMetadata &m = rec.metadata;
    m.start = QDateTime::fromString(root.value(u"start").toString(), Qt::ISODateWithMs);
    m.source = root.value(u"source").toString();
    const QString protocol = root.value(u"protocol").toString();
    m.device.protocol = protocol == u"legacy" ? WireProtocol::Legacy : WireProtocol::V2;
    const QJsonObject dev = root.value(u"device").toObject();
    m.device.port = dev.value(u"port").toString();
    m.device.baud = dev.value(u"baud").toInt();
    m.device.simulated = dev.value(u"simulated").toBool();
    m.device.protocolVersion = static_cast<quint8>(dev.value(u"protocol_version").toInt());
    m.device.maxStreamHz = static_cast<quint16>(dev.value(u"max_stream_hz").toInt());
    m.device.deviceId = static_cast<quint32>(dev.value(u"device_id").toDouble());
    m.device.tauLimit = dev.value(u"tau_limit").toDouble(m.device.tauLimit);
    m.device.firmware = dev.value(u"firmware").toString();
    const QJsonObject params = root.value(u"parameters").toObject();
    const QJsonObject device = params.value(u"device").toObject();
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const QString key = QString::fromLatin1(deviceFieldName(i));
        if (device.contains(key))
            m.params.setField(i, device.value(key).toDouble(m.params.field(i)));
    }
    const QJsonObject host = params.value(u"host").toObject();
    m.host.v_max = host.value(u"v_max").toDouble(m.host.v_max);
    m.host.mode = host.value(u"mode").toString() == u"rotation" ? ReferenceMode::Rotation
                                                                : ReferenceMode::Translation;
    m.host.ref_deadzone = host.value(u"ref_deadzone").toBool(m.host.ref_deadzone);
    m.host.tau_limit = host.value(u"tau_limit").toDouble(m.host.tau_limit);
    rec.hasMetadata = true;

    // Events the CSV lost (e.g. a cut-off last line) are taken from the metadata. The CSV's
    // event times are looked up per text in sorted order, so a metadata file holding very many
    // events costs O(n log n), not a comparison of every pair.
    QHash<QString, std::vector<double>> csvTimes;
    for (const RecordingEvent &x : std::as_const(rec.events))
        csvTimes[x.text].push_back(x.t_s);
    for (auto it = csvTimes.begin(); it != csvTimes.end(); ++it)
        std::sort(it->begin(), it->end());
    QSet<QPair<QString, double>> fromMetadata; //!< listed twice in the .json: kept once
    for (const QJsonValue &v : root.value(u"events").toArray()) {
        const QJsonObject e = v.toObject();
        RecordingEvent event{e.value(u"t_s").toDouble(), e.value(u"text").toString()};
        if (event.text.isEmpty())
            continue;
        const auto found = csvTimes.constFind(event.text);
        bool known = false;
        if (found != csvTimes.cend()) {
            for (auto at = std::lower_bound(found->cbegin(), found->cend(), event.t_s - 1e-9);
                 !known && at != found->cend() && *at <= event.t_s + 1e-9; ++at) {
                known = std::abs(*at - event.t_s) < 1e-9;
            }
        }
        if (!known && !fromMetadata.contains({event.text, event.t_s})) {
            fromMetadata.insert({event.text, event.t_s});
            rec.events.append(event);
        }
    }
    std::stable_sort(rec.events.begin(), rec.events.end(),
                     [](const auto &a, const auto &b) { return a.t_s < b.t_s; });
}

void readMetadata(const QString &csvPath, Recording &rec, QStringList &warnings)
{
    QFile file(Recorder::metadataPath(csvPath));
    if (!file.exists())
        return;
    if (file.size() > kMaxMetadataBytes) {
        warnings << file.fileName() + u" is too large to be recording metadata; ignored.";
        return;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        warnings << u"Cannot read " % file.fileName() % u": " % file.errorString();
        return;
    }
    applyMetadata(file.readAll(), file.fileName(), rec, warnings);
}

//! Reads the CSV rows from `file` (opened, its size already checked) into `rec`. `name` names
//! the file in messages. False (with out.error) when the file is refused.
bool readCsv(QIODevice &file, const QString &name, qint64 maxBytes, Recording &rec,
             RecordingReadResult &out)
{
    std::array<int, ColCount> index;
    index.fill(-1);
    int columnCount = 0;
    qint64 lineNumber = 0;
    qint64 readBytes = 0;
    bool haveHeader = false;
    QList<QByteArray> fields;
    QString problem;
    const QStringList columns = recordingColumns();
    int warningsLeft = kMaxWarnings;
    auto warn = [&](const QString &message) {
        if (warningsLeft-- > 0)
            out.warnings << message;
        else if (warningsLeft == -1)
            out.warnings << QStringLiteral("(further warnings left out)");
    };
    auto fail = [&](const QString &message) {
        out.error = u"line " % QString::number(lineNumber) % u": " % message;
        return false;
    };

    while (!file.atEnd()) {
        QByteArray line = file.readLine(kMaxLineBytes + 1);
        ++lineNumber;
        readBytes += line.size();
        if (readBytes > maxBytes)
            return fail(QStringLiteral("the file grew beyond the size limit while being read"));
        const bool complete = line.endsWith('\n');
        if (!complete && !file.atEnd()) {
            return fail(u"longer than " % QString::number(kMaxLineBytes) %
                        u" bytes; this is not a recording");
        }
        while (line.endsWith('\n') || line.endsWith('\r'))
            line.chop(1);
        if (lineNumber == 1 && line.startsWith("\xEF\xBB\xBF"))
            line.remove(0, 3); // UTF-8 byte order mark, as some spreadsheets write it
        if (line.trimmed().isEmpty())
            continue;

        if (!splitCsvLine(line, fields, problem)) {
            if (!complete && haveHeader) {
                warn(u"line " % QString::number(lineNumber) %
                     u": incomplete last line ignored (the recording was cut off).");
                break;
            }
            return fail(problem);
        }

        if (!haveHeader) {
            columnCount = static_cast<int>(fields.size());
            for (int c = 0; c < columnCount; ++c) {
                const QString name = QString::fromUtf8(fields[c].trimmed());
                const int known = static_cast<int>(columns.indexOf(name));
                if (known < 0) {
                    warn(u"line 1: unknown column \"" % name % u"\" ignored.");
                    continue;
                }
                if (index[known] >= 0)
                    return fail(u"column \"" % name % u"\" appears twice");
                index[known] = c;
            }
            if (index[ColT] < 0 || index[ColTheta] < 0) {
                return fail(u"not a HATPIC recording: the header must name at least t_s and "
                            u"theta (expected " %
                            columns.join(u',') % u')');
            }
            for (int k = 0; k < ColCount; ++k) {
                if (index[k] < 0 && k != ColEvent) {
                    warn(u"line 1: column \"" % columns[k] %
                         u"\" missing; its values read as empty.");
                }
            }
            haveHeader = true;
            continue;
        }

        if (fields.size() != columnCount) {
            if (!complete) {
                warn(u"line " % QString::number(lineNumber) %
                     u": incomplete last line ignored (the recording was cut off).");
                break;
            }
            return fail(u"expected " % QString::number(columnCount) % u" fields, found " %
                        QString::number(fields.size()));
        }

        Sample s;
        double values[ColFlags];
        bool cutOff = false;
        for (int k = 0; k < ColFlags; ++k) {
            values[k] = std::numeric_limits<double>::quiet_NaN();
            if (index[k] < 0 || parseDouble(fields[index[k]], values[k]))
                continue;
            if (!complete) {
                cutOff = true;
                break;
            }
            return fail(u"column " % columns[k] % u": \"" %
                        QString::fromUtf8(fields[index[k]].left(40)) % u"\" is not a number");
        }
        if (cutOff) {
            warn(u"line " % QString::number(lineNumber) %
                 u": incomplete last line ignored (the recording was cut off).");
            break;
        }
        if (!std::isfinite(values[ColT]))
            return fail(QStringLiteral("t_s must be a finite number"));
        s.t_s = values[ColT];
        s.t_us = static_cast<quint32>(static_cast<quint64>(std::llround(s.t_s * 1e6)));
        s.theta = values[ColTheta];
        s.omega = values[ColOmega];
        s.tau = values[ColTau];
        s.tau_rec = values[ColTauRec];
        s.tau_ext = values[ColTauExt];
        s.tau_total = values[ColTauTotal];
        s.v_ref = values[ColVRef];
        s.p_ref = values[ColPRef];
        if (index[ColFlags] >= 0) {
            const QByteArray text = fields[index[ColFlags]].trimmed();
            bool ok = true;
            const uint flags = text.isEmpty() ? 0u : text.toUInt(&ok);
            if (!ok || flags > 0xFFFF) {
                return fail(u"column flags: \"" % QString::fromUtf8(text.left(40)) %
                            u"\" is not a number from 0 to 65535");
            }
            s.flags = static_cast<quint16>(flags);
        }
        if (!rec.samples.isEmpty() && s.t_s < rec.samples.last().t_s) {
            warn(u"line " % QString::number(lineNumber) % u": t_s goes back in time.");
        }
        if (index[ColEvent] >= 0) {
            const QString event = QString::fromUtf8(fields[index[ColEvent]]);
            if (!event.isEmpty())
                rec.events.append({s.t_s, event});
        }
        rec.samples.append(s);
    }
    if (!haveHeader) {
        out.error = name % u" is empty: no header row.";
        return false;
    }
    return true;
}

} // namespace

RecordingReadResult readRecording(const QString &csvPath, qint64 maxBytes)
{
    RecordingReadResult out;
    QFile file(csvPath);
    if (!file.open(QIODevice::ReadOnly)) {
        out.error = u"Cannot open " % csvPath % u": " % file.errorString();
        return out;
    }
    if (file.size() > maxBytes) {
        out.error = csvPath % u" is " % QString::number(file.size()) %
                    u" bytes, more than the limit of " % QString::number(maxBytes) % u" bytes.";
        return out;
    }
    Recording rec;
    if (!readCsv(file, csvPath, maxBytes, rec, out))
        return out;
    readMetadata(csvPath, rec, out.warnings);
    out.recording = std::move(rec);
    return out;
}

RecordingReadResult parseRecording(const QByteArray &csv, const std::optional<QByteArray> &metadata,
                                   const QString &name)
{
    RecordingReadResult out;
    QBuffer buffer;
    buffer.setData(csv);
    buffer.open(QIODevice::ReadOnly);
    Recording rec;
    if (!readCsv(buffer, name, std::numeric_limits<qint64>::max(), rec, out))
        return out;
    if (metadata)
        applyMetadata(*metadata, Recorder::metadataPath(name), rec, out.warnings);
    out.recording = std::move(rec);
    return out;
}

} // namespace hatpic
