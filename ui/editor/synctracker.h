// Bookkeeping behind the editor's sync state: what was pushed, what the device answered and
// read back. No widgets; the editor asks it for the state after every change.
#pragma once

#include "model/params.h"
#include "session/sessiontypes.h"

#include <QString>

#include <optional>

namespace hatpic {

enum class SyncState {
    NotConnected,     //!< no device that takes parameters
    NotRead,          //!< connected, device values not known yet
    Edited,           //!< editor differs from the device, not pushed
    Pushing,          //!< SET_PARAMS sent, no answer yet
    AwaitingReadback, //!< ACK OK, the read-back has not arrived yet
    InSync,           //!< the device's read-back matches the editor (as float32)
    ReadbackDiffers,  //!< ACK OK but the read-back differs from what was pushed
    Rejected,         //!< the device refused the set; values stay for the user to fix
    Timeout,          //!< no answer after the retries
    Failed,           //!< any other failure (not connected, unsupported, …)
};

class SyncTracker
{
public:
    void setCanPush(bool canPush, const QString &reason);
    bool canPush() const { return m_canPush; }

    //! The device's read-back (nullopt: disconnected, forget everything about the device).
    void setDevice(const std::optional<DeviceParams> &device);
    const std::optional<DeviceParams> &device() const { return m_device; }

    //! The edited values changed: the last failure was about other values.
    void edited();
    void pushStarted(const DeviceParams &pushed);
    //! Returns false when no push was in flight (a late answer), which changes nothing.
    bool pushFinished(const CommandResult &result);
    bool isPushing() const { return m_pushing; }
    //! ParamBlock index the device named in its last rejection, or -1.
    int rejectedField() const { return m_rejectedField; }

    SyncState state(const DeviceParams &edited) const;
    QString text(const DeviceParams &edited) const;

private:
    bool m_canPush = false;
    QString m_cannotPushReason;
    std::optional<DeviceParams> m_device;
    DeviceParams m_lastPushed;
    bool m_pushing = false;
    bool m_awaitingReadback = false;
    bool m_readbackDuringPush = false;
    bool m_pushedOk = false;
    std::optional<SyncState> m_failure;
    QString m_failureText;
    int m_rejectedField = -1;
};

} // namespace hatpic
