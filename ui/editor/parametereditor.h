// The parameter editor: every device and host parameter and the device's effect block with
// its meaning, unit and valid range, whole-set validation at the fields, undo/redo, diff
// markers against the device, push/read with a visible sync state, optional rate-limited live
// push, the derived figures, and the effects' warnings and vibration test.
// "Push" means sending to the device, only; edits go onto the undo stack (recordEdit).
// It edits the window's TuningModel on the window's undo stack (both given, neither owned) and
// pushes through the model (TuningModel::push), as profiles and the blind test do. It does not
// talk to the device itself: DeviceParameterLink carries the model's pushes and the editor's
// reads to the DeviceClient and brings back the answers and read-backs.
#pragma once

#include "editor/editoractions.h"
#include "editor/livepush.h"
#include "session/sessiontypes.h"
#include "tuning/tuningmodel.h"

#include <QWidget>

#include <optional>

class QAction;
class QScrollArea;
class QUndoStack;

namespace hatpic {

class DerivedFiguresView;
class EffectsSection;
class ParameterField;
class ParameterForm;
class SyncBar;

class ParameterEditor : public QWidget
{
    Q_OBJECT
public:
    using SyncState = hatpic::SyncState;

    static constexpr int kDefaultLivePushIntervalMs = LivePush::kDefaultIntervalMs;

    //! `model` and `undo` are the window's: they must outlive the editor.
    ParameterEditor(TuningModel *model, QUndoStack *undo, QWidget *parent = nullptr);
    ~ParameterEditor() override;

    //! The tuning edited here, the device's and the sync state (the window's).
    TuningModel *model() const { return m_model; }
    const Tuning &tuning() const { return m_model->edited(); }
    DeviceParams params() const { return tuning().device; }
    HostParams hostParams() const { return tuning().host; }
    EffectParams effects() const { return tuning().effects; }
    PassivityParams passivity() const { return tuning().passivity; }

    //! Replaces the whole tuning as one undo step named `undoText`.
    void setTuning(const Tuning &tuning, const QString &undoText);
    //! setTuning with the effects and the passivity controller as they are.
    void setParams(const DeviceParams &device, const HostParams &host, const QString &undoText);

    //! The device's tuning as read: drives the diff markers and the sync state. Without
    //! parameters (disconnected): no diff markers, no sync state.
    void setDeviceTuning(const DeviceTuning &device) { m_model->setDevice(device); }
    const DeviceTuning &deviceTuning() const { return m_model->device(); }
    //! Whether the connected device renders effects (the effects are then pushed and kept in
    //! sync with the parameters); `reason` says why not. `controlRate` [Hz] is the device's
    //! control rate, for the passivity figures and the vibration test's Nyquist rule.
    void setEffectsAvailable(bool available, const QString &reason, double controlRate);
    //! Whether the connected device has the passivity controller (its block is then pushed and
    //! kept in sync with the parameters); `reason` says why not.
    void setPassivityAvailable(bool available, const QString &reason);

    //! False while disconnected or for a legacy device; `reason` replaces "not connected".
    void setCanPush(bool deviceAcceptsParams, const QString &reason = {});
    bool canPush() const { return m_model->canPush(); }
    //! The connected device's knobs: two or more show the selector of the knob tuned (its
    //! tuning is then the device's that the model compares with). A new count selects knob 1.
    void setKnobs(int count);
    //! The knob tuned: 0 for knob 1.
    int knob() const;
    //! The connected device's actuator limit: sets tau_limit as an undoable edit when it differs.
    void setTauLimit(double tauLimit);

    bool isValid() const { return m_valid; }
    //! Every violated rule of the edited set ("K_min: must be ≤ K_max (0.4), got 0.9"),
    //! parameters first, then effects.
    QStringList problems() const { return m_problems; }

    QUndoStack *undoStack() const { return m_undo; } //!< the window's, given

    QAction *pushAction() const { return m_actions->push; }     //!< Ctrl+Return
    QAction *readAction() const { return m_actions->read; }     //!< "Read from device"
    QAction *revertAction() const { return m_actions->revert; } //!< "Revert to device values"
    QAction *undoAction() const { return m_actions->undo; }     //!< no shortcut of its own
    QAction *redoAction() const { return m_actions->redo; }     //!< no shortcut of its own

    SyncState syncState() const { return m_model->syncState(); }
    QString syncText() const { return m_model->syncText(); }

    //! Push on every edit while valid, at most one in flight and one per interval; the last
    //! value is always sent.
    void setLivePush(bool enabled);
    void setLivePushInterval(int milliseconds);

    //! Display only: θ0, N and Q_dz in degrees; params() stays in rad.
    void setAngleInDegrees(bool degrees);
    bool angleInDegrees() const { return m_degrees; }

    //! The row of a numeric field by model name ("K_max", "v_max", "wall_max", …), or nullptr.
    ParameterField *field(const QString &key) const;
    DerivedFiguresView *derivedFiguresView() const { return m_derived; }
    EffectsSection *effectsSection() const;
    //! Read, Revert and "Go to <field>" (Alt+1 … Alt+9), for the shortcut table.
    QList<QAction *> keyboardActions() const;

Q_SIGNALS:
    //! The vibration test's Vibrate or Stop (already valid).
    void vibrateRequested(const hatpic::Vibration &vibration);
    void readRequested();
    //! The user chose another knob to tune (0 for knob 1).
    void knobSelected(int knob);
    void validityChanged(bool valid);
    void angleInDegreesChanged(bool degrees);

private:
    void buildUi();
    void onFieldEdited(const QString &key, double value);
    //! The change as an undo step of the model (merged within one gesture).
    void recordEdit(const Tuning &tuning, const QString &text, const QString &field);
    void revert();
    //! The model changed: everything shown follows it.
    void refresh();
    void revalidate();
    //! Brings the field of the first broken rule into sight, with the cursor in it.
    void showFirstProblem();
    //! Scrolls `field` into view and puts the cursor in it, its text selected.
    void goTo(ParameterField *field);

    TuningModel *m_model;
    double m_controlRate; //!< [Hz]
    bool m_valid = true;
    QStringList m_problems;
    QStringList m_problemFields; //!< the field of each of m_problems

    LivePush *m_live = nullptr;
    bool m_degrees = false;
    quint64 m_gesture = 0; //!< edits merge into one undo step only within one gesture

    QUndoStack *m_undo;
    EditorActions *m_actions = nullptr;
    ParameterForm *m_form = nullptr;
    SyncBar *m_syncBar = nullptr;
    QScrollArea *m_scroll = nullptr; //!< scrolls m_form
    DerivedFiguresView *m_derived = nullptr;
};

} // namespace hatpic
