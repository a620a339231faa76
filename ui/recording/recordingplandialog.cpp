#include "recording/recordingplandialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSettings>

namespace hatpic {

namespace {

using Start = RecordingPlan::Start;
using Quantity = RecordingPlan::Quantity;
using Edge = RecordingPlan::Edge;

QString key(const char *name)
{
    return QStringLiteral("recording/plan/") + QLatin1String(name);
}

} // namespace

RecordingPlanDialog::RecordingPlanDialog(QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("recordingPlanDialog"));
    setWindowTitle(tr("Recording Options"));
    m_start = new QComboBox(this);
    m_start->setObjectName(QStringLiteral("planStart"));
    m_start->addItem(tr("Now"), int(Start::Now));
    m_start->addItem(tr("On the next push"), int(Start::NextPush));
    m_start->addItem(tr("When a value crosses a level"), int(Start::Threshold));
    m_quantity = new QComboBox(this);
    m_quantity->setObjectName(QStringLiteral("planQuantity"));
    m_quantity->addItem(tr("θ (angle)"), int(Quantity::Theta));
    m_quantity->addItem(tr("τ (interaction torque)"), int(Quantity::Tau));
    m_edge = new QComboBox(this);
    m_edge->setObjectName(QStringLiteral("planEdge"));
    m_edge->addItem(tr("rising"), int(Edge::Rising));
    m_edge->addItem(tr("falling"), int(Edge::Falling));
    m_level = new QDoubleSpinBox(this);
    m_level->setObjectName(QStringLiteral("planLevel"));
    m_level->setRange(-1000, 1000);
    m_level->setDecimals(4);
    m_level->setSingleStep(0.01);
    m_pre = new QDoubleSpinBox(this);
    m_pre->setObjectName(QStringLiteral("planPreTrigger"));
    m_pre->setRange(0, RecordingPlan::kMaxPreTrigger_s);
    m_pre->setDecimals(2);
    m_pre->setSuffix(tr(" s"));
    m_pre->setToolTip(
        tr("Kept from before the trigger (at most %1 s)").arg(RecordingPlan::kMaxPreTrigger_s));
    m_duration = new QDoubleSpinBox(this);
    m_duration->setObjectName(QStringLiteral("planDuration"));
    m_duration->setRange(0, 24 * 3600);
    m_duration->setDecimals(2);
    m_duration->setSuffix(tr(" s"));
    m_duration->setSpecialValueText(tr("until stopped"));
    m_duration->setToolTip(tr("Recorded from the trigger on; the recording then closes itself"));

    auto *form = new QFormLayout(this);
    form->addRow(tr("&Start:"), m_start);
    form->addRow(tr("&Value:"), m_quantity);
    form->addRow(tr("&Edge:"), m_edge);
    form->addRow(tr("&Level:"), m_level);
    form->addRow(tr("&Before the trigger:"), m_pre);
    form->addRow(tr("Len&gth:"), m_duration);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_start, &QComboBox::currentIndexChanged, this, &RecordingPlanDialog::updateEnabled);
    connect(m_quantity, &QComboBox::currentIndexChanged, this, &RecordingPlanDialog::updateEnabled);
    setPlan({});
}

void RecordingPlanDialog::setPlan(const RecordingPlan &plan)
{
    const RecordingPlan p = plan.sanitized();
    m_start->setCurrentIndex(m_start->findData(int(p.start)));
    m_quantity->setCurrentIndex(m_quantity->findData(int(p.quantity)));
    m_edge->setCurrentIndex(m_edge->findData(int(p.edge)));
    m_level->setValue(p.level);
    m_pre->setValue(p.preTrigger_s);
    m_duration->setValue(p.duration_s);
    updateEnabled();
}

RecordingPlan RecordingPlanDialog::plan() const
{
    RecordingPlan p;
    p.start = static_cast<Start>(m_start->currentData().toInt());
    p.quantity = static_cast<Quantity>(m_quantity->currentData().toInt());
    p.edge = static_cast<Edge>(m_edge->currentData().toInt());
    p.level = m_level->value();
    p.preTrigger_s = m_pre->value();
    p.duration_s = m_duration->value();
    return p.sanitized();
}

void RecordingPlanDialog::updateEnabled()
{
    const bool threshold = m_start->currentData().toInt() == int(Start::Threshold);
    m_quantity->setEnabled(threshold);
    m_edge->setEnabled(threshold);
    m_level->setEnabled(threshold);
    const bool theta = m_quantity->currentData().toInt() == int(Quantity::Theta);
    m_level->setSuffix(theta ? tr(" rad") : tr(" N·m"));
}

QString RecordingPlanDialog::describeTrigger(const RecordingPlan &plan)
{
    switch (plan.start) {
    case Start::Now:
        return tr("now");
    case Start::NextPush:
        return tr("the next push");
    case Start::Threshold:
        break;
    }
    const bool theta = plan.quantity == Quantity::Theta;
    const QString level = theta ? tr("%1 rad").arg(plan.level) : tr("%1 N·m").arg(plan.level);
    const bool rising = plan.edge == Edge::Rising;
    if (theta)
        return rising ? tr("θ rising through %1").arg(level)
                      : tr("θ falling through %1").arg(level);
    return rising ? tr("τ rising through %1").arg(level) : tr("τ falling through %1").arg(level);
}

RecordingPlan RecordingPlanDialog::loadPlan(const QSettings &settings)
{
    const RecordingPlan defaults;
    RecordingPlan p;
    const int start = settings.value(key("start"), int(defaults.start)).toInt();
    if (start >= int(Start::Now) && start <= int(Start::Threshold))
        p.start = static_cast<Start>(start);
    p.quantity =
        settings.value(key("quantity"), int(defaults.quantity)).toInt() == int(Quantity::Tau)
            ? Quantity::Tau
            : Quantity::Theta;
    p.edge = settings.value(key("edge"), int(defaults.edge)).toInt() == int(Edge::Falling)
                 ? Edge::Falling
                 : Edge::Rising;
    p.level = settings.value(key("level"), defaults.level).toDouble();
    p.preTrigger_s = settings.value(key("preTrigger"), defaults.preTrigger_s).toDouble();
    p.duration_s = settings.value(key("duration"), defaults.duration_s).toDouble();
    return p.sanitized();
}

void RecordingPlanDialog::savePlan(QSettings &settings, const RecordingPlan &plan)
{
    settings.setValue(key("start"), int(plan.start));
    settings.setValue(key("quantity"), int(plan.quantity));
    settings.setValue(key("edge"), int(plan.edge));
    settings.setValue(key("level"), plan.level);
    settings.setValue(key("preTrigger"), plan.preTrigger_s);
    settings.setValue(key("duration"), plan.duration_s);
}

} // namespace hatpic
