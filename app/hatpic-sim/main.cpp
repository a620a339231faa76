// hatpic-sim: a simulated HATPIC joystick on a pseudo-terminal, in real time.
//
// Prints the slave path as the first stdout line, then runs until SIGINT/SIGTERM (exit 0).
// With --faults, prints what it injected on stderr at exit and on SIGUSR1.
// Bad options: one sentence on stderr, exit 4. Runtime failure (no pty, no link): exit 1.
#include "common/connectionoptions.h"
#include "common/faultreport.h"
#include "common/ptyprogram.h"
#include "realtime/realtime.h"
#include "sim/cyclelog.h"
#include "sim/simulateddevice.h"
#include "sim/simulatorhost.h"

#include <QCoreApplication>
#include <QFile>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

using namespace hatpic;

namespace {

// hatpic-sim's own options: the wire protocol and the emulated link's speed.
struct LinkOptions
{
    QCommandLineOption protocol;
    QCommandLineOption baud;
    QCommandLineOption noThrottle;
};

bool readLinkOptions(const PtyProgram &program, const LinkOptions &options,
                     SimulatedDevice::Config &config)
{
    // The device speaks one protocol: the shared --protocol without auto.
    QString error;
    const auto protocol = parseProtocol(program.value(options.protocol), &error, false);
    if (!protocol) {
        program.printError(error);
        return false;
    }
    config.protocol = *protocol == ProtocolChoice::V2 ? WireProtocol::V2 : WireProtocol::Legacy;
    if (!program.readRate(config.controlRateHz))
        return false;
    if (program.isSet(options.baud)) {
        const auto baud = parseBaud(program.value(options.baud), &error);
        if (!baud) {
            program.printError(error);
            return false;
        }
        config.baud = *baud;
    }
    config.throttle = !program.isSet(options.noThrottle);
    return true;
}

// The board: one knob, or the IMU branch's four knobs and tilt.
struct BoardOptions
{
    QCommandLineOption device;
    QCommandLineOption protocol;
    PtyProgram::OtherHandOptions hands;
    QCommandLineOption tilt;
};

bool readBoardOptions(const PtyProgram &program, const BoardOptions &options,
                      SimulatedDevice::Config &config)
{
    const QString device = program.value(options.device);
    const bool imu = device == u"imu-branch";
    if (!imu && device != u"knob") {
        program.printError(
            QStringLiteral("--device: must be knob or imu-branch, got \"%1\".").arg(device));
        return false;
    }
    const bool extras = program.isSet(options.tilt) ||
                        std::any_of(options.hands.begin(), options.hands.end(),
                                    [&](const QCommandLineOption &o) { return program.isSet(o); });
    if (!imu) {
        if (extras)
            program.printError(QStringLiteral("--tilt and --hand-2 … --hand-4 need "
                                              "--device imu-branch (a single knob has neither)."));
        return !extras;
    }
    if (program.isSet(options.protocol) && config.protocol != WireProtocol::Legacy) {
        program.printError(QStringLiteral("--device imu-branch speaks the IMU branch's legacy "
                                          "frames; drop --protocol or give legacy."));
        return false;
    }
    config.board = SimulatedDevice::Board::ImuBranch;
    config.protocol = WireProtocol::Legacy;
    if (!program.readOtherHands(options.hands, config.otherHands))
        return false;
    if (program.isSet(options.tilt)) {
        const QString text = program.value(options.tilt);
        const QStringList parts = text.split(u',');
        bool rollOk = false;
        bool pitchOk = false;
        const double roll = parts.size() == 2 ? parts[0].toDouble(&rollOk) : 0;
        const double pitch = parts.size() == 2 ? parts[1].toDouble(&pitchOk) : 0;
        const double limit = std::numbers::pi / 2;
        if (!rollOk || !pitchOk || !(std::abs(roll) <= limit) || !(std::abs(pitch) <= limit)) {
            program.printError(QStringLiteral("--tilt: must be ROLL,PITCH in rad, each from "
                                              "-1.5708 to 1.5708 (a quarter turn), got \"%1\".")
                                   .arg(text));
            return false;
        }
        config.roll = roll;
        config.pitch = pitch;
    }
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    PtyProgram program(app, "hatpic-sim",
                       QStringLiteral("Simulated HATPIC joystick on a pseudo-terminal."));
    const auto device = program.add(
        "device",
        "The board: knob (one knob, the master firmware or ours) or imu-branch (the published "
        "IMU branch: four knobs and a tilt, its legacy frames; docs/simulator.md).",
        "knob|imu-branch", "knob");
    const auto protocol =
        program.add("protocol", "Wire protocol: v2 or legacy.", "v2|legacy", "v2");
    program.add(SharedOption::Rate);
    const auto baud =
        program.add("baud",
                    "Emulated link baud rate, 300 to 4000000 (default 921600 for v2, 115200 for "
                    "legacy).",
                    "N");
    const auto noThrottle = program.add("no-throttle", "Do not limit output to the baud rate.");
    const auto cycleLog =
        program.add("cycle-log",
                    "Write every control cycle to FILE as CSV: t_s, the quantities TELEMETRY "
                    "carries (t_us, theta, omega, tau, ...), tau_total; about 100 bytes a cycle.",
                    "FILE");
    program.add(SharedOption::Hand);
    const PtyProgram::OtherHandOptions otherHands = program.addOtherHands("imu-branch");
    const auto tilt = program.add(
        "tilt", "imu-branch: the board's roll and pitch [rad] (default 0,0: level).", "ROLL,PITCH");
    program.add(SharedOption::Seed, "Seed of the load-reading noise and of the faults.");
    program.add(SharedOption::State);
    program.add(SharedOption::Link);
    program.add(SharedOption::Faults,
                "Faults to inject on the link, e.g. "
                "drop=0.01,corrupt=0.005,dup=0.002,delay=0.01:20ms,cut=30s:2s,hdrop=0.01 "
                "(docs/simulator.md).");

    SimulatedDevice::Config config;
    config.noise = SimulatedDevice::kProgramNoise;
    if (!program.parse() || !readLinkOptions(program, {protocol, baud, noThrottle}, config) ||
        !readBoardOptions(program, {device, protocol, otherHands, tilt}, config) ||
        !program.readHand(config.hand) || !program.readSeed(config.seed) ||
        !program.readStateFile(config.stateFile) || !program.readFaults(config.faults) ||
        !program.readLink())
        return PtyProgram::kExitBadOptions;

    SimulatorHost host(config);
    QFile log;
    if (program.isSet(cycleLog)) {
        log.setFileName(program.value(cycleLog));
        if (!log.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
            program.printError(QStringLiteral("--cycle-log: cannot write %1: %2")
                                   .arg(log.fileName(), log.errorString()));
            return PtyProgram::kExitBadOptions;
        }
        log.write(cycleLogHeader() + '\n');
        host.device().setCycleObserver(
            [&log](const SimulatedDevice::Cycle &c) { log.write(cycleLogLine(c) + '\n'); });
    }
    for (const QString &warning : {host.device().stateWarning(), host.device().saveWarning()}) {
        if (!warning.isEmpty())
            program.printError(warning);
    }
    const Serving serving = program.serve(host); // after the host, which it must not outlive
    if (!serving)
        return PtyProgram::kExitFailure;
    // This thread runs the simulated device, standing in for hardware: real-time where allowed
    // (said after the pty's path, the first line a client reads).
    for (const std::string &problem :
         {realtime::makeThreadRealtime(realtime::kDevicePriority), realtime::lockMemory()}) {
        if (!problem.empty())
            program.printError(QString::fromStdString(problem) + u'.');
    }
    std::fprintf(stderr, "hatpic-sim: %s%s protocol, %g Hz control, %d baud%s\n",
                 config.board == SimulatedDevice::Board::ImuBranch ? "IMU-branch board (4 knobs), "
                                                                   : "",
                 qPrintable(wireProtocolName(config.protocol)), config.controlRateHz,
                 host.device().baud(), config.throttle ? "" : " (not throttled)");

    auto printFaults = [&host, &config] {
        if (const FaultInjector *faults = host.faults()) {
            printFaultReport("hatpic-sim", *faults, config.seed);
            // Losses that are not faults: the device's transmit queue was full (the simulator
            // fell behind real time), or the pty was (nobody read for a long while).
            std::fprintf(
                stderr, "hatpic-sim:   not sent: telemetry_dropped=%llu pty_discarded_bytes=%llu\n",
                static_cast<unsigned long long>(host.device().telemetryDropped()),
                static_cast<unsigned long long>(host.bytesDiscarded()));
            std::fflush(stderr);
        }
    };
    if (host.faults() && !program.reportOnSignal(printFaults))
        return PtyProgram::kExitFailure;

    const int code = app.exec();
    host.stop();
    host.device().setCycleObserver({});
    log.close();
    printFaults();
    return PtyProgram::exitCode(code);
}
