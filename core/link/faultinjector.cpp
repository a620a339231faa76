#include "faultinjector.h"

#include "protocol/messages.h"

#include <QStringBuilder>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

constexpr quint64 kToHostStream = 0x9E3779B97F4A7C15ULL; // separates the two directions' draws
constexpr quint64 kToDeviceStream = 0xC2B2AE3D27D4EB4FULL;

QString itemError(const QString &item, const QString &rule, const QString &value)
{
    return u"Fault spec item \"" % item % u"\": " % rule % u", got \"" % value % u"\".";
}

std::optional<double> number(const QString &text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value))
        return std::nullopt;
    return value;
}

// "20ms", "2s", "1.5s" → seconds; nothing when the unit is missing or the number is bad.
std::optional<double> duration(const QString &text)
{
    if (text.endsWith(u"ms")) {
        if (const auto v = number(text.chopped(2)))
            return *v / 1000.0;
    } else if (text.endsWith(u's')) {
        return number(text.chopped(1));
    }
    return std::nullopt;
}

QString durationText(double seconds)
{
    if (seconds < 1)
        return QString::number(seconds * 1000.0, 'g', 12) % u"ms";
    return QString::number(seconds, 'g', 12) % u's';
}

QString laneText(const FaultSpec::Lane &lane, const QString &prefix)
{
    QStringList items;
    if (lane.drop > 0)
        items << prefix % u"drop=" % QString::number(lane.drop, 'g', 12);
    if (lane.corrupt > 0)
        items << prefix % u"corrupt=" % QString::number(lane.corrupt, 'g', 12);
    if (lane.dup > 0)
        items << prefix % u"dup=" % QString::number(lane.dup, 'g', 12);
    if (lane.delay > 0)
        items << prefix % u"delay=" % QString::number(lane.delay, 'g', 12) % u':' %
                     durationText(lane.delaySeconds);
    return items.join(u',');
}

} // namespace

std::optional<FaultSpec> FaultSpec::parse(const QString &text, QString *error)
{
    auto fail = [error](const QString &message) -> std::optional<FaultSpec> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    if (text.trimmed().isEmpty())
        return fail(QStringLiteral("The fault spec is empty; give items such as "
                                   "\"drop=0.01,cut=30s:2s\"."));
    FaultSpec spec;
    QStringList seen;
    const QStringList items = text.split(u',');
    for (const QString &item : items) {
        const qsizetype eq = item.indexOf(u'=');
        if (eq <= 0)
            return fail(itemError(item, QStringLiteral("an item is name=value"), item));
        const QString name = item.left(eq).trimmed();
        const QString value = item.mid(eq + 1).trimmed();
        const bool host = name.startsWith(u'h') && name != u"h";
        const QString field = host ? name.mid(1) : name;
        Lane &lane = host ? spec.toDevice : spec.toHost;
        static const QStringList probabilities = {QStringLiteral("drop"), QStringLiteral("corrupt"),
                                                  QStringLiteral("dup")};
        if (name != u"cut" && seen.contains(name))
            return fail(itemError(item, name % u" may be given once", value));
        seen << name;
        auto probability = [&](const QString &v) -> std::optional<double> {
            const auto p = number(v);
            if (!p || *p < 0 || *p > 1)
                return std::nullopt;
            return p;
        };
        if (probabilities.contains(field)) {
            const auto p = probability(value);
            if (!p)
                return fail(itemError(item, name % u" is a probability from 0 to 1", value));
            (field == u"drop" ? lane.drop : field == u"corrupt" ? lane.corrupt : lane.dup) = *p;
        } else if (field == u"delay") {
            const QStringList parts = value.split(u':');
            const auto p = parts.size() == 2 ? probability(parts[0]) : std::nullopt;
            if (!p)
                return fail(
                    itemError(item,
                              name % u" is probability:duration, e.g. 0.01:20ms, the probability "
                                     u"from 0 to 1",
                              value));
            const auto d = duration(parts[1]);
            if (!d || *d <= 0 || *d > kMaxDelaySeconds)
                return fail(itemError(item,
                                      name % u"'s duration is above 0 and at most " %
                                          QString::number(kMaxDelaySeconds) %
                                          u" s, with its unit (ms or s)",
                                      parts[1]));
            lane.delay = *p;
            lane.delaySeconds = *d;
        } else if (name == u"cut") {
            const QStringList parts = value.split(u':');
            const auto at = parts.size() == 2 ? duration(parts[0]) : std::nullopt;
            if (!at || *at < 0)
                return fail(itemError(item,
                                      QStringLiteral("cut is start:length, e.g. 30s:2s, the "
                                                     "start at or after 0 with its unit "
                                                     "(ms or s)"),
                                      value));
            const auto length = duration(parts[1]);
            if (!length || *length <= 0)
                return fail(itemError(
                    item, QStringLiteral("a cut's length is above 0, with its unit (ms or s)"),
                    parts[1]));
            if (spec.cuts.size() >= std::size_t(kMaxCuts))
                return fail(itemError(
                    item, u"at most " % QString::number(kMaxCuts) % u" cuts fit in one spec",
                    value));
            spec.cuts.push_back({*at, *length});
        } else {
            return fail(itemError(item,
                                  QStringLiteral("the names are drop, corrupt, dup, delay, cut "
                                                 "and, host to device, hdrop, hcorrupt, hdup, "
                                                 "hdelay"),
                                  name));
        }
    }
    return spec;
}

QString FaultSpec::toString() const
{
    QStringList items;
    if (const QString t = laneText(toHost, {}); !t.isEmpty())
        items << t;
    for (const Cut &cut : cuts)
        items << u"cut=" % durationText(cut.at) % u':' % durationText(cut.seconds);
    if (const QString t = laneText(toDevice, QStringLiteral("h")); !t.isEmpty())
        items << t;
    return items.join(u',');
}

FaultCounts &FaultCounts::operator+=(const FaultCounts &o)
{
    frames += o.frames;
    dropped += o.dropped;
    corrupted += o.corrupted;
    duplicated += o.duplicated;
    delayed += o.delayed;
    cut += o.cut;
    unframed += o.unframed;
    streamLost += o.streamLost;
    streamCorrupted += o.streamCorrupted;
    streamDuplicated += o.streamDuplicated;
    return *this;
}

QString describeFaultCounts(const FaultCounts &c)
{
    return u"frames=" % QString::number(c.frames) % u" dropped=" % QString::number(c.dropped) %
           u" corrupted=" % QString::number(c.corrupted) % u" duplicated=" %
           QString::number(c.duplicated) % u" delayed=" % QString::number(c.delayed) % u" cut=" %
           QString::number(c.cut) % u" stream_lost=" % QString::number(c.streamLost) %
           u" stream_corrupted=" % QString::number(c.streamCorrupted) % u" stream_duplicated=" %
           QString::number(c.streamDuplicated) % u" unframed_bytes=" % QString::number(c.unframed);
}

FaultInjector::FaultInjector(const FaultSpec &spec, quint64 seed, Framing framing)
    : m_spec(spec), m_delimiter(framing == Framing::V2 ? '\0' : '\n'),
      m_toHost(spec.toHost, *this, seed ^ kToHostStream),
      m_toDevice(spec.toDevice, *this, seed ^ kToDeviceStream)
{}

bool FaultInjector::cutAt(double now) const
{
    return std::any_of(m_spec.cuts.begin(), m_spec.cuts.end(), [now](const FaultSpec::Cut &c) {
        return now >= c.at && now < c.at + c.seconds;
    });
}

QString FaultInjector::summary() const
{
    return u"injected device→host: " % describeFaultCounts(toHostCounts()) %
           u"\ninjected host→device: " % describeFaultCounts(toDeviceCounts()) %
           u"\nseen device→host: " % describeFaultCounts(toHostSeen()) % u"\nseen host→device: " %
           describeFaultCounts(toDeviceSeen());
}

FaultInjector::Lane::Lane(const FaultSpec::Lane &faults, const FaultInjector &owner, quint64 seed)
    : m_faults(faults), m_owner(owner), m_random(seed)
{}

double FaultInjector::Lane::draw()
{
    // 53 random bits as a double in [0, 1): the same numbers on every standard library.
    return double(m_random() >> 11) * 0x1.0p-53;
}

QByteArray FaultInjector::Lane::pass(QByteArrayView bytes, double now)
{
    for (;;) {
        const qsizetype end = bytes.indexOf(m_owner.m_delimiter);
        if (end < 0)
            break;
        m_partial.append(bytes.first(end + 1));
        frame(std::exchange(m_partial, {}), now);
        bytes = bytes.sliced(end + 1);
    }
    m_partial.append(bytes);
    if (m_partial.size() > kMaxFrameBytes) {
        // No frame this long exists: pass the run on as it is rather than hold it forever.
        FaultCounts outcome;
        outcome.unframed = quint64(m_partial.size());
        m_counts.unframed += outcome.unframed;
        hold(std::exchange(m_partial, {}), now, outcome);
    }
    QByteArray out;
    // Bounded: when more than kMaxHeldBytes wait, everything goes now, early.
    const bool overfull = m_heldBytes > kMaxHeldBytes;
    while (!m_held.empty() && (overfull || m_held.front().release <= now)) {
        Held &held = m_held.front();
        out.append(held.bytes);
        m_seen += held.outcome;
        m_heldBytes -= held.bytes.size();
        m_held.pop_front();
    }
    return out;
}

bool FaultInjector::Lane::isStream(const QByteArray &frame) const
{
    if (m_owner.m_delimiter != '\0')
        return true; // legacy: every line is a telemetry frame or boot text
    // The packet's first byte is its type: the first data byte when the first COBS code
    // byte is above 1.
    return frame.size() > 2 && quint8(frame[0]) > 1 &&
           quint8(frame[1]) == quint8(v2::MessageType::Telemetry);
}

void FaultInjector::Lane::frame(QByteArray frame, double now)
{
    if (frame.size() <= 1) { // a lone delimiter (e.g. the one leading a HELLO)
        if (!m_owner.cutAt(now))
            hold(std::move(frame), now);
        return;
    }
    const bool stream = isStream(frame);
    FaultCounts outcome;
    outcome.frames = 1;
    // Five draws for every frame, used or not, so one frame's fate never shifts another's.
    const double dropDraw = draw();
    const double corruptDraw = draw();
    const double dupDraw = draw();
    const double delayDraw = draw();
    const double bitDraw = draw();
    if (m_owner.cutAt(now) || dropDraw < m_faults.drop) {
        (m_owner.cutAt(now) ? outcome.cut : outcome.dropped) = 1;
        outcome.streamLost = stream ? 1 : 0;
        m_counts += outcome;
        m_unseenLoss += outcome;
        return;
    }
    double release = now;
    if (delayDraw < m_faults.delay) {
        outcome.delayed = 1;
        release = now + m_faults.delaySeconds;
    }
    // A corrupted frame is not also duplicated: each corruption is one frame the receiver
    // rejects, so the counts compare one to one.
    FaultCounts copy;
    if (corruptDraw < m_faults.corrupt && corrupt(frame, bitDraw)) {
        outcome.corrupted = 1;
        outcome.streamCorrupted = stream ? 1 : 0;
    } else if (dupDraw < m_faults.dup) {
        copy.duplicated = 1;
        copy.streamDuplicated = stream ? 1 : 0;
    }
    m_counts += outcome;
    m_counts += copy;
    outcome += std::exchange(m_unseenLoss, {});
    hold(frame, release, outcome);
    if (copy.duplicated)
        hold(std::move(frame), release, copy);
}
bool FaultInjector::Lane::corrupt(QByteArray &frame, double draw) const
{
    // Flip one bit of a byte that carries data: never the delimiter, never a COBS code byte
    // (v2), and never so that the byte becomes the delimiter. The frame keeps its shape and
    // only its content is wrong, which a v2 receiver's CRC always detects.
    std::vector<qsizetype> candidates;
    const qsizetype body = frame.size() - 1;
    qsizetype nextCode = 0;
    for (qsizetype i = 0; i < body; ++i) {
        if (m_owner.m_delimiter == '\0' && i == nextCode) {
            nextCode = i + std::max(1, int(quint8(frame[i])));
            continue;
        }
        candidates.push_back(i);
    }
    if (candidates.empty())
        return false;
    const auto pick = std::min<std::size_t>(candidates.size() * 8 - 1,
                                            std::size_t(draw * double(candidates.size() * 8)));
    const qsizetype index = candidates[pick / 8];
    int bit = int(pick % 8);
    char flipped = char(quint8(frame[index]) ^ (1u << bit));
    if (flipped == m_owner.m_delimiter) {
        bit = (bit + 1) % 8;
        flipped = char(quint8(frame[index]) ^ (1u << bit));
    }
    frame[index] = flipped;
    return true;
}

void FaultInjector::Lane::hold(QByteArray bytes, double release, const FaultCounts &outcome)
{
    // Head of line: nothing overtakes a held frame, as on a link that stalled.
    if (!m_held.empty())
        release = std::max(release, m_held.back().release);
    m_heldBytes += bytes.size();
    m_held.push_back({std::move(bytes), release, outcome});
}

} // namespace hatpic
