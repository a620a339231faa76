// Waiting for a command's outcome in the session tests: the one helper they share.
#pragma once

#include "session/deviceclient.h"

#include <QObject>
#include <QTest>

#include <optional>

namespace hatpic::test {

//! Calls `issue` with a CommandDone of this call's own, which `issue` hands to one of
//! DeviceClient's commands, and returns that command's outcome once it came; a Timeout result
//! when it did not within `timeoutMs` (a later one then goes nowhere).
template<typename Issue> CommandResult waitForCommand(Issue issue, int timeoutMs)
{
    QObject waiter;
    std::optional<CommandResult> outcome;
    issue(CommandDone{&waiter, [&outcome](const CommandResult &r) { outcome = r; }});
    if (!QTest::qWaitFor([&] { return outcome.has_value(); }, timeoutMs))
        return commandResult(CommandKind::Hello, CommandResult::Status::Timeout);
    return *outcome;
}

} // namespace hatpic::test
