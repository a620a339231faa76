// The programs (hatpicctl, hatpic-bridge) report each failure once, in the session's sentences
// (session/sessionwording.h); the library's own log lines ("hatpic.*" categories) would repeat
// them.
#pragma once

#include <QLoggingCategory>

namespace hatpic::cli {

//! Turns the library's log off. QT_LOGGING_RULES="hatpic.*=true" brings it back (the
//! environment takes precedence).
inline void silenceLibraryLog()
{
    QLoggingCategory::setFilterRules(QStringLiteral("hatpic.*=false"));
}

} // namespace hatpic::cli
