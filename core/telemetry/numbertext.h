// The one text form of a measured value: CSV cells (recordings, hatpicctl's CSV forms, the plots'
// export), event descriptions, and the values a device reports as the CLI shows them.
#pragma once

#include <QString>

namespace hatpic {

//! Shortest decimal text that reads back as `value` (std::to_chars). Values that are exactly a
//! float (all telemetry and every device parameter travel as f32) are written with the float's
//! shortest digits ("0.05", not "0.05000000074505806"), so they read back as that float; any
//! other value gets the double's shortest round-trip digits. −0 is written "0" (e.g. −K_rec·0,
//! which reads as noise in a table); non-finite values give "nan", "inf", "-inf".
QString compactNumberText(double value);

} // namespace hatpic
