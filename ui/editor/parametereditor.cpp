#include "editor/parametereditor.h"

#include "editor/derivedfiguresview.h"
#include "editor/editoractions.h"
#include "editor/effectssection.h"
#include "editor/livepush.h"
#include "editor/parametereditcommand.h"
#include "editor/parameterfield.h"
#include "editor/parameterform.h"
#include "editor/scientificspinbox.h"
#include "editor/syncbar.h"
#include "model/derived.h"
#include "model/servo.h"

#include <QAction>
#include <QGroupBox>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

namespace hatpic {

using namespace Qt::StringLiterals;

ParameterEditor::ParameterEditor(QWidget *parent)
    : QWidget(parent), m_controlRate(servo::kControlRateHz)
{
    m_undo = new QUndoStack(this);
    m_live =
        new LivePush([this] { return m_valid && m_sync.canPush() && !m_sync.isPushing(); }, this);
    connect(m_live, &LivePush::pushDue, this, &ParameterEditor::startPush);

    m_actions = new EditorActions(this, m_undo);
    connect(m_actions->push, &QAction::triggered, this, [this] {
        if (m_valid && m_sync.canPush() && !m_sync.isPushing())
            startPush();
    });
    connect(m_actions->read, &QAction::triggered, this, &ParameterEditor::readRequested);
    connect(m_actions->revert, &QAction::triggered, this, &ParameterEditor::revert);

    buildUi();
    m_actions->addGoTo(m_form, [this](ParameterField *field) { goTo(field); });
    applyParams(DeviceParams{}, HostParams{});
    m_undo->clear();
    refreshSync();
    refreshActions();
}

ParameterEditor::~ParameterEditor() = default;

// The widgets: the fields, the sync bar and the derived figures.

QList<QAction *> ParameterEditor::keyboardActions() const
{
    return m_actions->keyboardActions();
}

ParameterField *ParameterEditor::field(const QString &key) const
{
    return m_form->field(key);
}

EffectsSection *ParameterEditor::effectsSection() const
{
    return m_form->effectsSection();
}

void ParameterEditor::buildUi()
{
    m_form = new ParameterForm;
    m_form->setObjectName(u"parameterForm"_s);
    connect(m_form, &ParameterForm::fieldEdited, this, &ParameterEditor::onFieldEdited);
    connect(m_form, &ParameterForm::editFinished, this, [this] { ++m_gesture; });
    connect(m_form, &ParameterForm::modeEdited, this, [this](ReferenceMode mode) {
        HostParams h = m_host;
        h.mode = mode;
        recordEdit({m_params, h, m_effects, m_passivity}, tr("Change mode"), u"mode"_s);
        ++m_gesture;
    });
    connect(m_form, &ParameterForm::refDeadzoneEdited, this, [this](bool on) {
        HostParams h = m_host;
        h.ref_deadzone = on;
        recordEdit({m_params, h, m_effects, m_passivity}, tr("Change dead-zone hold"),
                   u"ref_deadzone"_s);
        ++m_gesture;
    });
    connect(m_form->effectsSection(), &EffectsSection::vibrateRequested, this,
            &ParameterEditor::vibrateRequested);

    // The derived figures and their warnings sit right under Push, outside the scrolling
    // fields, so they are in sight at every window size.
    auto *derivedBox = new QGroupBox(tr("Derived figures (K = K_max)"), this);
    derivedBox->setObjectName(u"derivedFiguresBox"_s);
    auto *derivedLayout = new QVBoxLayout(derivedBox);
    derivedLayout->setContentsMargins(6, 2, 6, 4);
    m_derived = new DerivedFiguresView(derivedBox);
    derivedLayout->addWidget(m_derived);

    m_scroll = new QScrollArea(this);
    m_scroll->setObjectName(u"parameterScroll"_s);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidget(m_form);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(8);
    m_syncBar = new SyncBar(m_undo, m_actions->read, m_actions->revert, m_actions->push, this);
    connect(m_syncBar, &SyncBar::livePushToggled, this, &ParameterEditor::setLivePush);
    connect(m_syncBar, &SyncBar::angleInDegreesToggled, this, &ParameterEditor::setAngleInDegrees);
    connect(m_syncBar, &SyncBar::showProblemRequested, this, &ParameterEditor::showFirstProblem);
    layout->addWidget(m_syncBar);
    layout->addWidget(derivedBox);
    layout->addWidget(m_scroll, 1);
}

void ParameterEditor::showFirstProblem()
{
    ParameterField *field = m_problemFields.isEmpty() ? nullptr : m_form->field(m_problemFields[0]);
    if (field)
        goTo(field);
}

void ParameterEditor::goTo(ParameterField *field)
{
    // In view first, even when it has the focus already (scrolled away since): never typed
    // into blind (issue 27).
    m_scroll->ensureWidgetVisible(field->spinBox(), 12, 12);
    field->spinBox()->setFocus(Qt::ShortcutFocusReason);
    field->spinBox()->selectAll();
}

void ParameterEditor::revert()
{
    const DeviceTuning &device = m_sync.device();
    if (!device.params)
        return;
    Tuning t = tuning();
    t.device = tidyDeviceParams(*device.params);
    // The device's float32 effects, unless they are the edited ones as sent: the defaults ±π
    // travel as the float just inside π and need no revert.
    if (const auto &fx = device.effects; fx && !sameOnWire(effectsOnWire(), *fx))
        t.effects = tidyEffectParams(*fx);
    if (const auto &pc = device.passivity; pc && !sameOnWire(m_passivity, *pc))
        t.passivity = tidyPassivityParams(*pc);
    setTuning(t, tr("Revert to device values"));
}

EffectParams ParameterEditor::effectsOnWire() const
{
    return roundedForWire(m_effects, m_host.tau_limit);
}

DeviceTuning ParameterEditor::editedOnWire() const
{
    return {m_params, m_sync.effectsTracked() ? std::optional(effectsOnWire()) : std::nullopt,
            m_sync.passivityTracked() ? std::optional(roundedForWire(m_passivity)) : std::nullopt};
}

void ParameterEditor::onFieldEdited(const QString &key, double value)
{
    Tuning t = tuning();
    const std::string name = key.toStdString();
    if (const int index = deviceFieldIndex(name); index >= 0)
        t.device.setField(index, value);
    else if (const int fx = effectFieldIndex(name); fx >= 0)
        t.effects.setField(fx, value);
    else if (const int pc = passivityFieldIndex(name); pc >= 0)
        t.passivity.setField(pc, value);
    else if (key == u"v_max")
        t.host.v_max = value;
    else if (key == u"tau_limit")
        t.host.tau_limit = value;
    recordEdit(t, tr("Change %1 to %2").arg(key, QString::number(value, 'g', 6)), key);
}

void ParameterEditor::recordEdit(const Tuning &tuning, const QString &text, const QString &field)
{
    if (tuning == this->tuning())
        return;
    m_undo->push(new ParameterEditCommand(this, this->tuning(), tuning, text, field, m_gesture));
}

void ParameterEditor::setTuning(const Tuning &tuning, const QString &undoText)
{
    ++m_gesture;
    recordEdit(tuning, undoText, QString());
    ++m_gesture;
}

void ParameterEditor::setParams(const DeviceParams &device, const HostParams &host,
                                const QString &undoText)
{
    setTuning({device, host, m_effects, m_passivity}, undoText);
}

void ParameterEditor::applyParams(const DeviceParams &device, const HostParams &host)
{
    applyTuning({device, host, m_effects, m_passivity});
}

void ParameterEditor::applyTuning(const Tuning &tuning)
{
    const DeviceParams &device = tuning.device;
    const HostParams &host = tuning.host;
    const bool deviceChanged = device != m_params;
    const bool hostChanged = host != m_host;
    // The device's blocks change together: each is pushed, undone and compared alike.
    const bool effectsChanged = tuning.effects != m_effects || tuning.passivity != m_passivity;
    m_params = device;
    m_host = host;
    m_effects = tuning.effects;
    m_passivity = tuning.passivity;

    m_form->showTuning(tuning);

    if (deviceChanged || hostChanged || effectsChanged)
        m_sync.edited();
    revalidate();
    refreshDiff();
    refreshDerived();
    refreshSync();
    refreshActions();
    if (hostChanged)
        Q_EMIT hostParamsChanged(m_host);
    if (deviceChanged || hostChanged || effectsChanged)
        Q_EMIT paramsEdited();
    if (deviceChanged || effectsChanged)
        m_live->edited();
}

void ParameterEditor::setDeviceTuning(const DeviceTuning &device)
{
    m_sync.setDevice(device);
    revalidate();
    refreshDiff();
    refreshSync();
    refreshActions();
}

void ParameterEditor::setEffectsAvailable(bool available, const QString &reason, double controlRate)
{
    m_sync.setEffectsTracked(available);
    m_controlRate = controlRate > 0 ? controlRate : servo::kControlRateHz;
    m_form->effectsSection()->setAvailable(available, reason);
    refreshDiff();
    refreshDerived();
    refreshSync();
    refreshActions();
}

void ParameterEditor::setPassivityAvailable(bool available, const QString &reason)
{
    m_sync.setPassivityTracked(available);
    m_form->setPassivityAvailable(available, reason);
    refreshDiff();
    refreshSync();
    refreshActions();
}

void ParameterEditor::setCanPush(bool deviceAcceptsParams, const QString &reason)
{
    m_sync.setCanPush(deviceAcceptsParams, reason);
    if (!deviceAcceptsParams)
        m_live->cancel();
    refreshSync();
    refreshActions();
}

void ParameterEditor::setTauLimit(double tauLimit)
{
    if (tauLimit == m_host.tau_limit)
        return;
    HostParams h = m_host;
    h.tau_limit = tauLimit;
    setParams(m_params, h,
              tr("Use the device's torque limit (%1 N·m)").arg(QString::number(tauLimit, 'g', 6)));
}

void ParameterEditor::pushFinished(const Outcome &outcome)
{
    if (!m_sync.pushFinished(outcome))
        return;    // a late answer after a disconnect
    revalidate();  // shows or clears the field the device named
    refreshDiff(); // the outcome carries the read-back
    refreshSync();
    refreshActions();
    m_live->retry();
}

void ParameterEditor::startPush()
{
    // The effects go along while the device renders them and its read-back is not them yet.
    std::optional<EffectParams> effects;
    const EffectParams onWire = effectsOnWire();
    const std::optional<EffectParams> &fx = m_sync.device().effects;
    if (m_sync.effectsTracked() && (!fx || !sameOnWire(onWire, *fx)))
        effects = m_effects;
    // The passivity block likewise, while the device has the controller.
    std::optional<PassivityParams> passivity;
    const std::optional<PassivityParams> &pc = m_sync.device().passivity;
    if (m_sync.passivityTracked() && (!pc || !sameOnWire(m_passivity, *pc)))
        passivity = m_passivity;
    m_sync.pushStarted(editedOnWire());
    m_live->pushStarted();
    revalidate();
    refreshSync();
    refreshActions();
    Q_EMIT pushRequested({m_params, effects, passivity});
}

void ParameterEditor::setLivePush(bool enabled)
{
    m_live->setEnabled(enabled);
    m_syncBar->setLivePush(enabled);
}

void ParameterEditor::setLivePushInterval(int milliseconds)
{
    m_live->setInterval(milliseconds);
}

void ParameterEditor::setAngleInDegrees(bool degrees)
{
    if (degrees == m_degrees)
        return;
    m_degrees = degrees;
    m_syncBar->setAngleInDegrees(degrees);
    m_form->setAngleInDegrees(degrees);
    m_derived->setAngleInDegrees(degrees);
    Q_EMIT angleInDegreesChanged(degrees);
}

void ParameterEditor::revalidate()
{
    QHash<QString, QStringList> perField;
    QStringList all;
    QStringList fields;
    std::vector<Violation> violations = validate(m_params);
    for (Violation &v : validate(m_host))
        violations.push_back(std::move(v));
    for (Violation &v : validate(m_effects, m_host.tau_limit))
        violations.push_back(std::move(v));
    for (Violation &v : validate(m_passivity))
        violations.push_back(std::move(v));
    for (const Violation &v : violations) {
        const QString text = QString::fromStdString(v.message());
        perField[QString::fromStdString(v.field)] << text;
        all << text;
        fields << QString::fromStdString(v.field);
    }
    const QString rejected = m_sync.rejectedField();
    if (!rejected.isEmpty() && !perField.contains(rejected))
        perField[rejected] << tr("%1: the device refused this value").arg(rejected);
    m_form->setProblems(perField);

    m_problems = all;
    m_problemFields = fields;
    const bool valid = all.isEmpty();
    if (valid != m_valid) {
        m_valid = valid;
        Q_EMIT validityChanged(valid);
    }
}

void ParameterEditor::refreshDiff()
{
    m_form->showDevice(m_sync.device(), tuning(), effectsOnWire());
}

void ParameterEditor::refreshDerived()
{
    m_derived->setFigures(deriveFigures(m_params, m_host), m_valid);
    m_form->effectsSection()->setFigures(m_effects, m_params, m_host.tau_limit, m_controlRate,
                                         m_valid);
}

void ParameterEditor::refreshSync()
{
    const DeviceTuning edited = editedOnWire();
    const SyncState state = m_sync.state(edited);
    const QString text = m_sync.text(edited);
    m_syncBar->setState(state, text);

    if (state != m_syncState || text != m_syncText) {
        m_syncState = state;
        m_syncText = text;
        Q_EMIT syncStateChanged(state, text);
    }
}

void ParameterEditor::refreshActions()
{
    const auto &device = m_sync.device().params;
    const auto &fx = m_sync.device().effects;
    const auto &pc = m_sync.device().passivity;
    const bool differs =
        device && (!sameOnWire(m_params, *device) || (fx && !sameOnWire(effectsOnWire(), *fx)) ||
                   (pc && !sameOnWire(m_passivity, *pc)));
    m_actions->update(m_valid, m_problems, m_sync.canPush(), m_sync.isPushing(), differs);
    m_syncBar->setProblems(m_problems);
}

} // namespace hatpic
