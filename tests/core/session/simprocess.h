// hatpic-sim as a child process on a pseudo-terminal, for the session tests that talk to it
// (tst_sessionpty, tst_sessioneffects, tst_sessionpassivity).
#pragma once

#include "ptyprogram.h"

namespace hatpic::test {

//! hatpic-sim as a child process; the first line it prints is the pty's slave path (none when
//! the build has no hatpic-sim).
class SimProcess : public PtyProgram
{
public:
    explicit SimProcess(const QStringList &arguments) : PtyProgram(program(), arguments) {}

private:
    static QString program()
    {
#ifdef HATPIC_SIM_PATH
        return QStringLiteral(HATPIC_SIM_PATH);
#else
        return {};
#endif
    }
};

} // namespace hatpic::test
