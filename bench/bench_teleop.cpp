// bench_teleop [--seconds S] [--delays MS,MS,…] [--jitter S] [--repeat N] [--hand T]
//              [--gain G] [--profile FILE] [--csv PREFIX]
//
// The teleoperation loop of robot.md against the one-way delay of the network between knob
// and robot: for each delay (default 0, 20, 40, 60, 80, 100 ms) the three real programs that
// tst_teleoploop runs — hatpic-sim --hand const:T (default 0.05 N·m), hatpic-bridge
// --component force.x --gain G (default 0.02 N·m/N; --profile FILE passed on) and
// hatpic-robot-sim --delay (both directions; --jitter added) with its defaults — on loopback
// in a private ROS 2 domain, watched for S seconds (default 12) by a node of this program
// (tests/app/teleoploop.h). One row per run:
//
//   contact    first /robot/pose with x > x_w, seconds after the programs were started;
//   settle     from contact to settled: the arrival of the first τ_ext (/hatpic/feedback)
//              from which every later τ_ext of the run is within ±5 % of robot.md's
//              equilibrium (robot::loopEquilibrium), provided that holds over at least the
//              last 2 s and τ_ext still arrives; "never" otherwise (settled: no);
//   overshoot  the largest τ_ext after contact (in the equilibrium's direction), and the
//              largest F_e (−force.x on /wrench_estimation), beyond the equilibrium's, in % of
//              it (0 when never beyond) — the wall's impact included;
//   p-p        peak to peak of τ_ext [mN·m] and of θ (/hatpic/joint_states) [mrad] over the
//              last 2 s; when θ swings there by more than 3 encoder counts, its period over
//              the second half of the run;
//   left wall  how often x fell back to x_w or less after the first contact (bounces).
//
// Times are arrival times at this program's node, so τ_ext carries the bridge's feedback
// period and F_e the robot's outgoing delay; contact (the pose) has no added delay.
// Run it through /work/bin/isolated (or any network namespace with only lo).
#include "model/params.h"
#include "profile/bridgesettings.h"
#include "profile/profile.h"
#include "robot/loopequilibrium.h"
#include "robot/robotmodel.h"
#include "teleoploop.h"

#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

constexpr double kBand = 0.05; //!< settled: within ±5 % of the equilibrium
constexpr double kHold = 2.0;  //!< … over at least the last 2 s [s]; also the p-p window
constexpr double kEncoderStep = 2 * 3.14159265358979 / 4096; //!< one servo count [rad]

struct Options
{
    double seconds = 12;
    std::vector<double> delaysMs{0, 20, 40, 60, 80, 100};
    double jitter = 0; //!< [s]
    int repeat = 1;
    double hand = 0.05; //!< [N·m]
    double gain = 0.02; //!< [N·m/N]
    QString profile;
    QString csvPrefix;
};

struct Figures
{
    std::optional<double> contact; //!< [s after start]
    std::optional<double> settle;  //!< [s after contact]
    double tauOvershoot = NAN;     //!< [%]
    double forceOvershoot = NAN;   //!< [%]
    double tauPeakToPeak = NAN;    //!< last kHold s [N·m]
    double thetaPeakToPeak = NAN;  //!< last kHold s [rad]
    std::optional<double> period;  //!< θ's, second half of the run, when it swings [s]
    double tauMean = NAN;          //!< last kHold s [N·m]
    double thetaMean = NAN;        //!< last kHold s [rad]
    int wallLeft = 0;              //!< x ≤ x_w again after the first contact
    std::size_t thetaN = 0, tauN = 0, xN = 0, forceN = 0;
};

//! The mean period of a swing: mean crossings with a hysteresis of a quarter of the peak to
//! peak, one period per two crossings; nullopt with fewer than three crossings.
std::optional<double> periodOf(const Watcher &w, Watcher::Series series, double from, double to)
{
    const Stats st = statsOf(w.window(series, from, to));
    if (st.n < 4)
        return std::nullopt;
    const double h = st.spread() / 4;
    int side = 0; // −1 below mean − h, +1 above mean + h
    std::vector<double> crossings;
    for (const Watcher::Point &p : w.points(series)) {
        if (p.t < from || p.t > to)
            continue;
        const int now = p.value > st.mean + h ? 1 : p.value < st.mean - h ? -1 : 0;
        if (now != 0 && now != side) {
            if (side != 0)
                crossings.push_back(p.t);
            side = now;
        }
    }
    if (crossings.size() < 3)
        return std::nullopt;
    return 2 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

Figures figuresOf(const Watcher &w, double start, double end, const robot::LoopEquilibrium &eq,
                  double wall)
{
    Figures f;
    const auto theta = w.points(&Watcher::m_theta);
    const auto tau = w.points(&Watcher::m_tau);
    const auto x = w.points(&Watcher::m_x);
    const auto force = w.points(&Watcher::m_wallForce);
    f.thetaN = theta.size();
    f.tauN = tau.size();
    f.xN = x.size();
    f.forceN = force.size();

    double contactAt = NAN;
    bool touching = false;
    for (const Watcher::Point &p : x) {
        const bool in = p.value > wall;
        if (in && std::isnan(contactAt))
            contactAt = p.t;
        else if (!in && touching)
            ++f.wallLeft;
        touching = in;
    }
    if (!std::isnan(contactAt))
        f.contact = contactAt - start;

    // Settled from the first τ_ext of the final run inside the band, if that run is long enough.
    const double band = kBand * std::abs(eq.tauExt);
    double runFrom = NAN;
    for (const Watcher::Point &p : tau) {
        if (std::abs(p.value - eq.tauExt) <= band) {
            if (std::isnan(runFrom))
                runFrom = p.t;
        } else {
            runFrom = NAN;
        }
    }
    const bool tauStillArriving = !tau.empty() && tau.back().t >= end - 0.5;
    if (!std::isnan(runFrom) && !std::isnan(contactAt) && runFrom <= end - kHold &&
        tauStillArriving)
        f.settle = runFrom - contactAt;

    if (!std::isnan(contactAt)) {
        const double sign = eq.tauExt < 0 ? -1 : 1;
        double tauPeak = 0;
        for (const Watcher::Point &p : tau) {
            if (p.t >= contactAt)
                tauPeak = std::max(tauPeak, sign * p.value);
        }
        f.tauOvershoot = std::max(0.0, tauPeak / std::abs(eq.tauExt) - 1) * 100;
        double forcePeak = 0;
        for (const Watcher::Point &p : force)
            forcePeak = std::max(forcePeak, p.value);
        f.forceOvershoot = std::max(0.0, forcePeak / eq.wallForce - 1) * 100;
    }

    const Stats tauLast = statsOf(w.window(&Watcher::m_tau, end - kHold, end));
    const Stats thetaLast = statsOf(w.window(&Watcher::m_theta, end - kHold, end));
    f.tauPeakToPeak = tauLast.spread();
    f.thetaPeakToPeak = thetaLast.spread();
    f.tauMean = tauLast.mean;
    f.thetaMean = thetaLast.mean;
    if (f.thetaPeakToPeak > 3 * kEncoderStep)
        f.period = periodOf(w, &Watcher::m_theta, (start + end) / 2, end);
    return f;
}

void writeCsv(const QString &path, const Watcher &w, double start)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        std::fprintf(stderr, "bench_teleop: cannot write %s\n", qPrintable(path));
        return;
    }
    file.write("series,t_s,value\n");
    const auto write = [&](const char *name, Watcher::Series series) {
        for (const Watcher::Point &p : w.points(series))
            file.write(QByteArray(name) + ',' + QByteArray::number(p.t - start, 'f', 4) + ',' +
                       QByteArray::number(p.value, 'g', 8) + '\n');
    };
    write("theta_rad", &Watcher::m_theta);
    write("tau_ext_Nm", &Watcher::m_tau);
    write("x_m", &Watcher::m_x);
    write("F_e_N", &Watcher::m_wallForce);
}

QByteArray loadAverage()
{
    QFile file(u"/proc/loadavg"_s);
    if (!file.open(QIODevice::ReadOnly))
        return "?";
    return file.readAll().split(' ').mid(0, 3).join(' ');
}

//! "1.23 s" (`unit` after the number), or `none`.
QString cell(const std::optional<double> &v, int decimals, const QString &unit, const QString &none)
{
    return v ? QString(QString::number(*v, 'f', decimals) + unit) : none;
}

std::optional<Options> parse(const QStringList &args)
{
    Options o;
    for (int i = 1; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (i + 1 >= args.size()) {
            std::fprintf(stderr, "bench_teleop: %s needs a value\n", qPrintable(a));
            return std::nullopt;
        }
        const QString v = args.at(++i);
        if (a == u"--seconds"_s)
            o.seconds = v.toDouble();
        else if (a == u"--delays"_s) {
            o.delaysMs.clear();
            for (const QString &d : v.split(u',', Qt::SkipEmptyParts))
                o.delaysMs.push_back(d.toDouble());
        } else if (a == u"--jitter"_s)
            o.jitter = v.toDouble();
        else if (a == u"--repeat"_s)
            o.repeat = v.toInt();
        else if (a == u"--hand"_s)
            o.hand = v.toDouble();
        else if (a == u"--gain"_s)
            o.gain = v.toDouble();
        else if (a == u"--profile"_s)
            o.profile = v;
        else if (a == u"--csv"_s)
            o.csvPrefix = v;
        else {
            std::fprintf(stderr, "bench_teleop: unknown option %s\n", qPrintable(a));
            return std::nullopt;
        }
    }
    if (o.seconds < kHold + 3 || o.repeat < 1 || o.delaysMs.empty()) {
        std::fprintf(stderr,
                     "bench_teleop: --seconds at least %g, --repeat at least 1, one "
                     "delay at least\n",
                     kHold + 3);
        return std::nullopt;
    }
    return o;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const std::optional<Options> options = parse(app.arguments());
    if (!options)
        return 2;
    const Options &o = *options;

    DeviceParams device;
    HostParams host;
    if (!o.profile.isEmpty()) {
        const ProfileReadResult read = readProfile(o.profile);
        if (!read.ok()) {
            std::fprintf(stderr, "bench_teleop: %s: %s\n", qPrintable(o.profile),
                         qPrintable(read.errors.join(u"; "_s)));
            return 2;
        }
        device = read.profile->device;
        host = read.profile->host;
    }
    const robot::RobotParams robotParams;
    const auto rest = robot::loopEquilibrium(device, host, o.hand, o.gain,
                                             bridge::FeedbackSettings{}.limit, robotParams);
    if (!rest) {
        std::fprintf(stderr, "bench_teleop: no equilibrium for hand %g and gain %g\n", o.hand,
                     o.gain);
        return 2;
    }
    const robot::LoopEquilibrium eq = *rest;
    QTemporaryDir dir;
    if (!dir.isValid()) {
        std::fprintf(stderr, "bench_teleop: no temporary directory\n");
        return 1;
    }

    std::printf("hand const:%g N·m, gain %g N·m/N, M_adm %g N·m·s/rad, D_adm %g kg·m², jitter "
                "%g s, %g s a run\n",
                o.hand, o.gain, device.M_adm, device.D_adm, o.jitter, o.seconds);
    std::printf("equilibrium: θ %.4f rad, τ_ext %.4f N·m, F_e %.3f N, x %.5f m; settled within "
                "±%.0f %% of τ_ext (±%.2f mN·m) over ≥ %.0f s\n",
                eq.theta, eq.tauExt, eq.wallForce, eq.robotPosition, kBand * 100,
                kBand * std::abs(eq.tauExt) * 1000, kHold);
    std::printf("load average at start: %s\n\n", loadAverage().constData());
    std::printf("| delay | contact | settle | settled | overshoot τ_ext / F_e | p-p τ_ext, last "
                "2 s | p-p θ, last 2 s | θ period | mean θ / τ_ext, last 2 s | left wall |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);

    const int domainBase = 100 + int(QCoreApplication::applicationPid() % 50);
    int run = 0;
    int failures = 0;
    for (int r = 0; r < o.repeat; ++r) {
        for (const double delayMs : o.delaysMs) {
            LoopSetup setup;
            setup.simPath = QStringLiteral(HATPIC_SIM_PATH);
            setup.bridgePath = QStringLiteral(HATPIC_BRIDGE_PATH);
            setup.robotPath = QStringLiteral(HATPIC_ROBOT_SIM_PATH);
            setup.domain = domainBase + run % 50;
            setup.env = loopEnvironment(QProcessEnvironment::systemEnvironment(), setup.domain);
            setup.link = dir.filePath(u"knob-%1"_s.arg(run));
            setup.hand = u"const:%1"_s.arg(o.hand);
            setup.gain = o.gain;
            setup.robotArguments = {u"--delay"_s, QString::number(delayMs / 1000)};
            if (o.jitter > 0)
                setup.robotArguments << u"--jitter"_s << QString::number(o.jitter);
            if (!o.profile.isEmpty())
                setup.bridgeArguments = {u"--profile"_s, o.profile};
            setup.nodeName = "bench_teleop";
            ++run;

            Loop loop;
            const double start = monotonic();
            if (const QString why = startLoop(loop, setup); !why.isEmpty()) {
                std::fprintf(stderr, "bench_teleop: %s\n", qPrintable(why));
                return 1;
            }
            spinFor(o.seconds);
            const double end = monotonic();
            const Figures f = figuresOf(loop.watcher, start, end, eq, robotParams.wall);
            if (!o.csvPrefix.isEmpty())
                writeCsv(u"%1-%2ms-%3.csv"_s.arg(o.csvPrefix).arg(delayMs).arg(r + 1), loop.watcher,
                         start);
            if (f.thetaN < 50 || f.tauN < 50 || f.xN < 50) {
                ++failures;
                std::fprintf(stderr,
                             "bench_teleop: %g ms: too few messages (θ %zu, τ_ext %zu, "
                             "x %zu)\nrobot %s\nbridge %s\n",
                             delayMs, f.thetaN, f.tauN, f.xN, loop.robot->output().constData(),
                             loop.bridge->output().constData());
            }
            const QString row =
                u"| %1 ms | %2 | %3 | %4 | %5 / %6 % | %7 mN·m | %8 mrad (%9 counts) | %10 | "
                "%11 rad / %12 N·m | %13 |"_s.arg(delayMs)
                    .arg(cell(f.contact, 2, u" s"_s, u"none"_s))
                    .arg(cell(f.settle, 2, u" s"_s, u"never"_s))
                    .arg(f.settle ? u"yes"_s : u"no"_s)
                    .arg(f.tauOvershoot, 0, 'f', 0)
                    .arg(f.forceOvershoot, 0, 'f', 0)
                    .arg(f.tauPeakToPeak * 1000, 0, 'f', 2)
                    .arg(f.thetaPeakToPeak * 1000, 0, 'f', 1)
                    .arg(f.thetaPeakToPeak / kEncoderStep, 0, 'f', 0)
                    .arg(cell(f.period ? std::optional(*f.period * 1000) : std::nullopt, 0,
                              u" ms"_s, u"–"_s))
                    .arg(f.thetaMean, 0, 'f', 4)
                    .arg(f.tauMean, 0, 'f', 4)
                    .arg(f.wallLeft);
            std::printf("%s\n", qPrintable(row));
            std::fflush(stdout);
        }
    }
    std::printf("\nload average at end: %s\n", loadAverage().constData());
    return failures == 0 ? 0 : 1;
}
