#include "editor/parameterform.h"

#include "editor/effectssection.h"
#include "editor/parameterfield.h"
#include "editor/parameterspecs.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace hatpic {

using namespace Qt::StringLiterals;

ParameterForm::ParameterForm(QWidget *parent) : QWidget(parent)
{
    auto *column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(10);
    column->addWidget(buildDeviceGroups());
    column->addWidget(buildEffectsGroup());
    column->addWidget(buildPassivityGroup());
    column->addWidget(buildHostGroup());
    column->addStretch(1);

    // One column width for names and units across the groups, so the spin boxes line up.
    ParameterField::alignColumns(m_fields.values() + m_effectsSection->vibrationFields(),
                                 findChildren<QLabel *>(u"label_mode"_s));
}

QWidget *ParameterForm::buildDeviceGroups()
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
        QGridLayout *grid = ParameterField::newGrid(group);
        for (int i = g.first; i <= g.last; ++i) {
            auto *field = new ParameterField(specs[i], group, this);
            field->addToGrid(grid, 2 * (i - g.first));
            addField(field);
        }
        column->addWidget(group);
    }
    return box;
}

QWidget *ParameterForm::buildHostGroup()
{
    auto *group = new QGroupBox(tr("Reference model — host only, not sent to the device"));
    QGridLayout *grid = ParameterField::newGrid(group);

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
        Q_EMIT modeEdited(static_cast<ReferenceMode>(m_mode->itemData(index).toInt()));
    });

    const ParameterField::Spec specs[] = {vMaxSpec(), tauLimitSpec()};
    int row = 1;
    for (const auto &spec : specs) {
        auto *field = new ParameterField(spec, group, this);
        field->addToGrid(grid, row);
        row += 2;
        addField(field);
    }

    m_refDeadzone =
        new QCheckBox(tr("Hold v_ref at 0 inside the dead zone (|θ−θ0| < Q_dz)"), group);
    m_refDeadzone->setObjectName(u"check_ref_deadzone"_s);
    m_refDeadzone->setToolTip(tr("ref_deadzone: the robot does not drift while the stick rests"));
    grid->addWidget(m_refDeadzone, row, 1, 1, 4);
    connect(m_refDeadzone, &QCheckBox::toggled, this, &ParameterForm::refDeadzoneEdited);
    return group;
}

QWidget *ParameterForm::buildEffectsGroup()
{
    auto *group = new QGroupBox(tr("Effects — device: detents and end stops"));
    group->setObjectName(u"group_effects"_s);
    auto *column = new QVBoxLayout(group);
    m_effectsSection = new EffectsSection(group);
    column->addWidget(m_effectsSection);
    for (ParameterField *field : m_effectsSection->fields())
        addField(field);
    return group;
}

QWidget *ParameterForm::buildPassivityGroup()
{
    auto *group = new QGroupBox(tr("Passivity controller — device: stable contact under delay"));
    group->setObjectName(u"group_passivity"_s);
    QGridLayout *grid = ParameterField::newGrid(group);
    m_passivityUnavailable = new QLabel(group);
    m_passivityUnavailable->setObjectName(u"label_passivity_unavailable"_s);
    m_passivityUnavailable->setWordWrap(true);
    grid->addWidget(m_passivityUnavailable, 0, 0, 1, 5);
    auto *about = new QLabel(
        tr("Watches the energy the robot's feedback puts into the knob and damps only what a "
           "delayed loop adds: a stable contact passes untouched. pc_damping_max 0 turns it "
           "off; more holds longer delays and makes a swinging contact heavier. The Bridge "
           "panel shows when it damps, the Stability map what it buys."),
        group);
    about->setObjectName(u"label_passivity_about"_s);
    about->setWordWrap(true);
    grid->addWidget(about, 1, 0, 1, 5);
    const QList<ParameterField::Spec> specs = passivityFieldSpecs();
    for (int i = 0; i < specs.size(); ++i) {
        auto *field = new ParameterField(specs[i], group, this);
        field->addToGrid(grid, 2 + 2 * i);
        addField(field);
    }
    setPassivityAvailable(false, QString());
    return group;
}

void ParameterForm::setPassivityAvailable(bool available, const QString &reason)
{
    m_passivityUnavailable->setText(
        reason.isEmpty() ? tr("Not connected: edited here and saved in the profile, and pushed "
                              "with the parameters to a device that has the controller.")
                         : tr("This device has no passivity controller: %1. The values stay in "
                              "the profile and are not sent.")
                               .arg(reason));
    m_passivityUnavailable->setVisible(!available);
}

void ParameterForm::addField(ParameterField *field)
{
    const QString key = field->spec().key;
    m_fields.insert(key, field);
    connect(field, &ParameterField::edited, this,
            [this, key](double v) { Q_EMIT fieldEdited(key, v); });
    connect(field, &ParameterField::editFinished, this, &ParameterForm::editFinished);
}

void ParameterForm::showTuning(const Tuning &tuning)
{
    const HostParams &host = tuning.host;
    const auto show = [this](const QString &key, double value) {
        ParameterField *f = m_fields.value(key);
        if (f->value() != value)
            f->setValue(value);
    };
    const auto showBlock = [&show](const auto &block, std::string_view (*name)(int)) {
        for (int i = 0; i < std::decay_t<decltype(block)>::kFieldCount; ++i)
            show(QString::fromLatin1(name(i)), block.field(i));
    };
    showBlock(tuning.device, &deviceFieldName);
    showBlock(tuning.effects, &effectFieldName);
    showBlock(tuning.passivity, &passivityFieldName);
    show(u"v_max"_s, host.v_max);
    show(u"tau_limit"_s, host.tau_limit);
    m_fields.value(u"v_max"_s)
        ->setUnit(host.mode == ReferenceMode::Rotation ? u"rad/s"_s : u"m/s"_s);
    const QSignalBlocker b1(m_mode);
    const QSignalBlocker b2(m_refDeadzone);
    m_mode->setCurrentIndex(m_mode->findData(int(host.mode)));
    m_refDeadzone->setChecked(host.ref_deadzone);
}

void ParameterForm::showDevice(const DeviceTuning &device, const Tuning &edited,
                               const EffectParams &effectsOnWire)
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        ParameterField *f = m_fields.value(QString::fromLatin1(deviceFieldName(i)));
        f->setDeviceValue(device.params ? std::optional<double>(device.params->field(i))
                                        : std::nullopt);
    }
    showBlockDevice(device.effects, edited.effects, effectsOnWire, &effectFieldName);
    showBlockDevice(device.passivity, edited.passivity, edited.passivity, &passivityFieldName);
}

template<typename Block>
void ParameterForm::showBlockDevice(const std::optional<Block> &device, const Block &edited,
                                    const Block &onWire, std::string_view (*name)(int))
{
    // A field differs when what it sends differs from the read-back (as float32); the marker
    // then shows the device's value, else the field's own.
    for (int i = 0; i < Block::kFieldCount; ++i) {
        ParameterField *f = m_fields.value(QString::fromLatin1(name(i)));
        if (!device)
            f->setDeviceValue(std::nullopt);
        else if (float(device->field(i)) == float(onWire.field(i)))
            f->setDeviceValue(edited.field(i));
        else
            f->setDeviceValue(device->field(i));
    }
}

void ParameterForm::setProblems(const QHash<QString, QStringList> &perField)
{
    for (auto it = m_fields.cbegin(); it != m_fields.cend(); ++it)
        it.value()->setProblem(perField.value(it.key()).join(u'\n'));
}

void ParameterForm::setAngleInDegrees(bool degrees)
{
    for (ParameterField *f : std::as_const(m_fields))
        f->setAngleInDegrees(degrees);
}

} // namespace hatpic
