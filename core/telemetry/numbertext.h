// Compact, exact number text for recordings and event descriptions.
#pragma once

#include <QByteArray>
#include <QString>

namespace hatpic {

//! Shortest decimal text that reads back as `value`. Values that are exactly a float (all
//! telemetry travels as f32) are written with the float's shortest digits ("0.05", not
//! "0.05000000074505806"), so they read back as that float; any other value gets the
//! double's shortest round-trip digits. Non-finite values give "nan", "inf", "-inf".
QByteArray compactNumber(double value);
QString compactNumberText(double value);

} // namespace hatpic
