#include "deviceoptions.h"

#include "console.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <cmath>

namespace hatpic::cli {

void addDeviceOptions(QCommandLineParser &parser)
{
    parser.addOption(QCommandLineOption(
        QStringList{QStringLiteral("p"), QStringLiteral("port")},
        QStringLiteral("Serial device (e.g. /dev/ttyUSB0, a pty) or 'sim' for the built-in "
                       "simulated joystick. Required; 'hatpicctl ports' lists them."),
        QStringLiteral("PORT")));
    parser.addOption(QCommandLineOption(
        QStringList{QStringLiteral("baud")},
        QStringLiteral("Baud rate (default: 921600 for v2, 115200 for legacy; auto listens at "
                       "115200, then asks at 921600)."),
        QStringLiteral("N")));
    parser.addOption(
        QCommandLineOption(QStringList{QStringLiteral("protocol")},
                           QStringLiteral("auto (detect), v2 or legacy (default: auto)."),
                           QStringLiteral("NAME"), QStringLiteral("auto")));
    parser.addOption(QCommandLineOption(
        QStringList{QStringLiteral("timeout")},
        QStringLiteral("Longest wait for the connection and for each answer, in seconds "
                       "(default: 5)."),
        QStringLiteral("S"), QStringLiteral("5")));
    parser.addOption(QCommandLineOption(
        QStringList{QStringLiteral("faults")},
        QStringLiteral("With --port sim: faults the simulated link injects, e.g. "
                       "drop=0.01,cut=30s:2s (docs/simulator.md)."),
        QStringLiteral("SPEC")));
    parser.addOption(QCommandLineOption(
        QStringList{QStringLiteral("seed")},
        QStringLiteral("With --port sim: seed of the faults and the load noise (default: 1)."),
        QStringLiteral("N")));
}

std::optional<DeviceOptions> deviceOptions(const QCommandLineParser &parser)
{
    DeviceOptions options;
    options.connect.autoReconnect = false;

    const QString port = parser.value(QStringLiteral("port"));
    if (port.isEmpty()) {
        printError(QStringLiteral("This command needs --port: a serial device path, or 'sim' "
                                  "for the built-in simulated joystick."));
        return std::nullopt;
    }
    options.connect.port = port;

    if (parser.isSet(QStringLiteral("baud"))) {
        bool ok = false;
        const int baud = parser.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || baud <= 0) {
            printError(u"--baud must be a positive whole number, got '" +
                       parser.value(QStringLiteral("baud")) + u"'.");
            return std::nullopt;
        }
        options.connect.baud = baud;
    }

    const QString protocol = parser.value(QStringLiteral("protocol"));
    if (protocol == u"auto")
        options.connect.protocol = ProtocolChoice::Auto;
    else if (protocol == u"v2")
        options.connect.protocol = ProtocolChoice::V2;
    else if (protocol == u"legacy")
        options.connect.protocol = ProtocolChoice::Legacy;
    else {
        printError(u"--protocol must be auto, v2 or legacy, got '" + protocol + u"'.");
        return std::nullopt;
    }

    bool ok = false;
    const double timeout = parser.value(QStringLiteral("timeout")).toDouble(&ok);
    if (!ok || !std::isfinite(timeout) || timeout <= 0 || timeout > 3600) {
        printError(u"--timeout must be a number of seconds above 0 and at most 3600, got '" +
                   parser.value(QStringLiteral("timeout")) + u"'.");
        return std::nullopt;
    }
    options.timeoutS = timeout;

    const bool sim = port == QStringView(kSimPortName);
    if (parser.isSet(QStringLiteral("faults"))) {
        QString error;
        const auto faults = FaultSpec::parse(parser.value(QStringLiteral("faults")), &error);
        if (!faults) {
            printError(u"--faults: " + error);
            return std::nullopt;
        }
        options.connect.sim.faults = *faults;
    }
    if (parser.isSet(QStringLiteral("seed"))) {
        options.connect.sim.seed = parser.value(QStringLiteral("seed")).toULongLong(&ok);
        if (!ok) {
            printError(u"--seed must be a non-negative whole number, got '" +
                       parser.value(QStringLiteral("seed")) + u"'.");
            return std::nullopt;
        }
    }
    if (!sim && (parser.isSet(QStringLiteral("faults")) || parser.isSet(QStringLiteral("seed")))) {
        printError(QStringLiteral("--faults and --seed act on the built-in simulated joystick: "
                                  "use them with --port sim (hatpic-sim has its own)."));
        return std::nullopt;
    }
    return options;
}

} // namespace hatpic::cli
