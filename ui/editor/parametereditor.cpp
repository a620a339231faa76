#include "editor/parametereditor.h"

#include "editor/derivedfiguresview.h"
#include "editor/effectssection.h"
#include "editor/parametereditcommand.h"
#include "editor/parameterfield.h"
#include "editor/parameterspecs.h"
#include "editor/scientificspinbox.h"
#include "editor/syncbar.h"
#include "firmware/controller.h"
#include "model/derived.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

//! The device core's control rate, for a device that has not told its own [Hz].
double defaultControlRate()
{
    return fw::Controller<double>::Config{}.rateHz;
}

} // namespace

ParameterEditor::ParameterEditor(QWidget *parent)
    : QWidget(parent), m_controlRate(defaultControlRate())
{
    m_undo = new QUndoStack(this);
    m_liveTimer = new QTimer(this);
    m_liveTimer->setSingleShot(true);
    connect(m_liveTimer, &QTimer::timeout, this, &ParameterEditor::scheduleLivePush);

    m_pushAction = new QAction(tr("Push"), this);
    m_pushAction->setObjectName(u"action_push"_s);
    m_pushAction->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::Key_Return), QKeySequence(Qt::CTRL | Qt::Key_Enter)});
    m_pushAction->setToolTip(tr("Send the edited parameters to the device (Ctrl+Return)"));
    connect(m_pushAction, &QAction::triggered, this, [this] {
        if (m_valid && m_sync.canPush() && !m_sync.isPushing()) {
            m_livePending = false;
            startPush();
        }
    });
    m_readAction = new QAction(tr("Read"), this);
    m_readAction->setObjectName(u"action_read"_s);
    m_readAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    m_readAction->setToolTip(
        tr("Read from device: ask the device for its current parameters (Ctrl+Shift+R)"));
    connect(m_readAction, &QAction::triggered, this, &ParameterEditor::readRequested);
    m_revertAction = new QAction(tr("Revert"), this);
    m_revertAction->setObjectName(u"action_revert"_s);
    m_revertAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Backspace));
    m_revertAction->setToolTip(tr("Revert to device values (undoable; Ctrl+Shift+Backspace)"));
    connect(m_revertAction, &QAction::triggered, this, &ParameterEditor::revert);
    m_undoAction = m_undo->createUndoAction(this, tr("Undo"));
    m_redoAction = m_undo->createRedoAction(this, tr("Redo"));
    addAction(m_pushAction);

    buildUi();
    addGoToActions();
    applyParams(DeviceParams{}, HostParams{});
    m_undo->clear();
    refreshSync();
    refreshActions();
}

ParameterEditor::~ParameterEditor() = default;

// The widgets: the groups of fields, the sync bar, the derived figures and the keyboard actions.

void ParameterEditor::addGoToActions()
{
    // Alt+1 … Alt+9 put the cursor in a field, in the order they are shown.
    QStringList order;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        order << QString::fromLatin1(deviceFieldName(i));
    order << u"v_max"_s << u"tau_limit"_s;
    for (qsizetype i = 0; i < std::min<qsizetype>(order.size(), 9); ++i) {
        ParameterField *f = m_fields.value(order[i]);
        auto *go = new QAction(tr("Go to %1").arg(f->spec().symbol), this);
        go->setObjectName(u"action_goto_"_s + order[i]);
        go->setShortcut(QKeySequence(Qt::ALT | Qt::Key(Qt::Key_1 + int(i))));
        connect(go, &QAction::triggered, this, [f] {
            f->spinBox()->setFocus(Qt::ShortcutFocusReason);
            f->spinBox()->selectAll();
        });
        addAction(go);
        m_goToActions << go;
    }
}

QList<QAction *> ParameterEditor::keyboardActions() const
{
    return QList<QAction *>{m_readAction, m_revertAction} + m_goToActions;
}

void ParameterEditor::buildUi()
{
    auto *content = new QWidget;
    auto *column = new QVBoxLayout(content);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(10);
    column->addWidget(buildDeviceGroups());
    column->addWidget(buildEffectsGroup());
    column->addWidget(buildHostGroup());
    column->addStretch(1);
    // The derived figures and their warnings sit right under Push, outside the scrolling
    // fields, so they are in sight at every window size.
    auto *derivedBox = new QGroupBox(tr("Derived figures (K = K_max)"), this);
    derivedBox->setObjectName(u"derivedFiguresBox"_s);
    auto *derivedLayout = new QVBoxLayout(derivedBox);
    derivedLayout->setContentsMargins(6, 2, 6, 4);
    m_derived = new DerivedFiguresView(derivedBox);
    derivedLayout->addWidget(m_derived);

    // One column width for names and units across the groups, so the spin boxes line up.
    ParameterField::alignColumns(m_fields.values() + m_effectsSection->vibrationFields(),
                                 content->findChildren<QLabel *>(u"label_mode"_s));

    m_scroll = new QScrollArea(this);
    m_scroll->setObjectName(u"parameterScroll"_s);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidget(content);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(8);
    m_syncBar = new SyncBar(m_undo, m_readAction, m_revertAction, m_pushAction, this);
    connect(m_syncBar, &SyncBar::livePushToggled, this, &ParameterEditor::setLivePush);
    connect(m_syncBar, &SyncBar::angleInDegreesToggled, this, &ParameterEditor::setAngleInDegrees);
    connect(m_syncBar, &SyncBar::showProblemRequested, this, &ParameterEditor::showFirstProblem);
    layout->addWidget(m_syncBar);
    layout->addWidget(derivedBox);
    layout->addWidget(m_scroll, 1);
}

void ParameterEditor::showFirstProblem()
{
    ParameterField *field =
        m_problemFields.isEmpty() ? nullptr : m_fields.value(m_problemFields[0]);
    if (!field)
        return;
    m_scroll->ensureWidgetVisible(field->spinBox());
    field->spinBox()->setFocus(Qt::OtherFocusReason);
    field->spinBox()->selectAll();
}

QWidget *ParameterEditor::buildDeviceGroups()
{
    auto *box = new QWidget;
    auto *column = new QVBoxLayout(box);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(10);

    const QList<ParameterField::Spec> specs = deviceFieldSpecs();
    const struct
    {
        QString title;
        int first;
        int last;
    } groups[] = {{tr("Admittance filter — device"), 0, 1},
                  {tr("Re-centering stiffness — device"), 2, 6}};
    for (const auto &g : groups) {
        auto *group = new QGroupBox(g.title, box);
        auto *grid = new QGridLayout(group);
        grid->setHorizontalSpacing(8);
        grid->setVerticalSpacing(2);
        grid->setColumnStretch(4, 1);
        for (int i = g.first; i <= g.last; ++i) {
            auto *field = new ParameterField(specs[i], group, this);
            field->addToGrid(grid, 2 * (i - g.first));
            connectField(field);
        }
        column->addWidget(group);
    }
    return box;
}

QWidget *ParameterEditor::buildHostGroup()
{
    auto *group = new QGroupBox(tr("Reference model — host only, not sent to the device"));
    auto *grid = new QGridLayout(group);
    grid->setHorizontalSpacing(8);
    grid->setVerticalSpacing(2);
    grid->setColumnStretch(4, 1);

    auto *modeLabel = new QLabel(tr("<b>mode</b>&nbsp;&nbsp;<span style=\"color:gray\">unit "
                                    "family of v_ref, p_ref</span>"),
                                 group);
    modeLabel->setObjectName(u"label_mode"_s);
    m_mode = new QComboBox(group);
    m_mode->setObjectName(u"combo_mode"_s);
    m_mode->addItem(tr("translation (m, m/s)"), int(ReferenceMode::Translation));
    m_mode->addItem(tr("rotation (rad, rad/s)"), int(ReferenceMode::Rotation));
    m_mode->setToolTip(tr("Translation: v_ref in m/s and p_ref in m; rotation: ω_ref in rad/s "
                          "and yaw_ref in rad"));
    modeLabel->setBuddy(m_mode);
    grid->addWidget(modeLabel, 0, 1);
    grid->addWidget(m_mode, 0, 2, 1, 3, Qt::AlignLeft);
    connect(m_mode, &QComboBox::currentIndexChanged, this, [this](int index) {
        HostParams h = m_host;
        h.mode = static_cast<ReferenceMode>(m_mode->itemData(index).toInt());
        recordEdit({m_params, h, m_effects}, tr("Change mode"), u"mode"_s);
        ++m_gesture;
    });

    const ParameterField::Spec specs[] = {vMaxSpec(), tauLimitSpec()};
    int row = 1;
    for (const auto &spec : specs) {
        auto *field = new ParameterField(spec, group, this);
        field->addToGrid(grid, row);
        row += 2;
        connectField(field);
    }

    m_refDeadzone =
        new QCheckBox(tr("Hold v_ref at 0 inside the dead zone (|θ−θ0| < Q_dz)"), group);
    m_refDeadzone->setObjectName(u"check_ref_deadzone"_s);
    m_refDeadzone->setToolTip(tr("ref_deadzone: the robot does not drift while the stick rests"));
    grid->addWidget(m_refDeadzone, row, 1, 1, 4);
    connect(m_refDeadzone, &QCheckBox::toggled, this, [this](bool on) {
        HostParams h = m_host;
        h.ref_deadzone = on;
        recordEdit({m_params, h, m_effects}, tr("Change dead-zone hold"), u"ref_deadzone"_s);
        ++m_gesture;
    });
    return group;
}

QWidget *ParameterEditor::buildEffectsGroup()
{
    auto *group = new QGroupBox(tr("Effects — device: detents and end stops"));
    group->setObjectName(u"group_effects"_s);
    auto *column = new QVBoxLayout(group);
    m_effectsSection = new EffectsSection(group);
    column->addWidget(m_effectsSection);
    for (ParameterField *field : m_effectsSection->fields())
        connectField(field);
    connect(m_effectsSection, &EffectsSection::vibrateRequested, this,
            &ParameterEditor::vibrateRequested);
    return group;
}

void ParameterEditor::connectField(ParameterField *field)
{
    const QString key = field->spec().key;
    m_fields.insert(key, field);
    connect(field, &ParameterField::edited, this, [this, key](double v) { onFieldEdited(key, v); });
    connect(field, &ParameterField::editFinished, this, [this] { ++m_gesture; });
}

void ParameterEditor::revert()
{
    const DeviceTuning &device = m_sync.device();
    if (!device.params)
        return;
    Tuning t = tuning();
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        t.device.setField(i, shortestFloatDecimal(device.params->field(i)));
    // The device's float32 effects, unless they are the edited ones as sent: the defaults ±π
    // travel as the float just inside π and need no revert.
    if (const auto &fx = device.effects; fx && !sameOnWire(effectsOnWire(), *fx)) {
        for (int i = 0; i < EffectParams::kFieldCount; ++i)
            t.effects.setField(i, shortestFloatDecimal(fx->field(i)));
    }
    setTuning(t, tr("Revert to device values"));
}

EffectParams ParameterEditor::effectsOnWire() const
{
    return roundedForWire(m_effects, m_host.tau_limit);
}

DeviceTuning ParameterEditor::editedOnWire() const
{
    return {m_params, m_sync.effectsTracked() ? std::optional(effectsOnWire()) : std::nullopt};
}

void ParameterEditor::onFieldEdited(const QString &key, double value)
{
    Tuning t = tuning();
    const std::string name = key.toStdString();
    if (const int index = deviceFieldIndex(name); index >= 0)
        t.device.setField(index, value);
    else if (const int fx = effectFieldIndex(name); fx >= 0)
        t.effects.setField(fx, value);
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
    setTuning({device, host, m_effects}, undoText);
}

void ParameterEditor::applyParams(const DeviceParams &device, const HostParams &host)
{
    applyTuning({device, host, m_effects});
}

void ParameterEditor::applyTuning(const Tuning &tuning)
{
    const DeviceParams &device = tuning.device;
    const HostParams &host = tuning.host;
    const bool deviceChanged = device != m_params;
    const bool hostChanged = host != m_host;
    const bool effectsChanged = tuning.effects != m_effects;
    m_params = device;
    m_host = host;
    m_effects = tuning.effects;

    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        ParameterField *f = m_fields.value(QString::fromLatin1(deviceFieldName(i)));
        if (f->value() != device.field(i))
            f->setValue(device.field(i));
    }
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        ParameterField *f = m_fields.value(QString::fromLatin1(effectFieldName(i)));
        if (f->value() != m_effects.field(i))
            f->setValue(m_effects.field(i));
    }
    if (m_fields.value(u"v_max"_s)->value() != host.v_max)
        m_fields.value(u"v_max"_s)->setValue(host.v_max);
    if (m_fields.value(u"tau_limit"_s)->value() != host.tau_limit)
        m_fields.value(u"tau_limit"_s)->setValue(host.tau_limit);
    m_fields.value(u"v_max"_s)
        ->setUnit(host.mode == ReferenceMode::Rotation ? u"rad/s"_s : u"m/s"_s);
    {
        const QSignalBlocker b1(m_mode);
        const QSignalBlocker b2(m_refDeadzone);
        m_mode->setCurrentIndex(m_mode->findData(int(host.mode)));
        m_refDeadzone->setChecked(host.ref_deadzone);
    }

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
    if ((deviceChanged || effectsChanged) && m_livePush) {
        m_livePending = true;
        scheduleLivePush();
    }
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
    m_controlRate = controlRate > 0 ? controlRate : defaultControlRate();
    m_effectsSection->setAvailable(available, reason);
    refreshDiff();
    refreshDerived();
    refreshSync();
    refreshActions();
}

void ParameterEditor::setCanPush(bool deviceAcceptsParams, const QString &reason)
{
    m_sync.setCanPush(deviceAcceptsParams, reason);
    if (!deviceAcceptsParams) {
        m_livePending = false;
        m_liveTimer->stop();
    }
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

void ParameterEditor::pushFinished(const CommandResult &result)
{
    if (!m_sync.pushFinished(result))
        return;    // a late answer after a disconnect
    revalidate();  // shows or clears the field the device named
    refreshDiff(); // the result carries the read-back
    refreshSync();
    refreshActions();
    scheduleLivePush();
}

void ParameterEditor::startPush()
{
    // The effects go along while the device renders them and its read-back is not them yet.
    std::optional<EffectParams> effects;
    const EffectParams onWire = effectsOnWire();
    const std::optional<EffectParams> &fx = m_sync.device().effects;
    if (m_sync.effectsTracked() && (!fx || !sameOnWire(onWire, *fx)))
        effects = m_effects;
    m_sync.pushStarted(editedOnWire());
    m_sinceLastPush.start();
    revalidate();
    refreshSync();
    refreshActions();
    Q_EMIT pushRequested({m_params, effects});
}

void ParameterEditor::scheduleLivePush()
{
    if (!m_livePush || !m_livePending || !m_valid || !m_sync.canPush() || m_sync.isPushing())
        return; // retried on the next edit or when the push in flight finishes
    if (m_sinceLastPush.isValid() && m_sinceLastPush.elapsed() < m_liveInterval) {
        if (!m_liveTimer->isActive())
            m_liveTimer->start(int(m_liveInterval - m_sinceLastPush.elapsed()));
        return;
    }
    m_livePending = false;
    startPush();
}

void ParameterEditor::setLivePush(bool enabled)
{
    m_livePush = enabled;
    m_syncBar->setLivePush(enabled);
    if (!enabled) {
        m_livePending = false;
        m_liveTimer->stop();
    }
}

void ParameterEditor::setLivePushInterval(int milliseconds)
{
    m_liveInterval = std::max(0, milliseconds);
}

void ParameterEditor::setAngleInDegrees(bool degrees)
{
    if (degrees == m_degrees)
        return;
    m_degrees = degrees;
    m_syncBar->setAngleInDegrees(degrees);
    for (ParameterField *f : std::as_const(m_fields))
        f->setAngleInDegrees(degrees);
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
    for (const Violation &v : violations) {
        const QString text = QString::fromStdString(v.message());
        perField[QString::fromStdString(v.field)] << text;
        all << text;
        fields << QString::fromStdString(v.field);
    }
    const QString rejected = m_sync.rejectedField();
    if (!rejected.isEmpty() && !perField.contains(rejected))
        perField[rejected] << tr("%1: the device refused this value").arg(rejected);
    for (auto it = m_fields.cbegin(); it != m_fields.cend(); ++it)
        it.value()->setProblem(perField.value(it.key()).join(u'\n'));

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
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        ParameterField *f = m_fields.value(QString::fromLatin1(deviceFieldName(i)));
        const auto &device = m_sync.device().params;
        f->setDeviceValue(device ? std::optional<double>(device->field(i)) : std::nullopt);
    }
    // An effect field differs when what it sends differs from the read-back; the marker then
    // shows the device's value.
    const auto &fx = m_sync.device().effects;
    const EffectParams onWire = effectsOnWire();
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        ParameterField *f = m_fields.value(QString::fromLatin1(effectFieldName(i)));
        if (!fx)
            f->setDeviceValue(std::nullopt);
        else if (float(fx->field(i)) == float(onWire.field(i)))
            f->setDeviceValue(m_effects.field(i));
        else
            f->setDeviceValue(fx->field(i));
    }
}

void ParameterEditor::refreshDerived()
{
    m_derived->setFigures(deriveFigures(m_params, m_host), m_valid);
    m_effectsSection->setFigures(m_effects, m_params, m_host.tau_limit, m_controlRate, m_valid);
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
    const bool pushing = m_sync.isPushing();
    m_pushAction->setEnabled(m_valid && m_sync.canPush() && !pushing);
    m_pushAction->setToolTip(
        m_valid ? tr("Send the edited parameters to the device (Ctrl+Return)")
                : tr("Fix the invalid fields first:\n%1").arg(m_problems.join(u'\n')));
    m_syncBar->setProblems(m_problems);
    m_readAction->setEnabled(m_sync.canPush() && !pushing);
    const auto &device = m_sync.device().params;
    const auto &fx = m_sync.device().effects;
    const bool differs =
        device && (!sameOnWire(m_params, *device) || (fx && !sameOnWire(effectsOnWire(), *fx)));
    m_revertAction->setEnabled(!pushing && differs);
}

} // namespace hatpic
