// hatpicctl teleop-map: the stability map of the teleoperation loop — one-way delay × feedback
// gain (× one tuning field), each cell the whole loop run in process on virtual time
// (docs/teleop.md § The stability map).
#include "common/exitcodes.h"
#include "console.h"
#include "profileinput.h"
#include "rasterimage.h"
#include "subcommand.h"
#include "subcommands.h"

#include "telemetry/numbertext.h"
#include "teleop/stabilitymap.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSaveFile>
#include <QThread>

#include <cmath>
#include <optional>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

constexpr auto kDefaultDelays = u"0,0.04,0.08,0.12,0.15,0.2,0.3";
constexpr auto kDefaultGains = u"0.02";

//! Why `path` cannot be written (a folder that is missing or not writable, a folder in its
//! place, a file there without --force); empty when it can.
QString outputProblem(const QString &option, const QString &path, bool force)
{
    if (path.isEmpty())
        return u"--" + option + u" needs a file name."_s;
    const QFileInfo info(path);
    if (info.isDir())
        return u"--" + option + u" " + path + u" is a folder."_s;
    if (info.exists() && !force)
        return u"--" + option + u" " + path + u" exists; add --force to overwrite it."_s;
    const QFileInfo folder(info.absolutePath());
    if (!folder.isDir())
        return u"--" + option + u" " + path + u": the folder " + folder.filePath() +
               u" does not exist."_s;
    if (!folder.isWritable())
        return u"--" + option + u" " + path + u": the folder " + folder.filePath() +
               u" is not writable."_s;
    return {};
}

//! Writes `bytes` to `path` through a temporary file renamed into place.
bool writeFile(const QString &path, const QByteArray &bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        printError(u"Cannot write "_s + path + u": "_s + file.errorString() + u'.');
        return false;
    }
    return true;
}

QString cell(double v, int width, int precision = 3)
{
    const QString text = std::isfinite(v) ? QString::number(v, 'f', precision) : u"-"_s;
    return text.rightJustified(width);
}

class TeleopMapSubcommand final : public Subcommand
{
public:
    TeleopMapSubcommand()
        : Subcommand(
              {.name = u"teleop-map"_s,
               .summary =
                   u"Map where the teleoperation loop settles: one-way delay × feedback gain."_s,
               .synopsis =
                   u"teleop-map [--profile FILE] [--delays LIST] [--gains LIST] "
                   u"[--pc LIST | --vary FIELD=LIST] [--hand LIST | --hand SPEC] [--contacts N] "
                   u"[--duration S] [--seed N] [--jitter S] [--loss P] [--threads N] "
                   u"[--csv FILE] [--svg FILE] [--png FILE] [--force]"_s,
               .description =
                   u"Runs robot.md's teleoperation loop in process, on virtual time, for every\n"
                   u"one-way delay and feedback gain (and every hand and every value of one\n"
                   u"tuning field): the simulated joystick with the profile's tuning and the\n"
                   u"hand, the bridge (--component force.x at the gain, its 100 Hz twist), the\n"
                   u"network's delay, jitter and loss both ways, and hatpic-robot-sim's robot\n"
                   u"(200 Hz wrench). No device, no ROS. Prints one row per cell and contact:\n"
                   u"  settled   1 when every θ of the last 2 s lies within 0.003 rad of\n"
                   u"            robot.md's equilibrium\n"
                   u"  settle_s  from the first cycle with tau_ext ≠ 0 to the last one with\n"
                   u"            |θ − θ_eq| > 0.003 rad (passivity.md)\n"
                   u"  p2p       θ's peak to peak over the last 2 s [rad]\n"
                   u"  rms_tau_pc_ratio, dissipated_j  the passivity controller's price:\n"
                   u"            RMS(tau_pc) / RMS(tau_ext) from contact to rest, the energy it\n"
                   u"            took out [J]\n"
                   u"  damped_rest  the share of the last 2 s's cycles in which the controller\n"
                   u"            damped (the knob made heavier at rest)\n"
                   u"\n"
                   u"LIST is comma-separated items, each a number, FROM:TO:STEP (FROM, FROM+STEP,\n"
                   u"… up to TO) or FROM:TO/N (N values from FROM to TO): --delays 0:0.3/10.\n"
                   u"--pc LIST maps each pc_damping_max (the passivity controller's most damping;\n"
                   u"0 = off) side by side: --pc 0,0.5 compares the controller off and on.\n"
                   u"--vary FIELD=LIST does so for any tuning field (a device parameter, host\n"
                   u"setting or passivity parameter by its profile name, e.g. M_adm=0.01,0.05).\n"
                   u"--hand LIST maps each constant hand torque in N·m (--hand 0.03:0.1/8);\n"
                   u"--hand SPEC runs one hand of hatpic-sim's kinds (const:0.05, step:…).\n"
                   u"--contacts N: the hand pushes for --duration, lets go for 2 s and pushes\n"
                   u"again, N times; each contact is a row, and a cell's chart colour is its\n"
                   u"worst contact's.\n"
                   u"\n"
                   u"--csv FILE writes the table (with the columns hand and contact), --svg FILE\n"
                   u"the chart (settled cells coloured by settle time, the others grey and\n"
                   u"crossed), --png FILE the same chart at twice its size; an existing file\n"
                   u"needs --force.\n"
                   u"The cells run on --threads threads (default: one per core)."_s})
    {}
    void addOptions(QCommandLineParser &parser) override
    {
        const auto add = [&](const QString &name, const QString &help, const QString &value) {
            parser.addOption({QStringList{name}, help, value});
        };
        add(u"profile"_s, u"The tuning (default: the defaults)."_s, u"FILE"_s);
        add(u"delays"_s,
            u"One-way delays, s (default: "_s + QString::fromUtf16(kDefaultDelays) + u")."_s,
            u"LIST"_s);
        add(u"gains"_s,
            u"Feedback gains, N·m/N (default: "_s + QString::fromUtf16(kDefaultGains) + u")."_s,
            u"LIST"_s);
        add(u"pc"_s, u"Values of pc_damping_max (0: the controller off): one map each."_s,
            u"LIST"_s);
        add(u"vary"_s, u"A tuning field and its values: one map each."_s, u"FIELD=LIST"_s);
        add(u"hand"_s,
            u"Constant hands' torques, N·m, a map each; or one hand SPEC (default: const:0.05)."_s,
            u"LIST|SPEC"_s);
        add(u"contacts"_s,
            u"Contacts per cell, 1 to 100: push, let go for 2 s, push again (default: 1)."_s,
            u"N"_s);
        add(u"duration"_s,
            u"Seconds of virtual time per cell (per contact), 2 to 3600 (default: 20)."_s, u"S"_s);
        add(u"seed"_s, u"Seed of the load noise and the network's faults (default: 1)."_s, u"N"_s);
        add(u"jitter"_s, u"Uniform extra latency each way, 0 to 10 s (default: 0)."_s, u"S"_s);
        add(u"loss"_s, u"Fraction of messages lost each way, 0 to 1 (default: 0)."_s, u"P"_s);
        add(u"threads"_s, u"Threads running cells, 1 to 64 (default: one per core)."_s, u"N"_s);
        add(u"csv"_s, u"Write the table as CSV."_s, u"FILE"_s);
        add(u"svg"_s, u"Write the chart as SVG."_s, u"FILE"_s);
        add(u"png"_s, u"Write the chart as PNG."_s, u"FILE"_s);
        parser.addOption({u"force"_s, u"Overwrite --csv, --svg and --png files."_s});
    }

    int run(const QCommandLineParser &parser) override
    {
        teleop::MapSpec spec;
        spec.threads = std::clamp(QThread::idealThreadCount(), 1, teleop::kMaxMapThreads);
        if (parser.isSet(u"profile"_s)) {
            const auto profile = loadProfile(parser.value(u"profile"_s));
            if (!profile)
                return ExitBadUsage;
            spec.base.device = profile->device;
            spec.base.host = profile->host;
            spec.base.effects = profile->effects;
            spec.base.passivity = profile->passivity; // its defaults when the file has none
        }
        const auto list = [&](const QString &option, const QString &fallback,
                              std::vector<double> &into) {
            const QString text = parser.isSet(option) ? parser.value(option) : fallback;
            QString why;
            const auto values = teleop::parseValueList(text, &why);
            if (!values) {
                printError(u"--"_s + option + u' ' + why + u'.');
                return false;
            }
            into = *values;
            return true;
        };
        if (!list(u"delays"_s, QString::fromUtf16(kDefaultDelays), spec.delays) ||
            !list(u"gains"_s, QString::fromUtf16(kDefaultGains), spec.gains))
            return ExitBadUsage;
        if (parser.isSet(u"pc"_s) && parser.isSet(u"vary"_s)) {
            printError(u"--pc and --vary each choose the field to map; give one of them."_s);
            return ExitBadUsage;
        }
        if (parser.isSet(u"pc"_s) || parser.isSet(u"vary"_s)) {
            const QString vary = parser.isSet(u"pc"_s)
                                     ? u"pc_damping_max="_s + parser.value(u"pc"_s)
                                     : parser.value(u"vary"_s);
            const qsizetype eq = vary.indexOf(u'=');
            if (eq <= 0) {
                printError(u"--vary needs FIELD=LIST, got '"_s + vary + u"'."_s);
                return ExitBadUsage;
            }
            spec.field.name = vary.left(eq).trimmed();
            if (!teleop::fieldValue(spec.base, spec.field.name)) {
                printError(u"--vary: there is no tuning field '"_s + spec.field.name +
                           u"'; one of "_s + teleop::mapFieldNames().join(u", "_s) + u'.');
                return ExitBadUsage;
            }
            QString why;
            const auto values = teleop::parseValueList(vary.mid(eq + 1), &why);
            if (!values) {
                printError((parser.isSet(u"pc"_s) ? u"--pc"_s : u"--vary "_s + spec.field.name) +
                           u' ' + why + u'.');
                return ExitBadUsage;
            }
            spec.field.values = *values;
        }
        if (parser.isSet(u"hand"_s)) {
            // A list of torques when it starts like a number, else a hand of hatpic-sim's.
            const QString text = parser.value(u"hand"_s).trimmed();
            QString why;
            if (!text.isEmpty() && !text.front().isLetter()) {
                const auto hands = teleop::parseValueList(text, &why);
                if (!hands) {
                    printError(u"--hand "_s + why + u'.');
                    return ExitBadUsage;
                }
                spec.hands = *hands;
            } else {
                const auto hand = HandInput::parse(text, &why);
                if (!hand) {
                    printError(u"--hand: "_s + asSentence(why));
                    return ExitBadUsage;
                }
                spec.base.hand = *hand;
            }
        }
        if (parser.isSet(u"contacts"_s)) {
            bool ok = false;
            spec.base.contacts = parser.value(u"contacts"_s).toInt(&ok);
            if (!ok) {
                printError(u"--contacts needs a whole number from 1 to "_s +
                           QString::number(teleop::LoopConfig::kMaxContacts) + u", got '"_s +
                           parser.value(u"contacts"_s) + u"'."_s);
                return ExitBadUsage;
            }
        }
        for (auto [option, target] : {std::pair{u"duration"_s, &spec.base.duration},
                                      std::pair{u"jitter"_s, &spec.base.robot.faults.jitter},
                                      std::pair{u"loss"_s, &spec.base.robot.faults.loss}}) {
            if (!parser.isSet(option))
                continue;
            bool ok = false;
            *target = parser.value(option).toDouble(&ok);
            if (!ok || !std::isfinite(*target)) {
                printError(u"--"_s + option + u" needs a number, got '"_s + parser.value(option) +
                           u"'."_s);
                return ExitBadUsage;
            }
        }
        if (parser.isSet(u"seed"_s)) {
            bool ok = false;
            const quint64 seed = parser.value(u"seed"_s).toULongLong(&ok);
            if (!ok) {
                printError(u"--seed needs a whole number from 0, got '"_s +
                           parser.value(u"seed"_s) + u"'."_s);
                return ExitBadUsage;
            }
            spec.base.seed = seed;
            spec.base.robot.seed = seed;
        }
        if (parser.isSet(u"threads"_s)) {
            bool ok = false;
            spec.threads = parser.value(u"threads"_s).toInt(&ok);
            if (!ok || spec.threads < 1 || spec.threads > teleop::kMaxMapThreads) {
                printError(u"--threads needs a whole number from 1 to 64, got '"_s +
                           parser.value(u"threads"_s) + u"'."_s);
                return ExitBadUsage;
            }
        }
        if (const QString problem = teleop::checkSpec(spec); !problem.isEmpty()) {
            printError(asSentence(problem));
            return ExitBadUsage;
        }
        const bool force = parser.isSet(u"force"_s);
        if (const QString why = pngUnavailable(); parser.isSet(u"png"_s) && !why.isEmpty()) {
            printError(asSentence(u"--png: "_s + why));
            return ExitBadUsage;
        }
        for (const QString &option : {u"csv"_s, u"svg"_s, u"png"_s}) {
            if (!parser.isSet(option))
                continue;
            if (const QString p = outputProblem(option, parser.value(option), force);
                !p.isEmpty()) {
                printError(p);
                return ExitBadUsage;
            }
        }

        QElapsedTimer clock;
        clock.start();
        const std::vector<teleop::MapCell> cells = teleop::runMap(spec);
        const double seconds = double(clock.elapsed()) / 1000.0;

        printTable(cells, spec.field.name, !spec.hands.empty(), spec.base.contacts > 1);
        flushOut(); // the table before the note, on a terminal showing both
        printNote(u"%1 cells of %2 s in %3 s on %4 threads."_s.arg(cells.size())
                      .arg(compactNumberText(spec.base.duration))
                      .arg(seconds, 0, 'f', 2)
                      .arg(spec.threads));
        if (parser.isSet(u"csv"_s) &&
            !writeFile(parser.value(u"csv"_s), teleop::mapCsv(cells, spec.field.name)))
            return ExitFailure;
        const QByteArray svg = teleop::mapSvg(cells, spec.field.name, spec.base.duration);
        if (parser.isSet(u"svg"_s) && !writeFile(parser.value(u"svg"_s), svg))
            return ExitFailure;
        if (parser.isSet(u"png"_s)) {
            QString why;
            const QByteArray png = svgToPng(svg, 2.0, &why);
            if (png.isEmpty()) {
                printError(u"Cannot draw "_s + parser.value(u"png"_s) + u": "_s + why + u'.');
                return ExitFailure;
            }
            if (!writeFile(parser.value(u"png"_s), png))
                return ExitFailure;
        }
        return flushOut() ? ExitSuccess : ExitFailure;
    }

private:
    static void printTable(const std::vector<teleop::MapCell> &cells, QString field, bool hands,
                           bool contacts)
    {
        if (field == u"pc_damping_max")
            field.clear(); // the pc column shows it

        QString out = u"   delay     gain"_s;
        if (hands)
            out += u"     hand"_s;
        out += u"       pc"_s;
        if (!field.isEmpty())
            out += u' ' + field.rightJustified(10);
        if (contacts)
            out += u"  contact"_s;
        out += u"  settled  settle_s      p2p  rms_tau_pc_ratio  dissipated_j  damped_rest\n"_s;
        for (const teleop::MapCell &c : cells) {
            for (const teleop::LoopResult &r : c.contacts) {
                out += cell(c.delay, 8) + u' ' + cell(c.gain, 8, 4);
                if (hands)
                    out += u' ' + cell(c.hand, 8, 4);
                out += u' ' + cell(c.pc, 8);
                if (!field.isEmpty())
                    out += u' ' + cell(c.field, std::max<int>(10, int(field.size())), 4);
                if (contacts)
                    out += u' ' + QString::number(r.index).rightJustified(8);
                out += (r.settled ? u"        1"_s : u"        0"_s) + u' ' +
                       cell(r.settleS, 9, 2) + u' ' + cell(r.p2p, 8, 4) + u' ' +
                       cell(r.rmsTauPcRatio, 17) + u' ' + cell(r.dissipatedJ, 13, 4) + u' ' +
                       cell(r.dampedAtRest, 12) + u'\n';
            }
        }
        writeOut(out);
    }
};

} // namespace

std::unique_ptr<Subcommand> makeTeleopMapSubcommand()
{
    return std::make_unique<TeleopMapSubcommand>();
}

} // namespace hatpic::cli
