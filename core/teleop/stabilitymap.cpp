#include "teleop/stabilitymap.h"

#include "model/paramtable.h"
#include "telemetry/numbertext.h"

#include <QStringList>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <thread>

namespace hatpic::teleop {

namespace {

constexpr double kNaN = LoopResult::kNaN;

std::optional<double> number(const QString &text)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

//! Text a person gave, cut as every message quotes it.
QString echoed(const QString &text)
{
    return QString::fromStdString(echoedText(text.toStdString()));
}

QString fromView(std::string_view v)
{
    return QString::fromUtf8(v.data(), qsizetype(v.size()));
}

//! Where a field lives in a LoopConfig.
struct FieldPlace
{
    double *value = nullptr;
};

FieldPlace placeOf(LoopConfig &config, const QString &name)
{
    for (const DeviceFieldSpec &f : kDeviceFields) {
        if (fromView(f.name) == name)
            return {&(config.device.*f.member)};
    }
    for (const HostFieldSpec &f : kHostFields) {
        if (fromView(f.name) == name)
            return {&(config.host.*f.member)};
    }
    for (const PassivityFieldSpec &f : kPassivityFields) {
        if (fromView(f.name) == name)
            return {&(config.passivity.*f.member)};
    }
    return {};
}

//! A value a range generated, without the last bits' rounding noise (0.045, not
//! 0.045000000000000005): 12 significant digits.
double tidy(double v)
{
    return QString::number(v, 'g', 12).toDouble();
}

QString cellText(double v)
{
    return std::isfinite(v) ? compactNumberText(v) : QString();
}

} // namespace

std::optional<std::vector<double>> parseValueList(const QString &text, QString *error)
{
    const auto fail = [error](const QString &why) -> std::optional<std::vector<double>> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    std::vector<double> out;
    const QStringList items = text.split(u',');
    for (const QString &raw : items) {
        const QString item = raw.trimmed();
        if (item.isEmpty())
            return fail(u"needs numbers separated by commas, got an empty item in '" +
                        echoed(text) + u"'");
        const QStringList parts = item.split(u':');
        if (parts.size() == 1) {
            const auto v = number(item);
            if (!v)
                return fail(u"needs a number, got '" + echoed(item) + u"'");
            out.push_back(*v);
        } else if (parts.size() == 2 || parts.size() == 3) {
            // FROM:TO/N or FROM:TO:STEP
            QString toText = parts[1];
            std::optional<int> count;
            if (parts.size() == 2) {
                const qsizetype slash = toText.indexOf(u'/');
                if (slash < 0)
                    return fail(u"needs FROM:TO:STEP or FROM:TO/N, got '" + echoed(item) + u"'");
                bool ok = false;
                const int n = toText.mid(slash + 1).trimmed().toInt(&ok);
                if (!ok || n < 2 || n > kMaxListValues)
                    return fail(u"needs N from 2 to " + QString::number(kMaxListValues) +
                                u" in FROM:TO/N, got '" + echoed(item) + u"'");
                count = n;
                toText = toText.left(slash);
            }
            const auto from = number(parts[0]);
            const auto to = number(toText);
            if (!from || !to)
                return fail(u"needs numbers for FROM and TO, got '" + echoed(item) + u"'");
            if (*to < *from)
                return fail(u"needs FROM ≤ TO, got '" + echoed(item) + u"'");
            if (count) {
                for (int i = 0; i < *count; ++i)
                    out.push_back(tidy(*from + (*to - *from) * i / (*count - 1)));
            } else {
                const auto step = number(parts[2]);
                if (!step || *step <= 0)
                    return fail(u"needs a STEP above 0 in FROM:TO:STEP, got '" + echoed(item) +
                                u"'");
                const double span = (*to - *from) / *step;
                if (span + 1 > kMaxListValues)
                    return fail(u"gives more than " + QString::number(kMaxListValues) +
                                u" values, got '" + echoed(item) + u"'");
                const int n = int(std::floor(span + 1e-9)) + 1;
                for (int i = 0; i < n; ++i)
                    out.push_back(tidy(*from + *step * i));
            }
        } else {
            return fail(u"needs a number, FROM:TO:STEP or FROM:TO/N, got '" + echoed(item) + u"'");
        }
        if (out.size() > std::size_t(kMaxListValues))
            return fail(u"gives more than " + QString::number(kMaxListValues) + u" values");
    }
    return out;
}

QStringList mapFieldNames()
{
    QStringList names;
    for (const DeviceFieldSpec &f : kDeviceFields)
        names.append(fromView(f.name));
    for (const HostFieldSpec &f : kHostFields)
        names.append(fromView(f.name));
    for (const PassivityFieldSpec &f : kPassivityFields)
        names.append(fromView(f.name));
    return names;
}

std::optional<double> fieldValue(const LoopConfig &config, const QString &name)
{
    LoopConfig copy = config;
    const FieldPlace place = placeOf(copy, name);
    if (!place.value)
        return std::nullopt;
    return *place.value;
}

bool setFieldValue(LoopConfig &config, const QString &name, double value)
{
    const FieldPlace place = placeOf(config, name);
    if (!place.value)
        return false;
    *place.value = value;
    return true;
}

qsizetype MapSpec::cellCount() const
{
    const qsizetype fields = field.name.isEmpty() ? 1 : qsizetype(field.values.size());
    const qsizetype handCount = hands.empty() ? 1 : qsizetype(hands.size());
    return qsizetype(delays.size()) * qsizetype(gains.size()) * handCount * fields;
}

LoopConfig MapSpec::cellConfig(qsizetype index) const
{
    LoopConfig c = base;
    const qsizetype nd = qsizetype(delays.size());
    const qsizetype ng = qsizetype(gains.size());
    const qsizetype nh = hands.empty() ? 1 : qsizetype(hands.size());
    c.robot.faults.delay = delays[std::size_t(index % nd)];
    c.feedback.gain = gains[std::size_t((index / nd) % ng)];
    if (!hands.empty())
        c.hand = {HandInput::Kind::Constant, hands[std::size_t((index / (nd * ng)) % nh)]};
    if (!field.name.isEmpty())
        setFieldValue(c, field.name, field.values[std::size_t(index / (nd * ng * nh))]);
    return c;
}

QString checkSpec(const MapSpec &spec)
{
    if (spec.delays.empty() || spec.gains.empty())
        return QStringLiteral("The map needs at least one delay and one gain.");
    if (!spec.field.name.isEmpty()) {
        if (!fieldValue(spec.base, spec.field.name))
            return u"There is no tuning field '" + echoed(spec.field.name) + u"'; one of " +
                   mapFieldNames().join(u", ") + u'.';
        if (spec.field.values.empty())
            return u"The field " + spec.field.name + u" needs at least one value.";
    }
    if (spec.threads < 1 || spec.threads > kMaxMapThreads)
        return u"threads must be from 1 to " + QString::number(kMaxMapThreads) + u", got " +
               QString::number(spec.threads) + u'.';
    const double cells = double(spec.delays.size()) * double(spec.gains.size()) *
                         double(spec.hands.empty() ? 1 : spec.hands.size()) *
                         double(spec.field.name.isEmpty() ? 1 : spec.field.values.size());
    if (cells > double(kMaxMapCells))
        return u"The map would have " + compactNumberText(cells) + u" cells, more than " +
               QString::number(kMaxMapCells) + u'.';
    // Each value once: a cell is bad when its delay, gain or field value is.
    for (double d : spec.delays) {
        LoopConfig c = spec.base;
        c.robot.faults.delay = d;
        if (const QString p = LoopSimulation::check(c); !p.isEmpty())
            return p;
    }
    for (double g : spec.gains) {
        LoopConfig c = spec.base;
        c.feedback.gain = g;
        if (const QString p = LoopSimulation::check(c); !p.isEmpty())
            return p;
    }
    for (double h : spec.hands) {
        LoopConfig c = spec.base;
        c.hand = {HandInput::Kind::Constant, h};
        if (const QString p = LoopSimulation::check(c); !p.isEmpty())
            return u"hand " + compactNumberText(h) + u" N·m: " + p;
    }
    for (double v : spec.field.values) {
        LoopConfig c = spec.base;
        setFieldValue(c, spec.field.name, v);
        if (const QString p = LoopSimulation::check(c); !p.isEmpty())
            return p;
    }
    return LoopSimulation::check(spec.base);
}

std::vector<MapCell> runMap(const MapSpec &spec,
                            const std::function<void(qsizetype, qsizetype)> &progress,
                            const std::atomic<bool> *cancel)
{
    const qsizetype total = spec.cellCount();
    std::vector<MapCell> cells{std::size_t(total), MapCell{}};
    std::vector<char> ran(std::size_t(total), 0);
    std::atomic<qsizetype> next{0};
    std::atomic<qsizetype> done{0};
    const auto work = [&] {
        for (;;) {
            if (cancel && cancel->load())
                return;
            const qsizetype i = next.fetch_add(1);
            if (i >= total)
                return;
            const LoopConfig c = spec.cellConfig(i);
            MapCell &cell = cells[std::size_t(i)];
            cell.delay = c.robot.faults.delay;
            cell.gain = c.feedback.gain;
            cell.hand = c.hand.kind == HandInput::Kind::Constant ? c.hand.amplitude : kNaN;
            cell.field = spec.field.name.isEmpty() ? kNaN : *fieldValue(c, spec.field.name);
            cell.pc = c.passivity.pc_damping_max;
            cell.contacts = LoopSimulation::runContacts(c);
            cell.result = LoopSimulation::worst(cell.contacts);
            ran[std::size_t(i)] = 1;
            const qsizetype n = ++done;
            if (progress)
                progress(n, total);
        }
    };
    const int threads = int(std::min<qsizetype>(spec.threads, total));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread &t : pool)
        t.join();
    std::vector<MapCell> out;
    out.reserve(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (ran[i])
            out.push_back(cells[i]);
    }
    return out;
}

QByteArray mapCsv(const std::vector<MapCell> &cells, const QString &fieldName)
{
    const bool extra = !fieldName.isEmpty() && fieldName != u"pc_damping_max";
    QByteArray out = "delay,gain,pc,";
    if (extra)
        out += fieldName.toUtf8() + ',';
    out += "settled,settle_s,p2p,rms_tau_pc_ratio,dissipated_j,theta_rest,tau_ext_rest,x_rest,"
           "contact_s,hand,contact,damped_at_rest,theta_eq\n";
    for (const MapCell &c : cells) {
        for (const LoopResult &r : c.contacts) {
            QStringList row{compactNumberText(c.delay), compactNumberText(c.gain),
                            compactNumberText(c.pc)};
            if (extra)
                row.append(cellText(c.field));
            row << (r.settled ? QStringLiteral("1") : QStringLiteral("0")) << cellText(r.settleS)
                << cellText(r.p2p) << cellText(r.rmsTauPcRatio) << cellText(r.dissipatedJ)
                << cellText(r.thetaRest) << cellText(r.tauExtRest) << cellText(r.xRest)
                << cellText(r.contactAt) << cellText(c.hand) << QString::number(r.index)
                << cellText(r.dampedAtRest) << cellText(r.thetaEq);
            out += row.join(u',').toUtf8() + '\n';
        }
    }
    return out;
}

namespace {

//! Viridis at five stops, interpolated: 0 (fast, dark purple) … 1 (slow, yellow).
QString colourAt(double f)
{
    static constexpr std::array<std::array<double, 3>, 5> kStops = {
        {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
    f = std::clamp(std::isfinite(f) ? f : 1.0, 0.0, 1.0) * 4;
    const int i = std::min(3, int(f));
    const double u = f - i;
    QString out = QStringLiteral("#");
    for (int k = 0; k < 3; ++k) {
        const int v = int(std::lround(kStops[i][k] + (kStops[i + 1][k] - kStops[i][k]) * u));
        out += QStringLiteral("%1").arg(v, 2, 16, QLatin1Char('0'));
    }
    return out;
}

QString esc(QString s)
{
    return s.replace(u'&', QStringLiteral("&amp;"))
        .replace(u'<', QStringLiteral("&lt;"))
        .replace(u'>', QStringLiteral("&gt;"));
}

std::vector<double> distinct(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

//! Position of `v` along sorted `axis` as a fractional index (clamped to the ends).
double indexOf(const std::vector<double> &axis, double v)
{
    if (axis.size() < 2 || v <= axis.front())
        return 0;
    if (v >= axis.back())
        return double(axis.size() - 1);
    const auto it = std::upper_bound(axis.begin(), axis.end(), v);
    const std::size_t hi = std::size_t(it - axis.begin());
    const double a = axis[hi - 1], b = axis[hi];
    return double(hi - 1) + (v - a) / (b - a);
}

} // namespace

QByteArray mapSvg(const std::vector<MapCell> &cells, const QString &fieldName, double duration,
                  const std::optional<MapMark> &mark)
{
    std::vector<double> delays, gains, fields, hands;
    for (const MapCell &c : cells) {
        delays.push_back(c.delay);
        gains.push_back(c.gain);
        fields.push_back(fieldName.isEmpty() ? 0.0 : c.field);
        if (std::isfinite(c.hand))
            hands.push_back(c.hand);
    }
    delays = distinct(delays);
    gains = distinct(gains);
    fields = distinct(fields);
    hands = distinct(hands);
    if (fields.empty())
        fields.push_back(0);
    // A panel per field value and hand; the hand is named only when the map has several.
    const bool perHand = hands.size() > 1;
    if (!perHand)
        hands.assign(1, kNaN);
    struct Panel
    {
        double field, hand;
    };
    std::vector<Panel> panels;
    for (double f : fields) {
        for (double h : hands)
            panels.push_back({f, h});
    }

    constexpr double kPanelW = 320, kPanelH = 260, kLeft = 90, kTop = 40, kGap = 30;
    constexpr double kBottom = 60, kLegendW = 110;
    const double width = kLeft + double(panels.size()) * (kPanelW + kGap) + kLegendW;
    const double height = kTop + kPanelH + kBottom;
    const double cw = kPanelW / double(std::max<std::size_t>(1, delays.size()));
    const double ch = kPanelH / double(std::max<std::size_t>(1, gains.size()));

    QString s;
    const auto num = [](double v) { return QString::number(v, 'f', 1); };
    s += u"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + u"\" height=\"" +
         num(height) + u"\" viewBox=\"0 0 " + num(width) + u' ' + num(height) +
         u"\" font-family=\"sans-serif\" font-size=\"11\">\n";
    s += u"<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for (std::size_t p = 0; p < panels.size(); ++p) {
        const Panel &panel = panels[p];
        const double x0 = kLeft + double(p) * (kPanelW + kGap);
        QStringList titles;
        if (!fieldName.isEmpty())
            titles.append(esc(fieldName) + u" = " + compactNumberText(panel.field));
        if (perHand)
            titles.append(u"hand " + compactNumberText(panel.hand) + u" N·m");
        const QString title =
            titles.isEmpty() ? QStringLiteral("stability map") : titles.join(u", ");
        s += u"<text x=\"" + num(x0 + kPanelW / 2) + u"\" y=\"" + num(kTop - 12) +
             u"\" text-anchor=\"middle\" font-size=\"13\">" + title + u"</text>\n";
        for (const MapCell &c : cells) {
            if ((!fieldName.isEmpty() && c.field != panel.field) ||
                (perHand && c.hand != panel.hand))
                continue;
            const double cx = x0 + indexOf(delays, c.delay) * cw;
            const double cy = kTop + kPanelH - (indexOf(gains, c.gain) + 1) * ch;
            const LoopResult &r = c.result;
            const QString fill =
                r.settled ? colourAt(r.settleS / duration) : QStringLiteral("#c8c8c8");
            s += u"<rect x=\"" + num(cx) + u"\" y=\"" + num(cy) + u"\" width=\"" + num(cw) +
                 u"\" height=\"" + num(ch) + u"\" fill=\"" + fill +
                 u"\" stroke=\"white\" stroke-width=\"1\"><title>delay " +
                 compactNumberText(c.delay) + u" s, gain " + compactNumberText(c.gain) + u": " +
                 (r.settled ? QString(u"settled in " + compactNumberText(r.settleS) + u" s")
                            : QString(u"not settled, θ p2p " + cellText(r.p2p) + u" rad")) +
                 (c.contacts.size() > 1 ? u" (contact " + QString::number(r.index) + u" of " +
                                              QString::number(c.contacts.size()) + u", the worst)"
                                        : QString()) +
                 u"</title></rect>\n";
            if (!r.settled) {
                const double m = std::min(cw, ch) * 0.25;
                const double mx = cx + cw / 2, my = cy + ch / 2;
                s += u"<path d=\"M" + num(mx - m) + u' ' + num(my - m) + u" L" + num(mx + m) +
                     u' ' + num(my + m) + u" M" + num(mx - m) + u' ' + num(my + m) + u" L" +
                     num(mx + m) + u' ' + num(my - m) +
                     u"\" stroke=\"#707070\" stroke-width=\"1.5\"/>\n";
            }
        }
        // Axes: a tick per value, thinned to about eight.
        const auto stride = [](std::size_t n) { return std::max<std::size_t>(1, (n + 7) / 8); };
        for (std::size_t i = 0; i < delays.size(); i += stride(delays.size())) {
            s += u"<text x=\"" + num(x0 + (double(i) + 0.5) * cw) + u"\" y=\"" +
                 num(kTop + kPanelH + 15) + u"\" text-anchor=\"middle\">" +
                 compactNumberText(delays[i]) + u"</text>\n";
        }
        s += u"<text x=\"" + num(x0 + kPanelW / 2) + u"\" y=\"" + num(kTop + kPanelH + 35) +
             u"\" text-anchor=\"middle\">one-way delay [s]</text>\n";
        if (p == 0) {
            for (std::size_t i = 0; i < gains.size(); i += stride(gains.size())) {
                s += u"<text x=\"" + num(x0 - 6) + u"\" y=\"" +
                     num(kTop + kPanelH - (double(i) + 0.5) * ch + 4) + u"\" text-anchor=\"end\">" +
                     compactNumberText(gains[i]) + u"</text>\n";
            }
            s += u"<text transform=\"translate(16 " + num(kTop + kPanelH / 2) +
                 u") rotate(-90)\" text-anchor=\"middle\">feedback gain [N·m/N]</text>\n";
        }
        s += u"<rect x=\"" + num(x0) + u"\" y=\"" + num(kTop) + u"\" width=\"" + num(kPanelW) +
             u"\" height=\"" + num(kPanelH) + u"\" fill=\"none\" stroke=\"#404040\"/>\n";
        if (mark &&
            (fieldName.isEmpty() || !std::isfinite(mark->field) || mark->field == panel.field) &&
            (!perHand || !std::isfinite(mark->hand) || mark->hand == panel.hand)) {
            const double mx = x0 + (indexOf(delays, mark->delay) + 0.5) * cw;
            const double my = kTop + kPanelH - (indexOf(gains, mark->gain) + 0.5) * ch;
            const double rad = std::max(5.0, std::min(cw, ch) * 0.3);
            s += u"<circle cx=\"" + num(mx) + u"\" cy=\"" + num(my) + u"\" r=\"" + num(rad) +
                 u"\" fill=\"none\" stroke=\"#e8175d\" stroke-width=\"3\"><title>the settings "
                 u"in use</title></circle>\n";
        }
    }
    // Legend: the settle-time scale and "not settled".
    const double lx = width - kLegendW + 10;
    s += u"<text x=\"" + num(lx) + u"\" y=\"" + num(kTop - 12) + u"\">settle time [s]</text>\n";
    constexpr int kSteps = 20;
    for (int i = 0; i < kSteps; ++i) {
        const double f = double(i) / (kSteps - 1);
        s += u"<rect x=\"" + num(lx) + u"\" y=\"" + num(kTop + 150 * f) +
             u"\" width=\"18\" height=\"" + num(150.0 / kSteps + 0.5) + u"\" fill=\"" +
             colourAt(f) + u"\"/>\n";
    }
    s += u"<text x=\"" + num(lx + 24) + u"\" y=\"" + num(kTop + 8) + u"\">0</text>\n";
    s += u"<text x=\"" + num(lx + 24) + u"\" y=\"" + num(kTop + 155) + u"\">" +
         compactNumberText(duration) + u"</text>\n";
    s += u"<rect x=\"" + num(lx) + u"\" y=\"" + num(kTop + 180) +
         u"\" width=\"18\" height=\"14\" fill=\"#c8c8c8\"/>\n";
    s += u"<text x=\"" + num(lx + 24) + u"\" y=\"" + num(kTop + 191) + u"\">not settled</text>\n";
    if (mark) {
        s += u"<circle cx=\"" + num(lx + 9) + u"\" cy=\"" + num(kTop + 215) +
             u"\" r=\"6\" fill=\"none\" stroke=\"#e8175d\" stroke-width=\"3\"/>\n";
        s += u"<text x=\"" + num(lx + 24) + u"\" y=\"" + num(kTop + 219) + u"\">in use</text>\n";
    }
    s += u"</svg>\n";
    return s.toUtf8();
}

} // namespace hatpic::teleop
