// hatpic-robot-sim's command line (robot.md): every option validated, a bad one named with its
// rule and value.
#pragma once

#include "robotsim/robotsimulator.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace hatpic::robot {

//! The settings from `arguments` (argv, program name first) and the environment
//! (ROS_DOMAIN_ID). nullopt with `*help` set for --help, or with `*error` one sentence.
std::optional<RobotSimSettings> parseRobotSimOptions(const QStringList &arguments, QString *help,
                                                     QString *error);

} // namespace hatpic::robot
