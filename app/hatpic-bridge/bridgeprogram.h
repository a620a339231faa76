// hatpic-bridge at run time: a DeviceClient that keeps reconnecting, the Bridge on top of it,
// statistics once a second, and a shutdown that leaves the device with τ_ext = 0.
#pragma once

#include "bridgeoptions.h"

#include "bridge/bridge.h"
#include "profile/profile.h"
#include "session/deviceclient.h"

#include <QObject>
#include <QTimer>

#include <optional>

namespace hatpic::bridge {

class BridgeProgram : public QObject
{
    Q_OBJECT
public:
    static constexpr int kStatsIntervalMs = 1000;
    static constexpr int kRetryIntervalMs = 1000; //!< a first connection that failed
    static constexpr int kZeroConfirmMs = 300;    //!< longest wait for τ_ext 0 at shutdown

    explicit BridgeProgram(const AppOptions &options, QObject *parent = nullptr);

    //! Opens the DDS endpoints, starts connecting. Empty or one sentence.
    QString start();
    //! τ_ext 0 to the device (waiting until its telemetry shows it and /hatpic/feedback has
    //! published it, at most kZeroConfirmMs), then closes the endpoints and the port.
    void shutdown();

    //! ExitSuccess, or ExitBadUsage once an option was refused that only the connected device
    //! could judge (a --limit above its tau_limit, a --profile whose device block it refuses).
    int exitCode() const { return m_exitCode; }

Q_SIGNALS:
    //! An option was refused after connecting (said on stderr, the feedback released): the
    //! program ends with exitCode().
    void refused();

private:
    void refuse(const QString &sentence);
    void onStateChanged(SessionState state, const StateDetail &detail);
    void onConnected();
    void printStats();

    AppOptions m_options;
    DeviceClient m_client;
    Bridge m_bridge;
    QTimer m_statsTimer;
    QTimer m_retryTimer;
    //! τ_ext of the newest sample while connected; none once the link is gone [N·m]
    //! Connected: the bridge's figure of the device's τ_ext is the device's now (stats()).
    bool m_deviceKnown = false;
    bool m_closing = false;
    //! Why the robot path's threads may not run real-time; empty when they may.
    QString m_realtimeProblem;
    int m_exitCode = 0; //!< ExitCode (common/exitcodes.h)
};

} // namespace hatpic::bridge
