// hatpic-sim: a simulated HATPIC joystick on a pseudo-terminal, in real time.
//
// Prints the slave path as the first stdout line, then runs until SIGINT/SIGTERM (exit 0).
// With --faults, prints what it injected on stderr at exit and on SIGUSR1.
// Bad options: one sentence on stderr, exit 4. Runtime failure (no pty, no link): exit 1.
#include "common/faultreport.h"
#include "common/ptyprogram.h"
#include "common/quitonsignal.h"
#include "sim/handinput.h"
#include "sim/simulateddevice.h"
#include "sim/simulatorhost.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

#include <cstdio>

#include <optional>

using namespace hatpic;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadOptions = 4;
constexpr double kMaxRateHz = 20000;  //!< highest --rate accepted [Hz]
constexpr double kLoadNoise = 0.0005; //!< std-dev of the load-reading noise [N·m]

void printError(const QString &sentence)
{
    std::fprintf(stderr, "hatpic-sim: %s\n", qPrintable(sentence));
}

struct Options
{
    SimulatedDevice::Config config;
    QString link;
};

// Parses the command line; prints the sentence and returns nullopt on a bad option.
std::optional<Options> parseOptions(const QCoreApplication &app)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Simulated HATPIC joystick on a pseudo-terminal. Prints the terminal's path as the "
        "first line, then runs until SIGINT or SIGTERM."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption protocolOption(QStringLiteral("protocol"),
                                            QStringLiteral("Wire protocol: v2 or legacy."),
                                            QStringLiteral("v2|legacy"), QStringLiteral("v2"));
    const QCommandLineOption rateOption(QStringLiteral("rate"),
                                        QStringLiteral("Control rate [Hz] (default 1000)."),
                                        QStringLiteral("HZ"), QStringLiteral("1000"));
    const QCommandLineOption baudOption(
        QStringLiteral("baud"),
        QStringLiteral("Emulated link baud rate (default 921600 for v2, 115200 for legacy)."),
        QStringLiteral("N"));
    const QCommandLineOption noThrottleOption(
        QStringLiteral("no-throttle"), QStringLiteral("Do not limit output to the baud rate."));
    const QCommandLineOption handOption(
        QStringLiteral("hand"),
        QStringLiteral("Operator input: idle, const:T, step:T[:T0], sine:A:F, chirp:A:F0:F1 "
                       "or hand:ANGLE (N·m, Hz, rad)."),
        QStringLiteral("SPEC"), QStringLiteral("idle"));
    const QCommandLineOption seedOption(QStringLiteral("seed"),
                                        QStringLiteral("Seed of the load-reading noise and "
                                                       "of the faults."),
                                        QStringLiteral("N"), QStringLiteral("1"));
    const QCommandLineOption stateOption(
        QStringLiteral("state"),
        QStringLiteral("Profile file that SAVE_PARAMS writes and power-up reads."),
        QStringLiteral("FILE"));
    const QCommandLineOption linkOption(
        QStringLiteral("link"),
        QStringLiteral("Symlink to create to the terminal (removed on "
                       "exit)."),
        QStringLiteral("PATH"));
    const QCommandLineOption faultsOption(
        QStringLiteral("faults"),
        QStringLiteral("Faults to inject on the link, e.g. "
                       "drop=0.01,corrupt=0.005,dup=0.002,delay=0.01:20ms,cut=30s:2s,hdrop=0.01 "
                       "(docs/simulator.md)."),
        QStringLiteral("SPEC"));
    parser.addOptions({protocolOption, rateOption, baudOption, noThrottleOption, handOption,
                       seedOption, stateOption, linkOption, faultsOption});

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
        printError(QStringLiteral("Unexpected argument \"%1\"; hatpic-sim takes only options.")
                       .arg(parser.positionalArguments().first()));
        return std::nullopt;
    }

    Options options;
    SimulatedDevice::Config &config = options.config;
    const QString protocol = parser.value(protocolOption);
    if (protocol == QLatin1String("v2")) {
        config.protocol = WireProtocol::V2;
    } else if (protocol == QLatin1String("legacy")) {
        config.protocol = WireProtocol::Legacy;
    } else {
        printError(QStringLiteral("Unknown protocol \"%1\"; use v2 or legacy.").arg(protocol));
        return std::nullopt;
    }

    bool ok = false;
    const double rate = parser.value(rateOption).toDouble(&ok);
    if (!ok || !(rate >= 1 && rate <= kMaxRateHz)) {
        printError(QStringLiteral("The control rate \"%1\" must be a number of Hz from 1 to %2.")
                       .arg(parser.value(rateOption))
                       .arg(kMaxRateHz));
        return std::nullopt;
    }
    config.controlRateHz = rate;

    if (parser.isSet(baudOption)) {
        const qint32 baud = parser.value(baudOption).toInt(&ok);
        if (!ok || baud < 300) {
            printError(QStringLiteral("The baud rate \"%1\" must be a whole number of at least "
                                      "300.")
                           .arg(parser.value(baudOption)));
            return std::nullopt;
        }
        config.baud = baud;
    }
    config.throttle = !parser.isSet(noThrottleOption);

    QString handError;
    const std::optional<HandInput> hand = HandInput::parse(parser.value(handOption), &handError);
    if (!hand) {
        printError(handError);
        return std::nullopt;
    }
    config.hand = *hand;

    const quint64 seed = parser.value(seedOption).toULongLong(&ok);
    if (!ok) {
        printError(QStringLiteral("The seed \"%1\" must be a non-negative whole number.")
                       .arg(parser.value(seedOption)));
        return std::nullopt;
    }
    config.seed = seed;
    config.noise = kLoadNoise;

    if (parser.isSet(stateOption)) {
        config.stateFile = parser.value(stateOption);
        if (config.stateFile.isEmpty()) {
            printError(QStringLiteral("The state file name is empty."));
            return std::nullopt;
        }
        // A pipe would block open() before any signal handling exists (Ctrl+C and SIGTERM
        // ignored); a device or folder is no place for parameters either.
        const QFileInfo state(config.stateFile);
        if (state.exists() && !state.isFile()) {
            printError(QStringLiteral("The state file \"%1\" is not a regular file (a pipe, a "
                                      "device or a folder).")
                           .arg(config.stateFile));
            return std::nullopt;
        }
    }
    if (parser.isSet(faultsOption)) {
        QString faultError;
        const std::optional<FaultSpec> faults =
            FaultSpec::parse(parser.value(faultsOption), &faultError);
        if (!faults) {
            printError(faultError);
            return std::nullopt;
        }
        config.faults = *faults;
    }
    if (parser.isSet(linkOption)) {
        options.link = parser.value(linkOption);
        if (options.link.isEmpty()) {
            printError(QStringLiteral("The link path is empty."));
            return std::nullopt;
        }
    }
    return options;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("hatpic-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral("0.1"));

    const std::optional<Options> options = parseOptions(app);
    if (!options)
        return kExitBadOptions;

    if (!quitOnSignals()) {
        printError(QStringLiteral("Cannot set up signal handling."));
        return kExitFailure;
    }

    SimulatorHost host(options->config);
    if (!host.device().stateWarning().isEmpty())
        printError(host.device().stateWarning());
    if (!serveOnPseudoTerminal(host, options->link, printError))
        return kExitFailure;
    std::fprintf(stderr, "hatpic-sim: %s protocol, %g Hz control, %d baud%s\n",
                 qPrintable(wireProtocolName(options->config.protocol)),
                 options->config.controlRateHz, host.device().baud(),
                 options->config.throttle ? "" : " (not throttled)");

    auto printFaults = [&host, &options] {
        if (const FaultInjector *faults = host.faults()) {
            printFaultReport("hatpic-sim", *faults, options->config.seed);
            // Losses that are not faults: the device's transmit queue was full (the simulator
            // fell behind real time), or the pty was (nobody read for a long while).
            std::fprintf(
                stderr, "hatpic-sim:   not sent: telemetry_dropped=%llu pty_discarded_bytes=%llu\n",
                static_cast<unsigned long long>(host.device().telemetryDropped()),
                static_cast<unsigned long long>(host.bytesDiscarded()));
            std::fflush(stderr);
        }
    };
    if (host.faults() && !reportOnSignal(printFaults)) {
        printError(QStringLiteral("Cannot set up signal handling."));
        return kExitFailure;
    }

    const int code = app.exec();
    host.stop();
    printFaults();
    return code == 0 ? kExitOk : kExitFailure;
}
