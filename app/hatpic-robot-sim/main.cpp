// hatpic-robot-sim: a simulated robot at the other end of hatpic-bridge (robot.md,
// docs/teleop.md). Exit 0 after SIGINT/SIGTERM; bad options: one sentence on stderr, exit 4;
// the middleware refused: exit 1 (common/exitcodes.h).
#include "robotsimoptions.h"

#include "common/exitcodes.h"
#include "common/quitonsignal.h"
#include "ros/node.h"

#include <QCoreApplication>
#include <QTimer>

#include <cstdio>

using namespace hatpic;

namespace {

void printError(const QString &sentence)
{
    std::fprintf(stderr, "hatpic-robot-sim: %s\n", qPrintable(sentence));
}

void printStatus(const robot::RobotSimulator::Status &s)
{
    std::fprintf(stdout, "%s\n", s.line().c_str());
    std::fflush(stdout);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("hatpic-robot-sim"));
    QString help, error;
    const auto settings = robot::parseRobotSimOptions(QCoreApplication::arguments(), &help, &error);
    if (!settings) {
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
    std::string why;
    auto robot = robot::RobotSimulator::start(*settings, &why);
    if (!robot) {
        printError(QString::fromStdString(why));
        return ExitFailure;
    }
    std::fprintf(stderr, "hatpic-robot-sim: on %s\n", robot->where().c_str());
    QTimer status;
    QObject::connect(&status, &QTimer::timeout, &app, [&robot] { printStatus(robot->status()); });
    status.start(1000);
    app.exec();
    robot.reset();
    return ExitSuccess;
}
