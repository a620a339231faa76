// The round trip of the device's tuning between the editor and the device, in one place: edit →
// push (the parameters, and the effects when the device renders them) → ACK → read-back → in
// sync, one command and one result. It sends what the editor asks for (and its vibration tests),
// hands the device's answers and read-backs back to the editor (which shows the sync state),
// keeps the editor's host parameters in the session, and words the outcome of every parameter
// command (push, read, ZERO, save in the device) for the status bar and the event markers.
// On a device with several knobs it carries them for the knob the editor's selector names:
// knob 1's tuning is the session's (it follows every change), another knob's is read when it
// is chosen and follows its own commands' read-backs.
#pragma once

#include "model/params.h"
#include "session/sessiontypes.h"

#include <QObject>

namespace hatpic {

class DeviceClient;
class ParameterEditor;
class TuningModel;

class DeviceParameterLink : public QObject
{
    Q_OBJECT
public:
    //! None is owned; all must outlive the link (the window owns them all). It carries the
    //! model's pushes (TuningModel::pushRequested) and keeps the model's device tuning; the
    //! editor's reads, vibration tests and knob choice, and tells the editor what the device
    //! takes.
    DeviceParameterLink(DeviceClient *client, TuningModel *model, ParameterEditor *editor,
                        QObject *parent = nullptr);

    //! Before a connection: the editor's host parameters go to the session, and its tau_limit
    //! scales the feedback of a legacy device (which does not report its limit).
    void prepare(ConnectOptions &options);

    void readFromDevice(); //!< GET_PARAMS, and GET_EFFECTS when the device renders effects
    void zero();           //!< ZERO: θ0 := the current angle, then a read-back
    void saveInDevice();   //!< SAVE_PARAMS: the device restores them at power-up

    //! The knob tuned: 0 for knob 1.
    Knob knob() const { return m_knob; }

    //! The outcome of the last parameter command ("Pushed: K_max 0.4 → 0.6", "Read: done.").
    QString lastMessage() const { return m_lastMessage; }

Q_SIGNALS:
    //! A parameter command finished; `text` is lastMessage().
    void commandFinished(const QString &text);
    //! The device's parameters were changed by a push or a ZERO ("K_max 0.4 → 0.6"): worth a
    //! marker on the time axis.
    void deviceChanged(const QString &what);

private:
    void onStateChanged(SessionState state);
    void onDeviceInfo(const DeviceInfo &info);
    void selectKnob(int knob);
    //! The session's tuning (knob 1's) changed: the model's while knob 1 is tuned.
    void onSessionTuning(const DeviceTuning &tuning);
    void refreshEffectsAvailability();
    void onPushRequested(const DeviceTuning &tuning);
    //! `before`: the device's tuning when the push was sent.
    void finishPush(const DeviceTuning &before, const Outcome &outcome);
    //! Sends `request` (not a push); its outcome goes to finishCommand().
    void send(const Request &request);
    void finishCommand(const Outcome &outcome);

    DeviceClient *m_client;
    TuningModel *m_model;
    ParameterEditor *m_editor;
    QString m_lastMessage;
    Knob m_knob = 0;
    quint8 m_knobs = 1; //!< the connected device's, for the selector
};

} // namespace hatpic
