// The window's one tuning: what the user is editing, what the connected device holds (as last
// read or read back), what it takes (pushes at all, the effect block, the passivity block), the
// push in flight and how the last one ended. The sync state, the editor's "device differs"
// markers, the stiffness view's edited curves, the stability map and the reference model all
// read it and follow its signals; none keeps a copy. No widgets: the window owns it (and the
// undo stack its edits go on) and hands it to whoever reads or changes it: the editor changes it
// through edit() (an undo step), profiles and A/B through edit() and setEdited(), anyone pushes
// through push() and gets the outcome back, and DeviceParameterLink carries the push to the
// device (pushRequested → pushFinished) and keeps setDevice() true.
//
// Comparisons with the device are made "as the device holds it": the edited tuning rounded
// once, here (editedOnWire()), the way the wire carries it.
#pragma once

#include "model/devicetuning.h"
#include "session/request.h"
#include "tuning/tuning.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QUndoStack;

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

//! Which parts of the edited tuning an edit changed.
struct TuningChange
{
    bool device = false;
    bool host = false;
    bool effects = false;
    bool passivity = false;
    bool any() const { return device || host || effects || passivity; }
};

class TuningModel : public QObject
{
    Q_OBJECT
public:
    explicit TuningModel(QObject *parent = nullptr);

    // ---- what is edited ----
    const Tuning &edited() const { return m_edited; }
    //! Replaces the edited tuning; an edit forgets the last push's failure (it was about other
    //! values).
    void setEdited(const Tuning &tuning);
    //! setEdited() as one step on `undo` named `text` ("Change K_max to 0.6"), when `tuning`
    //! differs. Edits of the same `field` ("K_max") within one `gesture` (a typing or a drag, the
    //! editor's counter) merge into one step; an empty field (a whole tuning) never merges.
    void edit(QUndoStack &undo, const Tuning &tuning, const QString &text,
              const QString &field = {}, quint64 gesture = 0);

    // ---- the device ----
    //! The device's tuning as read; without parameters (disconnected) everything about the
    //! device and the last push is forgotten.
    void setDevice(const DeviceTuning &device);
    const DeviceTuning &device() const { return m_device; }
    //! Whether a device that takes parameters is connected; `reason` says why not.
    void setCanPush(bool canPush, const QString &reason = {});
    bool canPush() const { return m_canPush; }
    //! Whether the device renders effects: only then its effect block is pushed and compared.
    void setEffectsTracked(bool tracked);
    bool effectsTracked() const { return m_effectsTracked; }
    //! Whether the device has the passivity controller: only then its block counts.
    void setPassivityTracked(bool tracked);
    bool passivityTracked() const { return m_passivityTracked; }

    // ---- pushing ----
    //! Every rule the edited tuning breaks (model.md § 1, effects.md, passivity.md), parameters
    //! first: none, and it may be pushed.
    std::vector<Violation> violations() const;
    //! Whether a push may start now: the edited tuning is valid, a device takes it, and no push
    //! is in flight.
    bool mayPush() const;
    //! Pushes the edited tuning when mayPush() (false, nothing sent, when not): pushRequested
    //! carries what to send to the device's link, which hands the answer to pushFinished();
    //! `done` then gets that outcome, with the model already updated by it (syncState() says
    //! whether the device is in sync). A push dropped by a disconnect still gets its outcome.
    bool push(std::function<void(const Outcome &)> done = {});
    //! The push's outcome, which carries the device's read-back. Returns false when no push
    //! was in flight (a late answer), which changes nothing.
    bool pushFinished(const Outcome &outcome);
    bool isPushing() const { return m_pushing.has_value(); }
    //! Model name of the field the device named in its last rejection ("K_max",
    //! "wall_stiffness"), or empty.
    QString rejectedField() const { return m_rejectedField; }

    // ---- derived ----
    //! The edited effects as SET_EFFECTS carries them (what the device's read-back must equal).
    EffectParams effectsOnWire() const;
    //! The edited tuning as it travels, with the blocks the device has: what the device's
    //! read-back must equal.
    DeviceTuning editedOnWire() const;
    //! The device has parameters and some part it has differs from the edited one.
    bool differsFromDevice() const;
    //! The edited tuning with the device's parts in place of its own (tidied; a block that is
    //! the same on the wire stays as edited), or nullopt when the device's are not known.
    std::optional<Tuning> revertedToDevice() const;
    SyncState syncState() const { return m_syncState; }
    QString syncText() const { return m_syncText; }

Q_SIGNALS:
    void editedChanged(hatpic::TuningChange change);
    void deviceChanged(const hatpic::DeviceTuning &device);
    //! A push started (push()): the parameters, and each block the device has whose read-back
    //! is not the edited one yet. The device's link sends it and answers with pushFinished().
    void pushRequested(const hatpic::DeviceTuning &send);
    //! The sync state or its wording changed.
    void syncChanged(hatpic::SyncState state, const QString &text);
    //! The push in flight ended (pushFinished took its outcome): the editor may push again.
    void pushEnded();

private:
    //! Starts a push of the edited tuning and returns what to send.
    DeviceTuning startPush();
    //! pushFinished() without telling the caller.
    bool take(const Outcome &outcome);
    template<typename Block>
    void setTracked(bool &flag, std::optional<Block> &deviceBlock, bool tracked);
    //! `tuning` without the blocks the device does not have.
    DeviceTuning counted(const DeviceTuning &tuning) const;
    SyncState computeState() const;
    QString computeText(SyncState state) const;
    //! Recomputes the sync state and signals it when it changed.
    void refreshSync();

    Tuning m_edited;
    DeviceTuning m_device;
    bool m_canPush = false;
    QString m_cannotPushReason;
    bool m_effectsTracked = false;
    bool m_passivityTracked = false;
    std::optional<DeviceTuning> m_pushing;           //!< the edited tuning of the push in flight
    std::optional<DeviceTuning> m_pushed;            //!< …of the last push the device took
    std::function<void(const Outcome &)> m_pushDone; //!< push()'s caller, until the outcome
    //! The last push's failure (or its unanswered read-back), until an edit or a read-back
    std::optional<SyncState> m_failure;
    QString m_failureText;
    QString m_rejectedField;
    SyncState m_syncState = SyncState::NotConnected;
    QString m_syncText;
};

} // namespace hatpic
