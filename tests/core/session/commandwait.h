// Waiting for a request's outcome in the session tests: the one helper they share.
#pragma once

#include "session/deviceclient.h"

#include <QObject>
#include <QTest>

#include <optional>

namespace hatpic::test {

//! Sends `request` through `client` and returns its outcome once it came; a TimedOut at HELLO
//! (which no request has) when it did not within `timeoutMs` (a later one then goes nowhere).
inline Outcome waitForOutcome(DeviceClient &client, const Request &request, int timeoutMs)
{
    QObject waiter;
    std::optional<Outcome> outcome;
    client.request(request, CommandDone{&waiter, [&outcome](const Outcome &o) { outcome = o; }});
    if (!QTest::qWaitFor([&] { return outcome.has_value(); }, timeoutMs))
        return Outcome{request, outcome::TimedOut{{CommandKind::Hello, {}}, 0, timeoutMs}, {}};
    return *outcome;
}

} // namespace hatpic::test
