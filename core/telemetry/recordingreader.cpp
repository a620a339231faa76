// readRecording(): a recording's CSV (and its .json) read back for replay, bounded and
// tolerant of what people feed it (docs/recording.md, "Reading a recording back").
#include "recordingreader.h"

#include "profile/paramsjson.h"
#include "telemetry/recordingformat.h"
#include "telemetry/samplecolumns.h"

#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace hatpic {

namespace {

using recording::kFormatTag;
using recording::kFormatVersion;
using recording::kMaxLineBytes;
using recording::kMaxMetadataBytes;
using recording::kMaxReadEventChars;
using recording::kMaxReadEvents;
using recording::kMaxReadSamples;
constexpr int kMaxWarnings = 20; //!< warnings a reader lists before it stops listing

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

// Columns of recordingColumns(): the sample columns (samplecolumns.h), then the event.
constexpr std::size_t kColT = sampleColumnIndex("t_s");
constexpr std::size_t kColTheta = sampleColumnIndex("theta");
constexpr std::size_t kColFlags = sampleColumnIndex("flags");
constexpr std::size_t kColEvent = kSampleColumns.size();
constexpr std::size_t kColCount = kColEvent + 1;

// The columns a multi-axis device adds (extraSampleColumns for the most axes, with the tilt):
// each axis's kAxisColumns in turn, then kTiltColumns.
constexpr std::size_t kPerAxis = kAxisColumns.size();
constexpr std::size_t kAxisExtras = kPerAxis * (kMaxAxes - 1);

//! The axis (2…) of extra column `e`; 0 for the tilt's.
int extraAxis(std::size_t e)
{
    return e < kAxisExtras ? int(e / kPerAxis) + 2 : 0;
}

//! Where extra column `e`'s value goes in `board`.
double &extraValue(BoardSample &board, std::size_t e)
{
    if (e < kAxisExtras)
        return board.more[e / kPerAxis].*kAxisColumns[e % kPerAxis].value;
    return board.*kTiltColumns[e - kAxisExtras].value;
}

void applyMetadata(const QByteArray &text, const QString &fileName, Recording &rec,
                   QStringList &warnings);

void readMetadata(const QString &csvPath, Recording &rec, QStringList &warnings)
{
    QFile file(recordingMetadataPath(csvPath));
    const QFileInfo info(file.fileName());
    if (!info.exists())
        return;
    // size() says 0 for a device (a link to /dev/zero) and a pipe: only a regular file is
    // read, and never more than the limit whatever its size claims.
    if (!info.isFile()) {
        warnings << file.fileName() + u" is not a regular file; metadata ignored.";
        return;
    }
    if (file.size() > kMaxMetadataBytes) {
        warnings << file.fileName() + u" is too large to be recording metadata; ignored.";
        return;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        warnings << u"Cannot read " % file.fileName() % u": " % file.errorString();
        return;
    }
    const QByteArray text = file.read(kMaxMetadataBytes + 1);
    if (text.size() > kMaxMetadataBytes) {
        warnings << file.fileName() + u" is too large to be recording metadata; ignored.";
        return;
    }
    applyMetadata(text, file.fileName(), rec, warnings);
}

//! Applies the metadata JSON `text` (read from `fileName`) to `rec`.
void applyMetadata(const QByteArray &text, const QString &fileName, Recording &rec,
                   QStringList &warnings)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(text, &parseError);
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
    m.device.axes = quint8(std::clamp(dev.value(u"axes").toInt(1), 1, kMaxAxes));
    m.device.tilt = dev.value(u"tilt").toBool();
    // The parameters are read as a profile's are (paramsjson.h); what is missing or not of its
    // type keeps its default, with a warning.
    const QJsonObject params = root.value(u"parameters").toObject();
    QStringList problems;
    readDeviceParams(params.value(u"device").toObject(), QStringLiteral("parameters.device."),
                     m.params, problems, nullptr);
    readHostParams(params.value(u"host").toObject(), QStringLiteral("parameters.host."), m.host,
                   problems, nullptr);
    if (const QJsonValue effects = params.value(u"effects"); effects.isObject()) {
        QStringList ignored; // unknown keys: as for the other objects, not worth a warning
        m.effects.emplace();
        readEffectParams(effects.toObject(), QStringLiteral("parameters.effects."), *m.effects,
                         problems, ignored);
    }
    if (const QJsonValue passivity = params.value(u"passivity"); passivity.isObject()) {
        QStringList ignored;
        m.passivity.emplace();
        readPassivityParams(passivity.toObject(), QStringLiteral("parameters.passivity."),
                            *m.passivity, problems, ignored);
    }
    // Bounded: the first few are named, the rest counted in one line.
    constexpr qsizetype kNamedProblems = 3;
    for (qsizetype i = 0; i < std::min(problems.size(), kNamedProblems); ++i)
        warnings << fileName % u": " % problems.at(i) % u"; the default is used.";
    if (problems.size() > kNamedProblems) {
        warnings << fileName % u": " % QString::number(problems.size() - kNamedProblems) %
                        u" more parameters missing or not numbers; their defaults are used.";
    }
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
            // Within what the CSV's rows were read for, and within the bounds on events.
            if (rec.heldUntil_s && event.t_s > *rec.heldUntil_s)
                continue;
            if (rec.events.size() >= kMaxReadEvents) {
                warnings.prepend(fileName % u": events after the first " %
                                 QString::number(kMaxReadEvents) %
                                 u" are not shown: a replay holds at most that many.");
                break;
            }
            fromMetadata.insert({event.text, event.t_s});
            rec.events.append(event);
        }
    }
    std::stable_sort(rec.events.begin(), rec.events.end(),
                     [](const auto &a, const auto &b) { return a.t_s < b.t_s; });
}

bool readCsv(QIODevice &file, const QString &name, qint64 maxBytes, Recording &rec,
             RecordingReadResult &out);

} // namespace

RecordingReadResult readRecording(const QString &csvPath, qint64 maxBytes)
{
    RecordingReadResult out;
    QFile file(csvPath);
    const QFileInfo info(csvPath);
    if (info.exists() && !info.isFile()) {
        // A pipe would block the open, a device never end: only regular files are read.
        out.error = csvPath % u" is not a regular file; a recording is a file.";
        return out;
    }
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
        applyMetadata(*metadata, recordingMetadataPath(name), rec, out.warnings);
    out.recording = std::move(rec);
    return out;
}

namespace {

//! Reads the CSV rows from `file` (opened, its size already checked) into `rec`. `name` names
//! the file in messages. False (with out.error) when the file is refused.
bool readCsv(QIODevice &file, const QString &name, qint64 maxBytes, Recording &rec,
             RecordingReadResult &out)
{
    std::array<int, kColCount> index;
    index.fill(-1);
    int columnCount = 0;
    qint64 lineNumber = 0;
    qint64 readBytes = 0;
    bool haveHeader = false;
    QList<QByteArray> fields;
    QString problem;
    const QStringList columns = recordingColumns();
    const QList<QByteArray> extraNames = extraSampleColumns(kMaxAxes, true);
    std::vector<int> extraIndex(std::size_t(extraNames.size()), -1);
    int fileAxes = 1;             //!< the most axes the header has columns for
    bool hasBoardColumns = false; //!< it has a further axis's or the tilt's
    qint64 eventChars = 0;
    bool eventsCut = false;
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
        if (const qsizetype cr = line.indexOf('\r');
            cr >= 0 && cr < line.size() - (line.endsWith("\r\n") ? 2 : 1)) {
            return fail(QStringLiteral("a carriage return inside a line: the file uses CR-only "
                                       "line ends (old Mac style); convert them to LF or CRLF"));
        }
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
                const qsizetype known = columns.indexOf(name);
                if (const qsizetype extra = known < 0 ? extraNames.indexOf(name.toUtf8()) : -1;
                    extra >= 0) {
                    int &at = extraIndex[std::size_t(extra)];
                    if (at >= 0)
                        return fail(u"column \"" % name % u"\" appears twice");
                    at = c;
                    fileAxes = std::max(fileAxes, extraAxis(std::size_t(extra)));
                    hasBoardColumns = true;
                    continue;
                }
                if (known < 0) {
                    warn(u"line 1: unknown column \"" % name % u"\" ignored.");
                    continue;
                }
                if (index[static_cast<std::size_t>(known)] >= 0)
                    return fail(u"column \"" % name % u"\" appears twice");
                index[static_cast<std::size_t>(known)] = c;
            }
            if (index[kColT] < 0 || index[kColTheta] < 0) {
                return fail(u"not a HATPIC recording: the header must name at least t_s and "
                            u"theta (expected " %
                            columns.join(u',') % u')');
            }
            for (std::size_t k = 0; k < kColEvent; ++k) {
                if (index[k] < 0 && !kSampleColumns[k].addedLater) {
                    warn(u"line 1: column \"" % columns[static_cast<qsizetype>(k)] %
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
        bool cutOff = false;
        for (std::size_t k = 0; k < kSampleColumns.size(); ++k) {
            const SampleColumn &column = kSampleColumns[k];
            if (column.isFlags())
                continue; // below, once the row's numbers are known to be whole
            const int at = index[k];
            double &value = s.*column.value;
            value = std::numeric_limits<double>::quiet_NaN();
            if (at < 0 || parseDouble(fields[at], value))
                continue;
            if (!complete) {
                cutOff = true;
                break;
            }
            return fail(u"column " % columns[static_cast<qsizetype>(k)] % u": \"" %
                        QString::fromUtf8(fields[at].left(40)) % u"\" is not a number");
        }
        if (hasBoardColumns && !cutOff) {
            auto board = std::make_shared<BoardSample>();
            board->axes = fileAxes;
            for (std::size_t e = 0; e < extraIndex.size(); ++e) {
                if (extraAxis(e) > fileAxes)
                    continue; // an axis the file does not have keeps its defaults
                double &value = extraValue(*board, e);
                value = std::numeric_limits<double>::quiet_NaN();
                const int at = extraIndex[e];
                if (at < 0 || parseDouble(fields[at], value))
                    continue;
                if (!complete) {
                    cutOff = true;
                    break;
                }
                return fail(u"column " % QString::fromUtf8(extraNames[qsizetype(e)]) % u": \"" %
                            QString::fromUtf8(fields[at].left(40)) % u"\" is not a number");
            }
            s.board = std::move(board);
        }
        if (cutOff) {
            warn(u"line " % QString::number(lineNumber) %
                 u": incomplete last line ignored (the recording was cut off).");
            break;
        }
        if (!std::isfinite(s.t_s))
            return fail(QStringLiteral("t_s must be a finite number"));
        {
            // Any finite t_s: wrap in double before converting, so that no cast overflows.
            const double us = std::fmod(std::round(s.t_s * 1e6), 4294967296.0);
            s.t_us = std::isfinite(us) ? static_cast<quint32>(static_cast<qint64>(us)) : 0;
        }
        if (const int at = index[kColFlags]; at >= 0) {
            const QByteArray text = fields[at].trimmed();
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
        if (rec.samples.size() >= kMaxReadSamples) {
            // Bounded: what a replay holds. Said first, whatever else was said.
            rec.heldUntil_s = rec.samples.constLast().t_s;
            out.warnings.prepend(
                u"Only the first " % QString::number(kMaxReadSamples) % u" samples (to t_s = " %
                QString::number(*rec.heldUntil_s, 'f', 3) % u" s) are shown: " % name %
                u" holds more, and a replay holds at most that many; the rest was not read.");
            break;
        }
        if (index[kColEvent] >= 0 && !fields[index[kColEvent]].isEmpty() && !eventsCut) {
            const QString event = QString::fromUtf8(fields[index[kColEvent]]);
            eventsCut = rec.events.size() >= kMaxReadEvents ||
                        eventChars + event.size() > kMaxReadEventChars;
            if (eventsCut) {
                out.warnings.prepend(u"Events from line " % QString::number(lineNumber) %
                                     u" on are not shown: a replay holds at most " %
                                     QString::number(kMaxReadEvents) % u" events and " %
                                     QString::number(kMaxReadEventChars) %
                                     u" characters of their text.");
            } else {
                eventChars += event.size();
                rec.events.append({s.t_s, event});
            }
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

} // namespace hatpic
