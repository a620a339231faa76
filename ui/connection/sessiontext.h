// The tuner's words (translatable) for what the device session reports in codes and numbers:
// the state's detail and the session's notices (a command's failure: editor/commandtext.h).
#pragma once

#include "session/sessiontypes.h"

#include <QCoreApplication>
#include <QString>

namespace hatpic {

class SessionText
{
    Q_DECLARE_TR_FUNCTIONS(SessionText)
public:
    //! "/dev/ttyUSB0 at 921600 baud", or "the simulated joystick".
    static QString port(const StateDetail &detail);
    //! One sentence for the status bar and the link banner; empty for Kind::None.
    static QString stateDetail(const StateDetail &detail);
    static QString notice(const SessionNotice &notice);
};

} // namespace hatpic
