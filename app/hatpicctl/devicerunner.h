// Runs a DeviceClient from a command-line program: connect, issue one command and wait for its
// result, or let the link run for a while — each with a deadline, on a local event loop.
//
// Lives on the main thread. Every failure is printed as one sentence on stderr and returned
// as an ExitCode, so a subcommand can simply `return` what these functions give. The device's
// LOG lines go to stderr as they arrive ("hatpicctl: device: …").
#pragma once

#include "deviceoptions.h"

#include "session/deviceclient.h"

#include <QObject>

#include <functional>

namespace hatpic::cli {

class DeviceRunner
{
public:
    explicit DeviceRunner(const DeviceOptions &options);
    ~DeviceRunner(); //!< closes the link
    DeviceRunner(const DeviceRunner &) = delete;
    DeviceRunner &operator=(const DeviceRunner &) = delete;

    DeviceClient &client() { return m_client; }
    const DeviceOptions &options() const { return m_options; }

    //! Opens the port and waits until the session reports Connected.
    int connect();
    //! Sends `request` and waits for its outcome, which is stored in `*outcome` when given,
    //! whatever it is — also when the link was lost (the loss is reported and ExitNoDevice
    //! returned), if the outcome came.
    int runCommand(const Request &request, Outcome *outcome = nullptr);
    //! Lets the link run for `seconds` (≤ 0: no limit) or until `stop()` returns true; `stop`
    //! is checked whenever the client reports anything and when wake() is called — nothing
    //! polls it. A lost link gives ExitNoDevice *without* printing, so the caller can report
    //! first; then it calls reportLoss().
    int runFor(double seconds, const std::function<bool()> &stop);
    //! What a running wait's condition reads changed without the client saying so (an
    //! interrupt, an experiment's end): it is checked now. Nothing when no wait runs.
    void wake();
    //! Prints why the link went away; returns ExitNoDevice.
    int reportLoss() const;

    //! Exit code for a request's outcome (0, 2, 3 or 4); prints its sentence unless done.
    static int reportOutcome(const Outcome &outcome);

private:
    enum class Wait { Done, TimedOut, Lost };
    Wait wait(const std::function<bool()> &done, double seconds);
    void onStateChanged(SessionState state, const StateDetail &detail);

    DeviceOptions m_options;
    DeviceClient m_client;
    QObject m_context;      //!< receiver of the runner's own connections
    bool m_started = false; //!< connectDevice() was called
    bool m_closing = false; //!< we asked to disconnect; a Disconnected state is expected
    bool m_lost = false;    //!< the link went away (or never came up)
    QString m_lostDetail;   //!< the session's reason
    //! While a wait runs: re-checks its condition at once (wake(), a request's outcome).
    std::function<void()> m_wake;
};

} // namespace hatpic::cli
