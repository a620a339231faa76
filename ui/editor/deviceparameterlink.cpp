#include "editor/deviceparameterlink.h"

#include "editor/parametereditor.h"
#include "model/overloaded.h"
#include "session/deviceclient.h"
#include "session/sessionwording.h"

namespace hatpic {

namespace {

//! "knob 2: " before what a command changed on knob 2 and on; nothing for knob 1.
QString knobPrefix(Knob knob)
{
    return knob ? DeviceParameterLink::tr("knob %1: ").arg(int(knob) + 1) : QString();
}

} // namespace

DeviceParameterLink::DeviceParameterLink(DeviceClient *client, TuningModel *model,
                                         ParameterEditor *editor, QObject *parent)
    : QObject(parent), m_client(client), m_model(model), m_editor(editor)
{
    connect(m_model, &TuningModel::pushRequested, this, &DeviceParameterLink::onPushRequested);
    connect(m_editor, &ParameterEditor::vibrateRequested, this, [this](const Vibration &v) {
        send(request::Vibrate{v, m_knob});
    });
    connect(m_editor, &ParameterEditor::knobSelected, this, &DeviceParameterLink::selectKnob);
    connect(m_editor, &ParameterEditor::readRequested, this, &DeviceParameterLink::readFromDevice);
    connect(m_model, &TuningModel::editedChanged, this, [this](TuningChange change) {
        if (change.host)
            m_client->setHostParams(m_model->edited().host);
    });
    connect(m_client, &DeviceClient::stateChanged, this,
            [this](SessionState state) { onStateChanged(state); });
    connect(m_client, &DeviceClient::deviceInfoChanged, this, &DeviceParameterLink::onDeviceInfo);
    connect(m_client, &DeviceClient::deviceTuningChanged, this,
            &DeviceParameterLink::onSessionTuning);
    onStateChanged(m_client->state());
}

void DeviceParameterLink::prepare(ConnectOptions &options)
{
    // The published firmware does not report its torque limit: the editor's tau_limit (the
    // profile's) scales the legacy feedback and stays what it is.
    const HostParams &host = m_model->edited().host;
    if (host.tau_limit > 0)
        options.legacy.tauLimit = host.tau_limit;
    m_client->setHostParams(host);
}

void DeviceParameterLink::send(const Request &request)
{
    m_client->request(request, {this, [this](const Outcome &outcome) { finishCommand(outcome); }});
}

void DeviceParameterLink::onPushRequested(const DeviceTuning &tuning)
{
    m_client->request(request::Push{tuning, m_knob},
                      {this, [this, before = m_model->device()](const Outcome &outcome) {
                           finishPush(before, outcome);
                       }});
}

void DeviceParameterLink::readFromDevice()
{
    send(request::Read{m_knob});
}

void DeviceParameterLink::zero()
{
    send(request::Zero{m_knob});
}

void DeviceParameterLink::selectKnob(int knob)
{
    if (knob == m_knob || knob < 0 || knob >= m_knobs)
        return;
    m_knob = Knob(knob);
    // The model compares with the chosen knob's tuning: knob 1's is the session's; another's
    // is unknown until read. The last push and its read-back were the other knob's.
    m_model->setDevice({});
    if (m_knob == 0)
        m_model->setDevice(m_client->deviceTuning());
    else
        readFromDevice();
}

void DeviceParameterLink::onSessionTuning(const DeviceTuning &tuning)
{
    if (m_knob == 0)
        m_model->setDevice(tuning);
}

void DeviceParameterLink::saveInDevice()
{
    send(request::Save{});
}

void DeviceParameterLink::onStateChanged(SessionState state)
{
    const bool connected = state == SessionState::Connected;
    m_editor->setCanPush(connected && m_client->deviceInfo().canSetParams(),
                         connected ? tr("the legacy protocol cannot carry parameters") : QString());
    if (state == SessionState::Disconnected) {
        m_model->setDevice({});
        m_knobs = 1;
        m_knob = 0;
        m_editor->setKnobs(1);
    }
    refreshEffectsAvailability();
}

void DeviceParameterLink::onDeviceInfo(const DeviceInfo &info)
{
    if (info.protocol == WireProtocol::V2) // a legacy device reports no limit
        m_editor->setTauLimit(shortestFloatDecimal(info.tauLimit));
    // Only a device that takes tuning has a tuning per knob (the IMU branch's has none).
    const quint8 knobs = info.canSetParams() ? info.axes : 1;
    if (knobs != m_knobs) {
        m_knobs = knobs;
        m_editor->setKnobs(knobs);
        selectKnob(0);
    }
    refreshEffectsAvailability();
}

void DeviceParameterLink::refreshEffectsAvailability()
{
    const DeviceInfo &info = m_client->deviceInfo();
    const bool connected = m_client->state() == SessionState::Connected;
    const bool available = connected && info.hasEffects();
    // Our device core streams at most at its control rate, so max_stream_hz is that rate.
    const double rate = available ? double(info.maxStreamHz) : 0.0;
    m_editor->setEffectsAvailable(
        available,
        connected && !available
            ? SessionWording::noEffectsReason(info.protocol == WireProtocol::Legacy)
            : QString(),
        rate);
    const bool controller = connected && info.hasPassivity();
    m_editor->setPassivityAvailable(
        controller, connected && !controller
                        ? SessionWording::noPassivityReason(info.protocol == WireProtocol::Legacy)
                        : QString());
}

void DeviceParameterLink::finishPush(const DeviceTuning &before, const Outcome &outcome)
{
    m_model->pushFinished(outcome);
    if (outcome.ok()) {
        // What changed is what the device held against what travelled (float32, bounds kept
        // by the session's one rounding), never the editor's doubles: the walls' ±π travel as
        // the float just inside π, which the device already held.
        const QString change = describeTuningChange(before, *outcome.pushed());
        if (change.isEmpty()) {
            m_lastMessage = tr("Pushed (no change).");
        } else {
            const QString what = knobPrefix(knobOf(outcome.request)) + change;
            m_lastMessage = tr("Pushed: %1").arg(what);
            Q_EMIT deviceChanged(what);
        }
    } else {
        m_lastMessage = tr("Push failed: %1").arg(SessionWording::commandFailure(outcome));
    }
    Q_EMIT commandFinished(m_lastMessage);
}

void DeviceParameterLink::finishCommand(const Outcome &outcome)
{
    const QString what =
        std::visit(Overloaded{
                       [](const request::Read &) { return tr("Read"); },
                       [](const request::Vibrate &v) {
                           return v.vibration.amplitude > 0 ? tr("Vibrate") : tr("Stop vibration");
                       },
                       [](const request::Zero &) { return tr("ZERO"); },
                       [](const request::Save &) { return tr("Save in device"); },
                       [](const auto &) { return QString(); }, // the link sends nothing else
                   },
                   outcome.request);
    const Knob knob = knobOf(outcome.request);
    const QString named = knob ? tr("%1 (knob %2)").arg(what).arg(int(knob) + 1) : what;
    m_lastMessage = outcome.ok()
                        ? tr("%1: done.").arg(named)
                        : tr("%1 failed: %2").arg(named, SessionWording::commandFailure(outcome));
    // Another knob's tuning follows its own reads (knob 1's follows the session's); one read
    // for a knob no longer chosen is not the model's.
    if (outcome.ok() && knob != 0 && knob == m_knob && outcome.received != DeviceTuning{})
        m_model->setDevice(m_model->device().updatedBy(outcome.received));
    if (outcome.ok() && std::holds_alternative<request::Zero>(outcome.request))
        Q_EMIT deviceChanged(knobPrefix(knob) + tr("ZERO: θ0 := current angle"));
    Q_EMIT commandFinished(m_lastMessage);
}

} // namespace hatpic
