// Bookkeeping behind the editor's sync state: the device's tuning as read, the push in flight
// and how the last one ended; the state is a function of these and the edited tuning. No
// widgets; the editor asks it for the state after every change. The device's effect block takes
// part only while the device renders effects (setEffectsTracked), its passivity block only while
// it has the controller (setPassivityTracked).
#pragma once

#include "model/devicetuning.h"
#include "session/sessiontypes.h"

#include <QString>

#include <optional>

namespace hatpic {

enum class SyncState {
    NotConnected,     //!< no device that takes parameters
    NotRead,          //!< connected, device values not known yet
    Edited,           //!< editor differs from the device, not pushed
    Pushing,          //!< the push and its read-back are under way
    AwaitingReadback, //!< ACK OK, but the read-back went unanswered: read again
    InSync,           //!< the device's read-backs match the editor (as float32)
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
    //! The device's tuning as read; without parameters (disconnected) everything about the
    //! device and the last push is forgotten.
    void setDevice(const DeviceTuning &device);
    const DeviceTuning &device() const { return m_device; }

    //! Whether the device renders effects: only then its effect block counts for the state.
    void setEffectsTracked(bool tracked);
    bool effectsTracked() const { return m_effectsTracked; }
    //! Whether the device has the passivity controller: only then its block counts.
    void setPassivityTracked(bool tracked);
    bool passivityTracked() const { return m_passivityTracked; }

    //! The edited values changed: the last failure was about other values.
    void edited();
    //! A push of the edited tuning `edited` (as it travels; its effects while tracked).
    void pushStarted(const DeviceTuning &edited);
    //! The push's outcome, which carries the device's read-back. Returns false when no push
    //! was in flight (a late answer), which changes nothing.
    bool pushFinished(const Outcome &outcome);
    bool isPushing() const { return m_pushing.has_value(); }
    //! Model name of the field the device named in its last rejection ("K_max",
    //! "wall_stiffness"), or empty.
    QString rejectedField() const { return m_rejectedField; }

    //! `edited` as it travels (roundedForWire), its effects and passivity block while tracked:
    //! what the device's read-back must equal.
    SyncState state(const DeviceTuning &edited) const;
    QString text(const DeviceTuning &edited) const;

private:
    bool m_canPush = false;
    QString m_cannotPushReason;
    DeviceTuning m_device;
    bool m_effectsTracked = false;
    bool m_passivityTracked = false;
    //! `tuning` without the parts that do not count (untracked blocks).
    DeviceTuning counted(const DeviceTuning &tuning) const;
    std::optional<DeviceTuning> m_pushing; //!< the edited tuning of the push in flight
    std::optional<DeviceTuning> m_pushed;  //!< …of the last push the device took
    //! The last push's failure (or its unanswered read-back), until an edit or a read-back
    std::optional<SyncState> m_failure;
    QString m_failureText;
    QString m_rejectedField;
};

} // namespace hatpic
