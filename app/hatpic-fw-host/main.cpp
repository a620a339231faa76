// hatpic-fw-host: the HATPIC firmware's device core on a Linux PC, with the STS3032 on a
// USB–TTL adapter and protocol v2 served on a pseudo-terminal (docs/firmware.md).
//
// Prints the pty's slave path as the first stdout line, then runs until SIGINT/SIGTERM: the
// control thread stops, the servo's torque goes off, the link is removed, exit 0. Bad options:
// one sentence on stderr, exit 4. The servo does not answer or no pty: exit 1.
#include "common/connectionoptions.h"
#include "common/faultreport.h"
#include "common/ptyprogram.h"
#include "fwhost/firmwarehost.h"

#include <QCoreApplication>
#include <QTimer>

#include <cstdio>

using namespace hatpic;

namespace {

constexpr double kMaxTimeoutMs = 100; //!< highest --servo-timeout accepted [ms]
constexpr int kReportMs = 1000;       //!< stderr report period [ms]

// hatpic-fw-host's own options: the servo bus.
struct BusOptions
{
    QCommandLineOption servo;
    QCommandLineOption baud;
    QCommandLineOption timeout;
};

bool readBusOptions(const PtyProgram &program, const BusOptions &options,
                    FirmwareHost::Config &config)
{
    config.servoPath = program.value(options.servo);
    if (config.servoPath.isEmpty()) {
        program.printError(QStringLiteral("The servo port is missing; name it with --servo PATH."));
        return false;
    }
    // Each of the three says what is wrong with it.
    const auto baud =
        program.wholeNumber(program.value(options.baud), kMinBaud, kMaxBaud, "baud rate");
    const bool idOk =
        program.readServoId(config.servoId) && program.readServos(config.servoId, config.servos);
    const bool centerOk = program.readCenterTick(config.centerTick);
    if (!baud || !idOk || !centerOk)
        return false;
    config.servoBaud = std::uint32_t(*baud);

    bool ok = false;
    const double timeoutMs = program.value(options.timeout).toDouble(&ok);
    if (!ok || !(timeoutMs >= 0.1 && timeoutMs <= kMaxTimeoutMs)) {
        program.printError(QStringLiteral("The servo timeout \"%1\" must be a number of ms from "
                                          "0.1 to %2.")
                               .arg(program.value(options.timeout))
                               .arg(kMaxTimeoutMs));
        return false;
    }
    config.servoTimeoutUs = std::uint32_t(timeoutMs * 1000.0 + 0.5);
    return true;
}

void printReport(const char *what, const FirmwareHost::Report &r)
{
    std::fprintf(stderr,
                 "hatpic-fw-host: %s %llu cycles in %.2f s (%.1f Hz); period p50 %lld µs, p99 "
                 "%lld µs, max %lld µs; cycle p99 %lld µs, max %lld µs; late %llu; bus errors "
                 "%u (total %u: timeouts %u, short %u, corrupt %u, foreign %u)%s\n",
                 what, static_cast<unsigned long long>(r.cycles), r.seconds, r.rateHz(),
                 static_cast<long long>(r.periodP50Us), static_cast<long long>(r.periodP99Us),
                 static_cast<long long>(r.periodMaxUs), static_cast<long long>(r.busyP99Us),
                 static_cast<long long>(r.busyMaxUs), static_cast<unsigned long long>(r.late),
                 r.busErrors, r.bus.errors(), r.bus.timeouts, r.bus.shortReplies, r.bus.corrupt,
                 r.bus.foreignId, r.faulted ? "; FAULT: torque off" : "");
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    PtyProgram program(app, "hatpic-fw-host",
                       QStringLiteral("The HATPIC firmware on a PC: drives an STS3032 on a serial "
                                      "port and serves protocol v2 on a pseudo-terminal."));
    const auto servo = program.add("servo", "Serial device of the servo bus (required).", "PATH");
    const auto baud = program.add("servo-baud", "Bus baud rate (default 1000000).", "N", "1000000");
    program.add(SharedOption::ServoId, "Servo id, 0…253 (default 1; knob 1's with --servos).");
    program.add(SharedOption::Servos, "Knobs: servos on the bus, 1 to 4, with ids ID, ID + 1, … "
                                      "(default 1; 4: the IMU branch's board).");
    program.add(SharedOption::CenterTick, "Servo tick of θ = 0, 0…4095 (default 1000).");
    const auto timeout =
        program.add("servo-timeout", "Bus reply timeout [ms] (default 5).", "MS", "5");
    program.add(SharedOption::Rate);
    program.add(SharedOption::State);
    program.add(SharedOption::Link);
    const auto quiet = program.add("quiet", "No timing reports on stderr.");
    program.add(SharedOption::Faults, "Faults to inject on the pty link, e.g. drop=0.01,cut=30s:2s "
                                      "(docs/simulator.md); a summary at exit and on SIGUSR1.");
    program.add(SharedOption::Seed, "Seed of the faults (default 1).");

    FirmwareHost::Config config;
    if (!program.parse() || !readBusOptions(program, {servo, baud, timeout}, config) ||
        !program.readRate(config.rateHz) || !program.readStateFile(config.stateFile) ||
        !program.readLink() || !program.readFaults(config.faults) ||
        !program.readSeed(config.faultSeed))
        return PtyProgram::kExitBadOptions;

    FirmwareHost host(config);
    const Serving serving = program.serve(host); // after the host, which it must not outlive
    if (!serving)
        return PtyProgram::kExitFailure;
    for (const QString &warning : host.warnings())
        program.printError(warning);
    const QString ids = config.servos == 1 ? QStringLiteral("servo id %1").arg(config.servoId)
                                           : QStringLiteral("%1 servos, ids %2–%3")
                                                 .arg(config.servos)
                                                 .arg(config.servoId)
                                                 .arg(config.servoId + config.servos - 1);
    std::fprintf(stderr,
                 "hatpic-fw-host: %s on %s at %u baud, center tick %d, timeout %u µs; "
                 "%g Hz control\n",
                 qPrintable(ids), qPrintable(config.servoPath), config.servoBaud,
                 int(config.centerTick), config.servoTimeoutUs, config.rateHz);

    auto printFaults = [&host, &config] {
        if (const FaultInjector *faults = host.faults())
            printFaultReport("hatpic-fw-host", *faults, config.faultSeed);
    };
    if (host.faults() && !program.reportOnSignal(printFaults))
        return PtyProgram::kExitFailure;

    QTimer report;
    const bool reports = !program.isSet(quiet);
    if (reports) {
        QObject::connect(&report, &QTimer::timeout, &app,
                         [&host] { printReport("last", host.takeReport()); });
        report.start(kReportMs);
    }

    const int code = app.exec();
    report.stop();
    const FirmwareHost::Report total = host.totalReport();
    printFaults(); // before stop(), which ends the link
    host.stop();   // control thread joined, then torque off
    if (reports) {
        printReport("total", total);
        std::fprintf(stderr, "hatpic-fw-host: control thread %s; torque off\n",
                     host.realtime() ? "SCHED_FIFO" : "normal priority");
    }
    return PtyProgram::exitCode(code);
}
