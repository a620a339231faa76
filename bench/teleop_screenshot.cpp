// teleop_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot-teleop.png: the real main
// window on the built-in simulator, the simulated hand pushing 0.05 N·m, the demo's profile
// (resources/teleop/teleop-demo.json) and its robot bridge on ROS 2, with hatpic-robot-sim's
// robot in this process (the same RobotSimulator, on the same domain): the knob pushed into the
// robot's wall, the Bridge panel scrolled to the robot side and the passivity observer. Run it
// under Xvfb, confined to loopback (docs/teleop.md):
//   ROS_DOMAIN_ID=77 ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST xvfb-run -a -s
//   "-screen 0 1920x1080x24" build/bench/teleop_screenshot docs/screenshot-teleop.png 1920 1080
#include "robotsim/robotsimulator.h"
#include "screenshotwindow.h"

#include <QDockWidget>
#include <QScrollArea>

#include <memory>

using namespace hatpic;

int main(int argc, char *argv[])
{
    std::unique_ptr<robot::RobotSimulator> robot;
    const int code = runScreenshot(
        argc, argv, "teleop_screenshot", 11000, [&robot](MainWindow &window, QSize size) {
            std::string why;
            robot = robot::RobotSimulator::start(robot::RobotSimSettings{}, &why);
            if (!robot) {
                std::fprintf(stderr, "teleop_screenshot: the robot: %s\n", why.c_str());
                QApplication::exit(1);
                return;
            }
            QString error;
            if (!window.openProfile(
                    QStringLiteral(HATPIC_SOURCE_DIR "/resources/teleop/teleop-demo.json"), &error))
                std::fprintf(stderr, "teleop_screenshot: %s\n", qPrintable(error));
            window.setSimulatedHand(HandInput{HandInput::Kind::Constant, 0.05});
            window.startBridge(2);
            auto *dock = window.findChild<QDockWidget *>(QStringLiteral("bridgeDock"));
            window.resizeDocks({dock}, {size.height() / 2}, Qt::Vertical);
            QTimer::singleShot(10500, &window, [&window] {
                QWidget *passivity =
                    window.findChild<QWidget *>(QStringLiteral("bridge_section_passivity"));
                QWidget *panel = window.findChild<QWidget *>(QStringLiteral("bridgePanel"));
                if (auto *scroll = panel ? panel->findChild<QScrollArea *>() : nullptr;
                    scroll && passivity)
                    scroll->ensureWidgetVisible(passivity, 0, 0);
            });
        });
    robot.reset();
    return code;
}
