#include "hatpic-tuner/tuneroptions.h"

#include "common/connectionoptions.h"
#include "common/exitcodes.h"
#include "plots/plotpanel.h"
#include "window/mainwindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace Qt::StringLiterals;

namespace hatpic {

namespace {

constexpr double kMaxQuitAfterSeconds = 604800; //!< --quit-after: at most one week [s]

void fail(const QString &message)
{
    std::fprintf(stderr, "hatpic-tuner: %s\n", qPrintable(message));
}

// Qt's own options (-platform, -style, …) are known only to a QApplication, and --help-all
// lists them. One on the offscreen platform, which needs no display, parses the command line
// as process() does (a bad option or help: a message and exit), then goes. The user's
// arguments come first, so the appended -platform wins only for this one.
void parseWithQt(int argc, char *argv[], QCommandLineParser &parser)
{
    static char platform[] = "-platform";
    static char offscreen[] = "offscreen";
    std::vector<char *> arguments(argv, argv + argc);
    arguments.push_back(platform);
    arguments.push_back(offscreen);
    arguments.push_back(nullptr);
    int count = argc + 2;
    const QApplication probe(count, arguments.data());
    // A bad option is bad usage, as in every program (Qt's process() would exit 1).
    if (!parser.parse(QCoreApplication::arguments())) {
        fail(parser.errorText());
        std::exit(ExitBadUsage);
    }
    parser.process(probe); // help, help-all, version: printed, then exits
}

// True when every argument that looks like an option is one of `names` spelt out ("--port",
// "--port=X", "-p"): QApplication then takes none of them, and the parser sees them as they
// are. Anything else ("-platform", "-pX", a value starting with '-') may be Qt's.
bool onlyOwnOptions(const QStringList &arguments, const QStringList &names)
{
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments[i];
        if (!a.startsWith(u'-') || a == u"-")
            continue;
        const bool own = a.startsWith(u"--")
                             ? a.size() > 3 && names.contains(a.mid(2).section(u'=', 0, 0))
                             : a.size() == 2 && names.contains(a.mid(1));
        if (!own)
            return false;
    }
    return true;
}

} // namespace

std::variant<TunerOptions, int> readTunerOptions(int argc, char *argv[])
{
    // --version answers without a display (over ssh, in a package check): before QApplication,
    // which needs one. The same text as QCommandLineParser's.
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--version") == 0 || std::strcmp(argv[i], "-v") == 0) {
            std::printf("hatpic-tuner %s\n", HATPIC_VERSION);
            return 0;
        }
    }
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Tune, plot and record the HATPIC single-axis haptic joystick."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption port = connectionOption(
        ConnectionOption::Port,
        QStringLiteral("Connect at once to PORT (a serial port or pty), or 'sim' for the "
                       "built-in simulated joystick."));
    const QCommandLineOption baud = connectionOption(ConnectionOption::Baud);
    const QCommandLineOption protocol = connectionOption(ConnectionOption::Protocol);
    const auto option = [](const QString &name, const QString &help, const QString &value) {
        return QCommandLineOption(name, help, value);
    };
    const QCommandLineOption profile =
        option(u"profile"_s, u"Open this profile (JSON) in the editor."_s, u"FILE"_s);
    const QCommandLineOption hand =
        option(u"hand"_s,
               u"Simulated operator input (docs/cli.md), e.g. sine:0.06:0.2 or hand:0.3; "
               "default for --port sim: a gentle sine."_s,
               u"SPEC"_s);
    const QCommandLineOption repaint = option(
        u"repaint-rate"_s,
        u"Plot repaint rate in Hz (default %1)."_s.arg(PlotPanel::kDefaultRepaintHz), u"HZ"_s);
    const QCommandLineOption quitAfter =
        option(u"quit-after"_s,
               u"Close the window after SECONDS (for scripted screenshots and measurements)."_s,
               u"SECONDS"_s);
    const QCommandLineOption faults = connectionOption(ConnectionOption::Faults);
    const QCommandLineOption seed = connectionOption(ConnectionOption::Seed);
    const QCommandLineOption bridge =
        option(u"bridge"_s,
               u"Open the Bridge panel and start the robot bridge on ROS 1 or ROS 2, with the "
               "profile's bridge settings (docs/teleop.md)."_s,
               u"1|2"_s);
    const QCommandLineOption record =
        option(u"record"_s,
               u"Record every sample to FILE.csv (and its .json) once connected, as Record does."_s,
               u"FILE.csv"_s);
    parser.addOptions(
        {port, baud, protocol, profile, hand, repaint, quitAfter, faults, seed, bridge, record});
    parser.addPositionalArgument(QStringLiteral("recording"),
                                 QStringLiteral("A recording (CSV) to open in replay."),
                                 QStringLiteral("[RECORDING.csv]"));
    // Help and option errors need no display: the options are parsed before QApplication.
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    QStringList names{u"h"_s, u"help"_s, u"help-all"_s, u"v"_s, u"version"_s};
    for (const QCommandLineOption *o : {&port, &baud, &protocol, &profile, &hand, &repaint,
                                        &quitAfter, &faults, &seed, &bridge, &record})
        names << o->names();
    if (!onlyOwnOptions(arguments, names) || !parser.parse(arguments) ||
        parser.isSet(QStringLiteral("help-all"))) {
        parseWithQt(argc, argv, parser); // maybe Qt's own options; exits unless they were
    } else if (parser.isSet(QStringLiteral("help"))) {
        // As process() prints it; without an application object Qt cannot name the program.
        std::fputs(qPrintable(parser.helpText().replace(QStringLiteral("<executable_name>"),
                                                        arguments.constFirst())),
                   stdout);
        return 0;
    }

    TunerOptions o;
    if (QString error; !readConnectionOptions(parser, o.connection, &error)) {
        fail(error);
        return ExitBadUsage;
    }
    if (parser.isSet(hand)) {
        QString error;
        o.hand = HandInput::parse(parser.value(hand), &error);
        if (!o.hand) {
            fail(QStringLiteral("--hand: %1").arg(error));
            return ExitBadUsage;
        }
    }
    o.repaintHz = PlotPanel::kDefaultRepaintHz;
    if (parser.isSet(repaint)) {
        bool ok = false;
        o.repaintHz = parser.value(repaint).toDouble(&ok);
        // NaN passes neither comparison, so finiteness is checked on its own.
        if (!ok || !std::isfinite(o.repaintHz) || o.repaintHz < 1 || o.repaintHz > 240) {
            fail(QStringLiteral("--repaint-rate: expected 1 to 240 Hz, got \"%1\"")
                     .arg(parser.value(repaint)));
            return ExitBadUsage;
        }
    }
    if (parser.isSet(quitAfter)) {
        bool ok = false;
        o.quitAfterSeconds = parser.value(quitAfter).toDouble(&ok);
        if (!ok || !std::isfinite(o.quitAfterSeconds) || o.quitAfterSeconds < 0 ||
            o.quitAfterSeconds > kMaxQuitAfterSeconds) {
            fail(QStringLiteral("--quit-after: expected 0 to %1 seconds, got \"%2\"")
                     .arg(kMaxQuitAfterSeconds)
                     .arg(parser.value(quitAfter)));
            return ExitBadUsage;
        }
    }
    if (parser.isSet(bridge)) {
        const QString v = parser.value(bridge).trimmed();
        if (v != u"1" && v != u"2") {
            fail(QStringLiteral("--bridge: expected 1 or 2 (the ROS version), got \"%1\"")
                     .arg(parser.value(bridge).left(40)));
            return ExitBadUsage;
        }
        o.bridgeRos = v.toInt();
    }
    if (parser.positionalArguments().size() > 1) {
        fail(QStringLiteral("at most one recording can be opened"));
        return ExitBadUsage;
    }

    if (parser.isSet(record) && o.connection.port.isEmpty()) {
        fail(QStringLiteral("--record needs --port: a recording is of a connected device"));
        return ExitBadUsage;
    }
    o.profile = parser.value(profile);
    o.record = parser.value(record);
    if (!parser.positionalArguments().isEmpty())
        o.recording = parser.positionalArguments().constFirst();

    return o;
}

void applyTunerOptions(const TunerOptions &o, MainWindow &window)
{
    window.setRepaintRate(o.repaintHz);
    if (!o.profile.isEmpty()) {
        QString error;
        if (!window.openProfile(o.profile, &error))
            fail(QStringLiteral("--profile: %1").arg(error));
    }
    if (o.hand)
        window.setSimulatedHand(*o.hand);
    window.show();
    if (!o.record.isEmpty())
        window.recordOnConnect(o.record);
    if (!o.connection.port.isEmpty())
        window.connectTo(o.connection);
    if (o.bridgeRos != 0 && !window.startBridge(o.bridgeRos))
        fail(QStringLiteral("--bridge: the robot bridge did not start; the Bridge panel says why"));
    if (!o.recording.isEmpty()) {
        QString error;
        if (!window.openRecording(o.recording, &error))
            fail(error);
    }
    if (o.quitAfterSeconds >= 0)
        QTimer::singleShot(static_cast<int>(std::lround(o.quitAfterSeconds * 1000)), &window,
                           &QWidget::close);
}

} // namespace hatpic
