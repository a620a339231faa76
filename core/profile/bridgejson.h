// The `bridge` object of a profile's `host` block (profile.md): the robot bridge's settings as
// JSON. Written and read here, and nowhere else; the bounds are bridgesettings.h's validate().
#pragma once

#include "bridgesettings.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace hatpic {

//! The key of the bridge object inside `host`.
inline constexpr char kHostBridgeKey[] = "bridge";

//! The `bridge` object: every setting a profile keeps, in profile.md's order. The network
//! settings (DDS domain, ROS version) are not among them: they belong to the network a machine
//! is on (ROS_DOMAIN_ID, --ros), not to a tuning (withNetworkOf()).
QByteArray bridgeSettingsJson(const bridge::BridgeSettings &settings, int indent);
//! Reads a `bridge` object into `settings`: a missing key keeps its value; a value of the wrong
//! type is reported in `errors` ("<prefix>gain: must be a number, got \"a\""), unknown keys in
//! `warnings`. Then every rule of validate() that the result breaks is reported once
//! ("<prefix>gain: must be …"). The network settings of `settings` are left as they are.
void readBridgeSettings(const QJsonObject &object, const QString &prefix,
                        bridge::BridgeSettings &settings, QStringList &errors,
                        QStringList &warnings);

} // namespace hatpic
