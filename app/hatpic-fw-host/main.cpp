// hatpic-fw-host: the HATPIC firmware's device core on a Linux PC, with the STS3032 on a
// USB–TTL adapter and protocol v2 served on a pseudo-terminal (docs/firmware.md).
//
// Prints the pty's slave path as the first stdout line, then runs until SIGINT/SIGTERM: the
// control thread stops, the servo's torque goes off, the link is removed, exit 0. Bad options:
// one sentence on stderr, exit 4. The servo does not answer or no pty: exit 1.
#include "common/faultreport.h"
#include "common/ptyprogram.h"
#include "common/quitonsignal.h"
#include "fwhost/firmwarehost.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTimer>

#include <cstdio>
#include <optional>

using namespace hatpic;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadOptions = 4;
constexpr double kMaxRateHz = 20000;  //!< highest --rate accepted [Hz]
constexpr double kMaxTimeoutMs = 100; //!< highest --servo-timeout accepted [ms]
constexpr int kReportMs = 1000;       //!< stderr report period [ms]

void printError(const QString &sentence)
{
    std::fprintf(stderr, "hatpic-fw-host: %s\n", qPrintable(sentence));
}

struct Options
{
    FirmwareHost::Config config;
    QString link;
    bool quiet = false;
};

//! A whole number from `low` to `high`, else the sentence and nullopt.
std::optional<qint64> wholeNumber(const QString &text, qint64 low, qint64 high, const char *what)
{
    bool ok = false;
    const qint64 value = text.toLongLong(&ok);
    if (ok && value >= low && value <= high)
        return value;
    printError(QStringLiteral("The %1 \"%2\" must be a whole number from %3 to %4.")
                   .arg(QLatin1String(what), text)
                   .arg(low)
                   .arg(high));
    return std::nullopt;
}

std::optional<Options> parseOptions(const QCoreApplication &app)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The HATPIC firmware on a PC: drives an STS3032 on a serial port and serves protocol v2 "
        "on a pseudo-terminal. Prints the terminal's path as the first line, then runs until "
        "SIGINT or SIGTERM."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const auto option = [](const char *name, const char *text, const char *value = nullptr,
                           const char *fallback = nullptr) {
        return QCommandLineOption(QLatin1String(name), QString::fromUtf8(text),
                                  value ? QLatin1String(value) : QString(),
                                  fallback ? QLatin1String(fallback) : QString());
    };
    const auto servo = option("servo", "Serial device of the servo bus (required).", "PATH");
    const auto baud = option("servo-baud", "Bus baud rate (default 1000000).", "N", "1000000");
    const auto id = option("servo-id", "Servo id, 0…253 (default 1).", "N", "1");
    const auto center =
        option("center-tick", "Servo tick of θ = 0, 0…4095 (default 1000).", "N", "1000");
    const auto timeout = option("servo-timeout", "Bus reply timeout [ms] (default 5).", "MS", "5");
    const auto rate = option("rate", "Control rate [Hz] (default 1000).", "HZ", "1000");
    const auto state =
        option("state", "Profile file that SAVE_PARAMS writes and power-up reads.", "FILE");
    const auto link =
        option("link", "Symlink to create to the terminal (removed on exit).", "PATH");
    const auto quiet = option("quiet", "No timing reports on stderr.");
    const auto faults = option("faults",
                               "Faults to inject on the pty link, e.g. drop=0.01,cut=30s:2s "
                               "(docs/simulator.md); a summary at exit and on SIGUSR1.",
                               "SPEC");
    const auto seed = option("seed", "Seed of the faults (default 1).", "N", "1");
    parser.addOptions({servo, baud, id, center, timeout, rate, state, link, quiet, faults, seed});

    if (!parser.parse(app.arguments())) {
        QString text = parser.errorText();
        if (!text.endsWith(QLatin1Char('.')))
            text += QLatin1Char('.');
        printError(text);
        return std::nullopt;
    }
    if (parser.isSet(helpOption))
        parser.showHelp(kExitOk); // exits
    if (!parser.positionalArguments().isEmpty()) {
        printError(QStringLiteral("Unexpected argument \"%1\"; hatpic-fw-host takes only "
                                  "options.")
                       .arg(parser.positionalArguments().first()));
        return std::nullopt;
    }

    Options options;
    FirmwareHost::Config &config = options.config;
    config.servoPath = parser.value(servo);
    if (config.servoPath.isEmpty()) {
        printError(QStringLiteral("The servo port is missing; name it with --servo PATH."));
        return std::nullopt;
    }
    const auto baudValue = wholeNumber(parser.value(baud), 300, 4000000, "baud rate");
    const auto idValue = wholeNumber(parser.value(id), 0, 253, "servo id");
    const auto centerValue = wholeNumber(parser.value(center), 0, 4095, "center tick");
    if (!baudValue || !idValue || !centerValue)
        return std::nullopt;
    config.servoBaud = std::uint32_t(*baudValue);
    config.servoId = std::uint8_t(*idValue);
    config.centerTick = std::int32_t(*centerValue);

    bool ok = false;
    const double timeoutMs = parser.value(timeout).toDouble(&ok);
    if (!ok || !(timeoutMs >= 0.1 && timeoutMs <= kMaxTimeoutMs)) {
        printError(QStringLiteral("The servo timeout \"%1\" must be a number of ms from 0.1 to "
                                  "%2.")
                       .arg(parser.value(timeout))
                       .arg(kMaxTimeoutMs));
        return std::nullopt;
    }
    config.servoTimeoutUs = std::uint32_t(timeoutMs * 1000.0 + 0.5);
    const double rateHz = parser.value(rate).toDouble(&ok);
    if (!ok || !(rateHz >= 1 && rateHz <= kMaxRateHz)) {
        printError(QStringLiteral("The control rate \"%1\" must be a number of Hz from 1 to %2.")
                       .arg(parser.value(rate))
                       .arg(kMaxRateHz));
        return std::nullopt;
    }
    config.rateHz = rateHz;
    if (parser.isSet(state)) {
        config.stateFile = parser.value(state);
        if (config.stateFile.isEmpty()) {
            printError(QStringLiteral("The state file name is empty."));
            return std::nullopt;
        }
    }
    if (parser.isSet(link)) {
        options.link = parser.value(link);
        if (options.link.isEmpty()) {
            printError(QStringLiteral("The link path is empty."));
            return std::nullopt;
        }
    }
    options.quiet = parser.isSet(quiet);
    if (parser.isSet(faults)) {
        QString error;
        const std::optional<FaultSpec> spec = FaultSpec::parse(parser.value(faults), &error);
        if (!spec) {
            printError(error);
            return std::nullopt;
        }
        config.faults = *spec;
    }
    config.faultSeed = parser.value(seed).toULongLong(&ok);
    if (!ok) {
        printError(QStringLiteral("The seed \"%1\" must be a non-negative whole number.")
                       .arg(parser.value(seed)));
        return std::nullopt;
    }
    return options;
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
    QCoreApplication::setApplicationName(QStringLiteral("hatpic-fw-host"));
    QCoreApplication::setApplicationVersion(QStringLiteral("0.1"));

    const std::optional<Options> options = parseOptions(app);
    if (!options)
        return kExitBadOptions;
    if (!quitOnSignals()) {
        printError(QStringLiteral("Cannot set up signal handling."));
        return kExitFailure;
    }

    FirmwareHost host(options->config);
    if (!serveOnPseudoTerminal(host, options->link, printError))
        return kExitFailure;
    for (const QString &warning : host.warnings())
        printError(warning);
    const FirmwareHost::Config &c = options->config;
    std::fprintf(stderr,
                 "hatpic-fw-host: servo id %d on %s at %u baud, center tick %d, timeout %u µs; "
                 "%g Hz control\n",
                 int(c.servoId), qPrintable(c.servoPath), c.servoBaud, int(c.centerTick),
                 c.servoTimeoutUs, c.rateHz);

    auto printFaults = [&host, &c] {
        if (const FaultInjector *faults = host.faults())
            printFaultReport("hatpic-fw-host", *faults, c.faultSeed);
    };
    if (host.faults() && !reportOnSignal(printFaults)) {
        printError(QStringLiteral("Cannot set up signal handling."));
        return kExitFailure;
    }

    QTimer report;
    if (!options->quiet) {
        QObject::connect(&report, &QTimer::timeout, &app,
                         [&host] { printReport("last", host.takeReport()); });
        report.start(kReportMs);
    }

    const int code = app.exec();
    report.stop();
    const FirmwareHost::Report total = host.totalReport();
    printFaults(); // before stop(), which ends the link
    host.stop();   // control thread joined, then torque off
    if (!options->quiet) {
        printReport("total", total);
        std::fprintf(stderr, "hatpic-fw-host: control thread %s; torque off\n",
                     host.realtime() ? "SCHED_FIFO" : "normal priority");
    }
    return code == 0 ? kExitOk : kExitFailure;
}
