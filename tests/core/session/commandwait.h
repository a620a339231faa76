// Waiting for a command's result in the session tests: the one helper they share.
#pragma once

#include "session/sessiontypes.h"

#include <QSignalSpy>
#include <QTest>

namespace hatpic::test {

//! The result of the command `id` once DeviceClient::commandFinished (spied by `finished`)
//! reported it; a Timeout result when it did not within `timeoutMs`.
inline CommandResult waitForCommand(QSignalSpy &finished, quint64 id, int timeoutMs)
{
    auto find = [&]() -> const QList<QVariant> * {
        for (const QList<QVariant> &args : std::as_const(finished)) {
            if (args.first().toULongLong() == id)
                return &args;
        }
        return nullptr;
    };
    if (!QTest::qWaitFor([&] { return find() != nullptr; }, timeoutMs))
        return commandResult(CommandKind::Hello, CommandResult::Status::Timeout);
    const QList<QVariant> *args = find();
    return args ? args->last().value<CommandResult>()
                : commandResult(CommandKind::Hello, CommandResult::Status::Timeout);
}

} // namespace hatpic::test
