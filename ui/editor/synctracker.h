// Bookkeeping behind the editor's sync state: what was pushed, what the device answered and
// read back. No widgets; the editor asks it for the state after every change. The device's
// effect block takes part only while the device renders effects (setEffectsTracked).
#pragma once

#include "model/effects.h"
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
    //! The device's read-back (nullopt: disconnected, forget everything about the device).
    void setDevice(const std::optional<DeviceParams> &device);
    const std::optional<DeviceParams> &device() const { return m_device; }

    //! Whether the device renders effects: only then its effect block counts for the state.
    void setEffectsTracked(bool tracked);
    bool effectsTracked() const { return m_effectsTracked; }
    //! The device's effect block as read back (nullopt: not known yet).
    void setDeviceEffects(const std::optional<EffectParams> &effects);
    const std::optional<EffectParams> &deviceEffects() const { return m_deviceEffects; }

    //! The edited values changed: the last failure was about other values.
    void edited();
    //! A push of `pushed`, and of `effects` when they are sent with it (SET_EFFECTS).
    void pushStarted(const DeviceParams &pushed, const std::optional<EffectParams> &effects);
    //! The push's outcome (its first failure, when a part failed). Returns false when no push
    //! was in flight (a late answer), which changes nothing.
    bool pushFinished(const CommandResult &result);
    bool isPushing() const { return m_pushing; }
    //! Model name of the field the device named in its last rejection ("K_max",
    //! "wall_stiffness"), or empty.
    QString rejectedField() const { return m_rejectedField; }

    //! `editedEffects` as they travel (roundedForWire): what the device's read-back must equal.
    SyncState state(const DeviceParams &edited, const EffectParams &editedEffects) const;
    QString text(const DeviceParams &edited, const EffectParams &editedEffects) const;

private:
    bool inSync(const DeviceParams &edited, const EffectParams &editedEffects) const;

    bool m_canPush = false;
    QString m_cannotPushReason;
    std::optional<DeviceParams> m_device;
    bool m_effectsTracked = false;
    std::optional<EffectParams> m_deviceEffects;
    DeviceParams m_lastPushed;
    std::optional<EffectParams> m_lastPushedEffects;
    bool m_pushing = false;
    bool m_awaitingReadback = false;        //!< the parameters' read-back of the last push
    bool m_awaitingEffectsReadback = false; //!< the effects' read-back of the last push
    bool m_readbackDuringPush = false;
    bool m_effectsReadbackDuringPush = false;
    bool m_pushedOk = false;
    std::optional<SyncState> m_failure;
    QString m_failureText;
    QString m_rejectedField;
};

} // namespace hatpic
