// ParameterEditor's widgets: the groups of fields, the sync bar, the derived figures and the
// keyboard actions. Its behaviour (edits, sync, push) is in parametereditor.cpp.
#include "editor/parametereditor.h"

#include "editor/derivedfiguresview.h"
#include "editor/effectssection.h"
#include "editor/parameterfield.h"
#include "editor/parameterspecs.h"
#include "editor/scientificspinbox.h"
#include "editor/syncbar.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>

namespace hatpic {

using namespace Qt::StringLiterals;

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

} // namespace hatpic
