// hatpic-bridge: the joystick on ROS 2 (or ROS 1) and the robot's wrench back in the operator's
// hand (docs/ros.md). Exit 0 after SIGINT/SIGTERM; bad options: one sentence on stderr, exit 4,
// also when only the connected device can tell (a --limit above its tau_limit); the middleware
// refused (or that ROS is not built in): exit 1 (common/exitcodes.h).
#include "bridgeoptions.h"
#include "bridgeprogram.h"

#include "common/exitcodes.h"
#include "common/librarylog.h"
#include "common/quitonsignal.h"
#include "session/sessiontypes.h"

#include "ros/node.h"

#include <QCoreApplication>

#include <cstdio>

using namespace hatpic;

namespace {

void printError(const QString &sentence)
{
    std::fprintf(stderr, "hatpic-bridge: %s\n", qPrintable(sentence));
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("hatpic-bridge"));
    registerSessionMetaTypes();
    cli::silenceLibraryLog(); // a lost device is reported once, in the bridge's own words

    QString help, error;
    const auto options = bridge::parseAppOptions(QCoreApplication::arguments(), &help, &error);
    if (!options) {
        if (!error.isEmpty()) {
            printError(error);
            return ExitBadUsage;
        }
        std::fputs(qPrintable(help), stdout);
        return ExitSuccess;
    }
    if (!quitOnSignals()) {
        printError(QStringLiteral("Cannot install the signal handlers."));
        return ExitFailure;
    }
    ros::setExitWhenShutDownByMaster(true); // ros.md § ROS 1
    bridge::BridgeProgram program(*options);
    if (const QString failure = program.start(); !failure.isEmpty()) {
        printError(failure);
        return ExitFailure;
    }
    QObject::connect(&program, &bridge::BridgeProgram::refused, &app, &QCoreApplication::quit,
                     Qt::QueuedConnection);
    app.exec();
    program.shutdown();
    return program.exitCode();
}
