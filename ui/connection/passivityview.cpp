#include "connection/passivityview.h"

#include "plots/palette.h"
#include "plots/plottheme.h"
#include "plots/qcp.h"

#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

constexpr double kWarningTint = 0.25; //!< the warning's background: this much of its frame's orange

QString millijoules(double joules)
{
    return QString::number(joules * 1e3, 'f', 2) + u" mJ"_s;
}

QString reserveText(double joules)
{
    return std::isfinite(joules) ? millijoules(joules) : PassivityView::tr("not reported");
}

} // namespace

PassivityView::PassivityView(QWidget *parent) : QGroupBox(tr("Passivity at the knob"), parent)
{
    setObjectName(u"bridge_section_passivity"_s);
    auto *layout = new QVBoxLayout(this);
    m_controller = new QLabel(this);
    m_controller->setObjectName(u"bridge_passivity_controller"_s);
    m_controller->setWordWrap(true);
    m_controller->setToolTip(
        tr("The device's passivity controller (passivity.md): it damps the knob by β·ω only "
           "while the feedback has put in more energy than the reserve allows, so a stable "
           "contact passes untouched. \"Took out\" is ∫ β·ω² dt since the bridge started. Set it "
           "in the editor's Passivity controller section (pc_damping_max 0 turns it off)."));
    layout->addWidget(m_controller);
    m_energy = new QLabel(this);
    m_energy->setObjectName(u"bridge_energy"_s);
    m_energy->setWordWrap(true);
    m_energy->setToolTip(
        tr("E = ∫ τ_ext·ω dt since the bridge started: the energy the feedback path put into "
           "the knob (> 0) or took from it (< 0). A passive contact only takes, and gives back "
           "at most what it took. \"Generated\" is E above its value when the contact began, or "
           "a window ago if higher. docs/teleop.md § The passivity observer."));
    layout->addWidget(m_energy);
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(u"bridge_energy_plot"_s);
    m_plot->setMinimumSize(220, 110);
    m_graph = m_plot->addGraph();
    m_graph->setName(tr("E"));
    m_graph->setPen(QPen(palette::channel(Channel::TauExt), 1.5));
    m_plot->xAxis->setLabel(tr("t − now [s]"));
    m_plot->yAxis->setLabel(tr("E [mJ]"));
    m_plot->xAxis->setRange(-kSpan, 0);
    plottheme::follow(m_plot);
    layout->addWidget(m_plot, 1);
    m_warning = new QLabel(this);
    m_warning->setObjectName(u"bridge_passivity_warning"_s);
    m_warning->setWordWrap(true);
    m_warning->setVisible(false);
    layout->addWidget(m_warning);
    applyPalette();
    setState({});
}

void PassivityView::changeEvent(QEvent *event)
{
    QGroupBox::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyPalette();
}

void PassivityView::applyPalette()
{
    // As the editor's warnings: the window's text on its colour tinted with the warning's orange,
    // framed in it, alike on the light and the dark theme.
    const QPalette &p = palette();
    m_warning->setStyleSheet(
        QStringLiteral("QLabel { background: %1; color: %2; border: 1px solid %3;"
                       " border-radius: 4px; padding: 4px; }")
            .arg(plottheme::mix(palette::kWarningFrame, p.color(QPalette::Window), kWarningTint)
                     .name(),
                 p.color(QPalette::WindowText).name(), palette::kWarningFrame.name()));
}

void PassivityView::clear()
{
    m_times.clear();
    m_energies.clear();
    setState({});
}

void PassivityView::setState(const analysis::PassivityObserver::State &s,
                             const analysis::PassivitySettings &settings)
{
    if (s.samples == 0)
        m_controller->setText(QString());
    else if (!s.controllerReported)
        m_controller->setText(tr("Controller: none reported — this device's telemetry carries "
                                 "no τ_pc (no passivity capability); only the observer below "
                                 "watches."));
    else if (s.dampedAtRest)
        m_controller->setText(
            tr("Controller: damping at rest — the knob rests, yet the controller damps it in "
               "%1 % of the samples (β up to %2 N·m·s/rad), so it feels heavier than tuned: the "
               "loop does not rest on its own at this gain and delay. Lower the gain, raise "
               "M_adm or cut the delay. Took out %3; reserve %4.")
                .arg(QString::number(100 * s.restDampedShare, 'f', 0),
                     QString::number(s.dampingCoefficient, 'f', 3), millijoules(s.dissipated),
                     reserveText(s.reserve)));
    else if (s.damping)
        m_controller->setText(
            tr("Controller: damping — β up to %1 N·m·s/rad (τ_pc %2 N·m). Took out %3; "
               "reserve %4.")
                .arg(QString::number(s.dampingCoefficient, 'f', 3),
                     QString::number(s.controllerTorque, 'f', 4), millijoules(s.dissipated),
                     reserveText(s.reserve)));
    else
        m_controller->setText(tr("Controller: idle — nothing to damp. Took out %1; reserve %2.")
                                  .arg(millijoules(s.dissipated), reserveText(s.reserve)));
    m_controller->setVisible(s.samples > 0);
    if (s.samples == 0) {
        m_energy->setText(tr("No sample yet"));
    } else {
        // What is good and what is bad, in words first, the figures after (issue 27).
        if (s.warning)
            m_energy->setText(tr("Bad: generating energy in contact. E %1; generated lately %2 "
                                 "(more than %3 is unstable).")
                                  .arg(millijoules(s.energy), millijoules(s.generated),
                                       millijoules(settings.threshold)));
        else if (s.inContact)
            m_energy->setText(tr("Good: passive in contact. E %1; generated lately %2 (up to "
                                 "%3 is fine).")
                                  .arg(millijoules(s.energy), millijoules(s.generated),
                                       millijoules(settings.threshold)));
        else
            m_energy->setText(tr("Good: no contact (|τ_ext| ≤ %2 N·m), nothing to dissipate. "
                                 "E %1.")
                                  .arg(millijoules(s.energy))
                                  .arg(settings.contactTorque));
    }
    m_warning->setText(
        tr("The loop is generating energy in contact (%1 within %2 s): it can chatter or push "
           "the hand. To make contact stable: lower the gain, raise M_adm (the admittance's "
           "damping) or pc_damping_max (the device's passivity controller), or cut the delay "
           "(Stamp → applied; the robot's rate and network).")
            .arg(millijoules(std::max(s.generated, settings.threshold)))
            .arg(settings.window));
    m_warning->setVisible(s.warning);

    if (std::isfinite(s.time) && (m_times.isEmpty() || s.time != m_times.last())) {
        if (!m_times.isEmpty() && s.time < m_times.last()) { // another clock: start again
            m_times.clear();
            m_energies.clear();
        }
        m_times.append(s.time);
        m_energies.append(s.energy);
        while (m_times.first() < s.time - kSpan) {
            m_times.removeFirst();
            m_energies.removeFirst();
        }
    }
    QList<double> keys, values;
    double low = 0, high = 0;
    for (qsizetype i = 0; i < m_times.size(); ++i) {
        keys.append(m_times[i] - m_times.last());
        values.append(m_energies[i] * 1e3);
        low = std::min(low, values.last());
        high = std::max(high, values.last());
    }
    m_graph->setData(keys, values, true);
    const double margin = std::max(0.1, 0.1 * (high - low));
    m_plot->yAxis->setRange(low - margin, high + margin);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

bool PassivityView::isWarning() const
{
    return !m_warning->isHidden();
}

QString PassivityView::text() const
{
    const QString controller = m_controller->text();
    return (controller.isEmpty() ? QString() : controller + u" | "_s) + m_energy->text() +
           (isWarning() ? u" | "_s + m_warning->text() : QString());
}

} // namespace hatpic
