#include "editor/effectssection.h"

#include "editor/parameterfield.h"
#include "editor/parameterspecs.h"
#include "model/paramtable.h"
#include "model/servo.h"
#include "model/staticcurve.h"
#include "plots/palette.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

#include <cmath>
#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QString num(double v)
{
    return QString::number(v, 'g', 3);
}

QString colored(const QColor &color, const QString &text)
{
    return u"<span style=\"color:%1\">%2</span>"_s.arg(color.name(), text.toHtmlEscaped());
}

QString vibrationKey(const ParameterField *field)
{
    return QString::fromUtf16(EffectsSection::kVibrationKey) + u'/' + field->spec().key;
}

} // namespace

EffectsSection::EffectsSection(QWidget *parent) : QWidget(parent)
{
    auto *column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(4);

    m_unavailable = new QLabel(this);
    m_unavailable->setObjectName(u"label_effects_unavailable"_s);
    m_unavailable->setWordWrap(true);
    column->addWidget(m_unavailable);

    QGridLayout *grid = ParameterField::newGrid(nullptr);
    const QList<ParameterField::Spec> specs = effectFieldSpecs();
    for (int i = 0; i < specs.size(); ++i) {
        auto *field = new ParameterField(specs[i], this, this);
        field->addToGrid(grid, 2 * i);
        m_fields << field; // the form takes their edits (ParameterForm::field)
    }
    column->addLayout(grid);

    m_figures = new QLabel(this);
    m_figures->setObjectName(u"label_effect_figures"_s);
    m_figures->setWordWrap(true);
    m_figures->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_figures->setToolTip(
        tr("A·2π/s is the detents' stiffness at a rest position. b − K·h/2 is the passivity "
           "margin of a spring K rendered every h seconds on a knob with damping b (Colgate "
           "and Schenkel): below 0 it may chatter. b is the STS3032's identified viscous "
           "friction, h the device's control period."));
    column->addWidget(m_figures);
    m_warnings = new QLabel(this);
    m_warnings->setObjectName(u"label_effect_warnings"_s);
    m_warnings->setWordWrap(true);
    m_warnings->hide();
    column->addWidget(m_warnings);

    column->addWidget(buildVibrationGroup());
    setAvailable(false, QString());
}

QWidget *EffectsSection::buildVibrationGroup()
{
    // A titled part of the section rather than a nested group box, whose frame would push
    // the fields out of line with the others and widen the editor.
    auto *group = new QWidget(this);
    group->setObjectName(u"group_vibration"_s);
    QGridLayout *grid = ParameterField::newGrid(group);
    grid->setContentsMargins(0, 6, 0, 0);
    auto *title = new QLabel(u"<b>%1</b>"_s.arg(tr("Vibration test")) + u" — "_s +
                                 tr("sent now, not part of the profile"),
                             group);
    grid->addWidget(title, 0, 0, 1, 5);
    const QList<ParameterField::Spec> specs = vibrationFieldSpecs();
    for (int i = 0; i < specs.size(); ++i) {
        auto *field = new ParameterField(specs[i], group, this);
        field->addToGrid(grid, 1 + 2 * i);
        m_vibrationFields << field;
        connect(field, &ParameterField::edited, this, [this] {
            revalidateVibration();
            rememberVibration();
        });
    }
    const QSettings settings;
    const double defaults[] = {kDefaultVibration.amplitude, kDefaultVibration.frequency,
                               kDefaultVibration.duration};
    for (int i = 0; i < m_vibrationFields.size(); ++i) {
        ParameterField *f = m_vibrationFields[i];
        const double v = settings.value(vibrationKey(f), defaults[i]).toDouble();
        f->setValue(std::isfinite(v) ? v : defaults[i]);
    }

    m_vibrate = new QPushButton(tr("Vibrate"), group);
    m_vibrate->setObjectName(u"button_vibrate"_s);
    connect(m_vibrate, &QPushButton::clicked, this,
            [this] { Q_EMIT vibrateRequested(vibration()); });
    m_stop = new QPushButton(tr("Stop"), group);
    m_stop->setObjectName(u"button_vibrate_stop"_s);
    m_stop->setToolTip(tr("Stop a running cue (VIBRATE with a = 0)"));
    connect(m_stop, &QPushButton::clicked, this, [this] {
        Vibration v = vibration();
        v.amplitude = 0;
        Q_EMIT vibrateRequested(v);
    });
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_stop);
    buttons->addWidget(m_vibrate);
    grid->addLayout(buttons, 1 + 2 * int(specs.size()), 1, 1, 4);
    revalidateVibration();
    return group;
}

void EffectsSection::setAvailable(bool available, const QString &reason)
{
    m_available = available;
    m_unavailable->setText(
        colored(palette::kCautionText,
                reason.isEmpty() ? tr("Not connected: effects are edited here and saved in the "
                                      "profile, and pushed with the parameters to a device "
                                      "that renders them.")
                                 : tr("This device cannot render effects: %1. They stay in "
                                      "the profile and are not sent.")
                                       .arg(reason)));
    m_unavailable->setVisible(!available);
    refreshButtons();
}

void EffectsSection::setFigures(const EffectParams &effects, const DeviceParams &device,
                                double tauLimit, double controlRate, bool valid)
{
    m_tauLimit = tauLimit;
    m_controlRate = controlRate;
    // The cue's frequency must stay below half the control rate: typing more is refused with
    // that rule, rather than clamped to a bound that breaks it too.
    const double tableMax = kVibrationFields[1].upper.value;
    if (controlRate > 0 && controlRate / 2 <= tableMax)
        m_vibrationFields[1]->setMaximum(controlRate / 2, true);
    else
        m_vibrationFields[1]->setMaximum(tableMax, false);
    revalidateVibration();
    if (!valid) {
        m_figures->setText(tr("Figures: — (fix the invalid fields first)"));
        m_warningList.clear();
        m_warnings->clear();
        m_warnings->hide();
        return;
    }
    const double b = servo::kViscousFriction;
    const double h = 1.0 / controlRate;
    const EffectFigures f = deriveEffectFigures(effects, device, b, h);
    const bool detents = detentsActive(effects);
    QStringList figures;
    figures << tr("detent peak stiffness A·2π/s = %1 N·m/rad")
                   .arg(detents ? num(f.detentPeakStiffness) : tr("— (off)"));
    figures << tr("wall passivity margin b − K_w·h/2 = %1 N·m·s/rad (b = %2, h = %3 ms)")
                   .arg(num(f.wallPassivityMargin), num(b), num(h * 1e3));
    m_figures->setText(figures.join(u"; "));

    QStringList warnings;
    for (const EffectWarning w : f.warnings)
        warnings << sayWarning(w, effects, device, f, b, h);
    m_warningList = warnings;
    QStringList lines;
    for (const QString &w : std::as_const(warnings))
        lines << colored(palette::kProblemText, u"⚠ "_s + w);
    m_warnings->setText(lines.join(u"<br>"));
    m_warnings->setVisible(!warnings.isEmpty());
}

QString EffectsSection::sayWarning(EffectWarning warning, const EffectParams &effects,
                                   const DeviceParams &device, const EffectFigures &f, double b,
                                   double h)
{
    switch (warning) {
    case EffectWarning::WallNotPassive:
        return tr("K_w·h/2 = %1 N·m·s/rad exceeds the knob's damping b = %2: the wall "
                  "may chatter (not passive).")
            .arg(num(effects.wall_stiffness * h / 2), num(b));
    case EffectWarning::DetentsNotPassive:
        return tr("The detents' peak stiffness %1 N·m/rad times h/2 exceeds the knob's "
                  "damping b = %2: the detents may chatter (not passive).")
            .arg(num(f.detentPeakStiffness), num(b));
    case EffectWarning::WallAboveServo:
        return tr("K_w = %1 N·m/rad is above what the STS3032's position loop follows "
                  "with this inertia, D_adm·(2π·%2 Hz)² = %3 N·m/rad: the wall is likely "
                  "to bounce. Try it on the simulator first, or raise D_adm.")
            .arg(num(effects.wall_stiffness), num(servo::kPositionLoopHz), num(f.servoLimit));
    case EffectWarning::DetentsAboveServo:
        return tr("The detents' peak stiffness A·2π/s = %1 N·m/rad is above what the "
                  "STS3032's position loop follows with this inertia (%2 N·m/rad): the "
                  "detents are likely to buzz.")
            .arg(num(f.detentPeakStiffness), num(f.servoLimit));
    case EffectWarning::DetentsStifferThanNotch:
        return tr("The detents (%1 N·m/rad at a rest position) are stiffer than the "
                  "notch K_max = %2 N·m/rad: near θ0 they, not the notch, set the feel.")
            .arg(num(f.detentPeakStiffness), num(device.K_max));
    }
    return {};
}

QString EffectsSection::warningText() const
{
    return m_warningList.join(u'\n');
}

Vibration EffectsSection::vibration() const
{
    return Vibration{m_vibrationFields[0]->value(), m_vibrationFields[1]->value(),
                     m_vibrationFields[2]->value()};
}

void EffectsSection::setVibration(const Vibration &vibration)
{
    m_vibrationFields[0]->setValue(vibration.amplitude);
    m_vibrationFields[1]->setValue(vibration.frequency);
    m_vibrationFields[2]->setValue(vibration.duration);
    revalidateVibration();
}

void EffectsSection::revalidateVibration()
{
    const std::vector<Violation> violations = validate(vibration(), m_tauLimit, m_controlRate);
    m_vibrationProblems.clear();
    QStringList perField[3];
    for (const Violation &v : violations) {
        const QString text = QString::fromStdString(v.message());
        m_vibrationProblems << text;
        for (int i = 0; i < 3; ++i) {
            if (v.field == kVibrationFields[std::size_t(i)].name)
                perField[i] << text;
        }
    }
    for (int i = 0; i < 3; ++i)
        m_vibrationFields[i]->setProblem(perField[i].join(u'\n'));
    refreshButtons();
}

void EffectsSection::refreshButtons()
{
    if (!m_vibrate)
        return;
    const bool valid = m_vibrationProblems.isEmpty();
    m_vibrate->setEnabled(m_available && valid);
    m_stop->setEnabled(m_available);
    m_vibrate->setToolTip(!m_available ? tr("Needs a device that renders effects")
                          : valid
                              ? tr("Send the cue τ_vib = a·sin(2π·f·t) for d seconds (VIBRATE)")
                              : tr("Fix the cue first:\n%1").arg(m_vibrationProblems.join(u'\n')));
}

void EffectsSection::rememberVibration() const
{
    QSettings settings;
    for (const ParameterField *f : m_vibrationFields)
        settings.setValue(vibrationKey(f), f->value());
}

} // namespace hatpic
