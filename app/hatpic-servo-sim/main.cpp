// hatpic-servo-sim: an emulated Feetech STS3032 on a pseudo-terminal, in real time — the servo
// bus of servo.md for hatpic-fw-host to drive without hardware.
//
// Prints the slave path as the first stdout line, then runs until SIGINT/SIGTERM (exit 0).
// Changes of the torque enable register are reported on stderr ("torque on" / "torque off").
// Bad options: one sentence on stderr, exit 4. Runtime failure (no pty, no link): exit 1.
#include "common/ptyprogram.h"
#include "common/quitonsignal.h"
#include "sim/servobushost.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>
#include <optional>

using namespace hatpic;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadOptions = 4;
constexpr double kLoadNoise = 0.0005; //!< std-dev of the load-reading noise, as hatpic-sim [N·m]

void printError(const QString &sentence)
{
    std::fprintf(stderr, "hatpic-servo-sim: %s\n", qPrintable(sentence));
}

struct Options
{
    ServoBusHost::Config config;
    QString link;
};

std::optional<Options> parseOptions(const QCoreApplication &app)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Emulated STS3032 servo (bus of servo.md) on a pseudo-terminal. Prints "
                       "the terminal's path as the first line, then runs until SIGINT or "
                       "SIGTERM."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption handOption(
        QStringLiteral("hand"),
        QStringLiteral("Operator input: idle, const:T, step:T[:T0], sine:A:F, chirp:A:F0:F1 "
                       "or hand:ANGLE (N·m, Hz, rad)."),
        QStringLiteral("SPEC"), QStringLiteral("idle"));
    const QCommandLineOption seedOption(QStringLiteral("seed"),
                                        QStringLiteral("Seed of the load-reading noise."),
                                        QStringLiteral("N"), QStringLiteral("1"));
    const QCommandLineOption idOption(QStringLiteral("servo-id"),
                                      QStringLiteral("Servo id on the bus, 0…253 (default 1)."),
                                      QStringLiteral("N"), QStringLiteral("1"));
    const QCommandLineOption centerOption(
        QStringLiteral("center-tick"),
        QStringLiteral("Present position at the knob's rest, 0…4095 (default 1000)."),
        QStringLiteral("N"), QStringLiteral("1000"));
    const QCommandLineOption linkOption(
        QStringLiteral("link"),
        QStringLiteral("Symlink to create to the terminal (removed on exit)."),
        QStringLiteral("PATH"));
    parser.addOptions({handOption, seedOption, idOption, centerOption, linkOption});

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
        printError(QStringLiteral("Unexpected argument \"%1\"; hatpic-servo-sim takes only "
                                  "options.")
                       .arg(parser.positionalArguments().first()));
        return std::nullopt;
    }

    Options options;
    ServoBusHost::Config &config = options.config;
    QString handError;
    const std::optional<HandInput> hand = HandInput::parse(parser.value(handOption), &handError);
    if (!hand) {
        printError(handError);
        return std::nullopt;
    }
    config.hand = *hand;
    bool ok = false;
    config.seed = parser.value(seedOption).toULongLong(&ok);
    if (!ok) {
        printError(QStringLiteral("The seed \"%1\" must be a non-negative whole number.")
                       .arg(parser.value(seedOption)));
        return std::nullopt;
    }
    config.noise = kLoadNoise;
    const uint id = parser.value(idOption).toUInt(&ok);
    if (!ok || id > 253) {
        printError(QStringLiteral("The servo id \"%1\" must be a whole number from 0 to 253.")
                       .arg(parser.value(idOption)));
        return std::nullopt;
    }
    config.id = std::uint8_t(id);
    const uint center = parser.value(centerOption).toUInt(&ok);
    if (!ok || center > 4095) {
        printError(QStringLiteral("The center tick \"%1\" must be a whole number from 0 to "
                                  "4095.")
                       .arg(parser.value(centerOption)));
        return std::nullopt;
    }
    config.centerTick = std::int32_t(center);
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
    QCoreApplication::setApplicationName(QStringLiteral("hatpic-servo-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral("0.1"));

    const std::optional<Options> options = parseOptions(app);
    if (!options)
        return kExitBadOptions;
    if (!quitOnSignals()) {
        printError(QStringLiteral("Cannot set up signal handling."));
        return kExitFailure;
    }

    ServoBusHost host(options->config);
    if (!serveOnPseudoTerminal(host, options->link, printError))
        return kExitFailure;
    QObject::connect(&host, &ServoBusHost::torqueEnableChanged, &app, [](bool enabled) {
        std::fprintf(stderr, "hatpic-servo-sim: torque %s\n", enabled ? "on" : "off");
    });
    std::fprintf(stderr, "hatpic-servo-sim: STS3032 id %d, center tick %d, hand %s; torque %s\n",
                 int(options->config.id), int(options->config.centerTick),
                 qPrintable(options->config.hand.toSpec()), host.torqueEnabled() ? "on" : "off");

    const int code = app.exec();
    host.stop();
    return code == 0 ? kExitOk : kExitFailure;
}
