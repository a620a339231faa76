#include "editor/parametereditor.h"

#include "editor/derivedfiguresview.h"
#include "editor/editoractions.h"
#include "editor/effectssection.h"
#include "editor/livepush.h"
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

ParameterEditor::ParameterEditor(TuningModel *model, QUndoStack *undo, QWidget *parent)
    : QWidget(parent), m_model(model), m_controlRate(servo::kControlRateHz), m_undo(undo)
{
    m_live = new LivePush([this] { return m_model->mayPush(); }, this);
    connect(m_live, &LivePush::pushDue, this, [this] { m_model->push(); });

    m_actions = new EditorActions(this, m_undo);
    connect(m_actions->push, &QAction::triggered, this, [this] { m_model->push(); });
    connect(m_actions->read, &QAction::triggered, this, &ParameterEditor::readRequested);
    connect(m_actions->revert, &QAction::triggered, this, &ParameterEditor::revert);

    buildUi();
    m_actions->addGoTo(m_form, [this](ParameterField *field) { goTo(field); });
    connect(m_model, &TuningModel::editedChanged, this, [this](TuningChange change) {
        m_form->showTuning(tuning());
        refresh();
        if (change.device || change.effects || change.passivity)
            m_live->edited();
    });
    connect(m_model, &TuningModel::deviceChanged, this, &ParameterEditor::refresh);
    // Whoever pushed (Push, a live push, A/B, the blind test): the interval counts from now.
    connect(m_model, &TuningModel::pushRequested, this, [this] {
        m_live->pushStarted();
        refresh();
    });
    connect(m_model, &TuningModel::pushEnded, this, [this] {
        refresh(); // shows or clears the field the device named
        m_live->retry();
    });
    connect(m_model, &TuningModel::syncChanged, m_syncBar, &SyncBar::setState);
    m_form->showTuning(tuning());
    m_syncBar->setState(syncState(), syncText());
    refresh();
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
        Tuning t = tuning();
        t.host.mode = mode;
        recordEdit(t, tr("Change mode"), u"mode"_s);
        ++m_gesture;
    });
    connect(m_form, &ParameterForm::refDeadzoneEdited, this, [this](bool on) {
        Tuning t = tuning();
        t.host.ref_deadzone = on;
        recordEdit(t, tr("Change dead-zone hold"), u"ref_deadzone"_s);
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
    connect(m_syncBar, &SyncBar::knobSelected, this, &ParameterEditor::knobSelected);
    layout->addWidget(m_syncBar);
    layout->addWidget(derivedBox);
    layout->addWidget(m_scroll, 1);
}

void ParameterEditor::setKnobs(int count)
{
    m_syncBar->setKnobs(count);
}

int ParameterEditor::knob() const
{
    return m_syncBar->knob();
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
    if (const std::optional<Tuning> reverted = m_model->revertedToDevice())
        setTuning(*reverted, tr("Revert to device values"));
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
    m_model->edit(*m_undo, tuning, text, field, m_gesture);
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
    setTuning({device, host, effects(), passivity()}, undoText);
}

void ParameterEditor::setEffectsAvailable(bool available, const QString &reason, double controlRate)
{
    m_controlRate = controlRate > 0 ? controlRate : servo::kControlRateHz;
    m_form->effectsSection()->setAvailable(available, reason);
    m_model->setEffectsTracked(available);
    refresh();
}

void ParameterEditor::setPassivityAvailable(bool available, const QString &reason)
{
    m_form->setPassivityAvailable(available, reason);
    m_model->setPassivityTracked(available);
    refresh();
}

void ParameterEditor::setCanPush(bool deviceAcceptsParams, const QString &reason)
{
    m_model->setCanPush(deviceAcceptsParams, reason);
    if (!deviceAcceptsParams)
        m_live->cancel();
    refresh();
}

void ParameterEditor::setTauLimit(double tauLimit)
{
    if (tauLimit == hostParams().tau_limit)
        return;
    HostParams h = hostParams();
    h.tau_limit = tauLimit;
    setParams(params(), h,
              tr("Use the device's torque limit (%1 N·m)").arg(QString::number(tauLimit, 'g', 6)));
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

void ParameterEditor::refresh()
{
    revalidate();
    m_form->showDevice(deviceTuning(), tuning(), m_model->effectsOnWire());
    const Tuning &t = tuning();
    m_derived->setFigures(deriveFigures(t.device, t.host), m_valid);
    m_form->effectsSection()->setFigures(t.effects, t.device, t.host.tau_limit, m_controlRate,
                                         m_valid);
    m_actions->update(m_valid, m_problems, m_model->canPush(), m_model->isPushing(),
                      m_model->differsFromDevice());
    m_syncBar->setProblems(m_problems);
}

void ParameterEditor::revalidate()
{
    QHash<QString, QStringList> perField;
    QStringList all;
    QStringList fields;
    for (const Violation &v : m_model->violations()) {
        const QString text = QString::fromStdString(v.message());
        perField[QString::fromStdString(v.field)] << text;
        all << text;
        fields << QString::fromStdString(v.field);
    }
    const QString rejected = m_model->rejectedField();
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

} // namespace hatpic
