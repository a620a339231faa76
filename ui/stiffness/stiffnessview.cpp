#include "stiffness/stiffnessview.h"

#include "model/staticcurve.h"
#include "model/stiffness.h"
#include "stiffness/staticcurves.h"

#include "plots/axistitle.h"
#include "plots/fadingtrail.h"
#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/plottheme.h"
#include "plots/qcp.h"
#include "tuning/tuningmodel.h"

#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

constexpr double kPi = std::numbers::pi;
// The curves are τ_rec(θ) and K_rec(θ): τ_rec's colour, solid when edited, dashed when the
// device's; the bands and the live point as in the time plots (plots/palette.h).
const QColor kCurveColour = palette::channel(Channel::TauRec);
const QColor kPointColour = palette::kLivePoint;

QCPItemStraightLine *straightLine(QCustomPlot *plot, QCPAxisRect *rect, const QPen &pen)
{
    auto *line = new QCPItemStraightLine(plot);
    line->setClipAxisRect(rect);
    line->setClipToAxisRect(true);
    for (QCPItemPosition *p : {line->point1, line->point2})
        p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    line->setPen(pen);
    return line;
}

} // namespace

StiffnessView::StiffnessView(const TuningModel &tuning, QWidget *parent)
    : QWidget(parent), m_tuning(tuning)
{
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(u"stiffness_plot"_s);
    m_plot->setMinimumSize(280, 200);
    m_plot->plotLayout()->clear();
    m_torqueRect = new QCPAxisRect(m_plot);
    m_stiffnessRect = new QCPAxisRect(m_plot);
    m_plot->plotLayout()->addElement(0, 0, m_torqueRect);
    m_plot->plotLayout()->addElement(1, 0, m_stiffnessRect);
    auto *margins = new QCPMarginGroup(m_plot);
    m_torqueRect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    m_stiffnessRect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    // Few ticks, titles in a corner and one θ axis for both: the dock may be short (1280×720),
    // and neither its numbers nor its titles may collide (issue 21).
    for (QCPAxisRect *rect : {m_torqueRect, m_stiffnessRect})
        rect->axis(QCPAxis::atLeft)->ticker()->setTickCount(3);
    m_torqueRect->axis(QCPAxis::atBottom)->setTickLabels(false);
    m_torqueRect->setAutoMargins(QCP::msLeft | QCP::msRight | QCP::msTop);
    m_torqueRect->setMargins(QMargins(0, 0, 0, 6));
    setCornerTitle(m_torqueRect, tr("τ_rec [N·m]"));
    setCornerTitle(m_stiffnessRect, tr("K_rec [N·m/rad]"));

    auto graph = [this](QCPAxisRect *rect, const QPen &pen, const QString &name) {
        QCPGraph *g = m_plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        g->setPen(pen);
        g->setName(name);
        return g;
    };
    QPen edited(kCurveColour, 2.0);
    // The same colour, dashed (palette.h): a darker shade was faint on the dark theme.
    QPen device(kCurveColour, 1.5, Qt::DashLine);
    m_otherTorque = graph(m_torqueRect, edited, QString());
    m_otherStiffness = graph(m_stiffnessRect, edited, QString());
    m_deviceTorque = graph(m_torqueRect, device, tr("device"));
    m_deviceStiffness = graph(m_stiffnessRect, device, tr("device"));
    m_torque = graph(m_torqueRect, edited, tr("edited"));
    m_stiffness = graph(m_stiffnessRect, edited, tr("edited"));
    m_deviceMarks = std::make_unique<EffectMarks>(m_plot, m_torqueRect, m_stiffnessRect, true);
    m_editedMarks = std::make_unique<EffectMarks>(m_plot, m_torqueRect, m_stiffnessRect, false);
    m_trail = std::make_unique<FadingTrail>(
        m_torqueRect->axis(QCPAxis::atBottom), m_torqueRect->axis(QCPAxis::atLeft),
        palette::channel(Channel::Tau), tr("τ (measured), last %1 s").arg(kTrailSeconds));
    m_trail->piece(FadingTrail::kPieces - 1)->removeFromLegend();
    m_point = graph(m_torqueRect, QPen(kPointColour), tr("live (θ, measured τ_rec)"));
    m_point->setLineStyle(QCPGraph::lsNone);
    m_point->setScatterStyle(plottheme::livePointStyle(palette()));

    // One compact row above the plots, so it never hides the curve or the live point.
    auto *legend = m_legend = new QCPLegend;
    m_plot->plotLayout()->insertRow(0);
    m_plot->plotLayout()->addElement(0, 0, legend);
    m_plot->plotLayout()->setRowStretchFactor(0, 0.001);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    legend->setLayer(u"legend"_s);
    legend->setFont(font());
    legend->setBorderPen(Qt::NoPen);
    legend->setBrush(Qt::NoBrush);
    legend->setMargins(QMargins(4, 2, 4, 0));
    legend->setWrap(3);
    for (QCPGraph *g : {m_torque, m_otherTorque, m_deviceTorque, m_point})
        g->addToLegend(legend);
    m_trail->piece(FadingTrail::kPieces - 1)->addToLegend(legend);
    // Room below the text (the legend clips each item to its rect, which would cut the "_").
    for (int k = 0; k < legend->itemCount(); ++k)
        if (QCPAbstractLegendItem *item = legend->item(k)) // a wrapped grid may hold gaps
            item->setMargins(QMargins(2, 1, 2, 3));

    QPen limitPen(palette::kLimit, 1.0, Qt::DotLine);
    m_limitHigh = straightLine(m_plot, m_torqueRect, limitPen);
    m_limitLow = straightLine(m_plot, m_torqueRect, limitPen);
    m_cursor = straightLine(m_plot, m_stiffnessRect, QPen(kPointColour, 1.0, Qt::DotLine));
    m_cursor->setVisible(false);
    // The live point moves with every batch of samples; on a buffered layer of its own it is
    // redrawn alone, over the curves, axes and legend drawn before.
    m_plot->layer(u"overlay"_s)->setMode(QCPLayer::lmBuffered);
    m_trail->setLayer(u"overlay"_s); // under the live point
    m_point->setLayer(u"overlay"_s);
    m_cursor->setLayer(u"overlay"_s);

    const QColor shades[] = {palette::kNotch, palette::kDeadZone};
    for (int i = 0; i < 4; ++i) {
        QCPAxisRect *rect = i < 2 ? m_torqueRect : m_stiffnessRect;
        auto *r = new QCPItemRect(m_plot);
        r->setLayer(u"grid"_s);
        r->setClipAxisRect(rect);
        r->setPen(Qt::NoPen);
        r->setBrush(shades[i % 2]);
        for (QCPItemPosition *p : {r->topLeft, r->bottomRight}) {
            p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            p->setAxisRect(rect);
            p->setTypeX(QCPItemPosition::ptPlotCoords);
            p->setTypeY(QCPItemPosition::ptAxisRectRatio);
        }
        r->topLeft->setCoords(0, 0);
        r->bottomRight->setCoords(0, 1);
        m_shades[i] = r;
    }

    m_replotTimer = new QTimer(this);
    m_replotTimer->setSingleShot(true);
    m_replotTimer->setInterval(kRepaintIntervalMs);
    connect(m_replotTimer, &QTimer::timeout, this, [this] {
        if (m_fullReplot)
            m_plot->replot();
        else
            m_plot->layer(u"overlay"_s)->replot(); // a full replot if the buffers are stale
        m_fullReplot = false;
    });

    m_plot->setToolTip(tr("Solid: the edited parameters. Dashed: the device's. Shaded: dead zone "
                          "(grey) and notch band (amber), as in the time plots. Dotted red: "
                          "±tau_limit. The dot is the "
                          "live knob angle and the measured re-centering torque. With two "
                          "profile slots: A crimson, B olive, the edited one wider. With "
                          "effects, the top curve is the static torque τ_rec + τ_det + τ_wall "
                          "(at rest: no wall damping, no vibration), the dot adds the measured "
                          "τ_fx, gold discs (circles: the device's) mark the detents' rest "
                          "positions and gold lines the walls; the bottom curve stays K_rec."));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    plottheme::follow(m_plot);
    updateComparisonStyle();
    connect(&m_tuning, &TuningModel::editedChanged, this, [this](TuningChange change) {
        if (change.device || change.effects || change.host) // tau_limit is the host's
            rebuild();
    });
    rebuild();
}

void StiffnessView::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange) // the live point's ring follows the theme
        m_point->setScatterStyle(plottheme::livePointStyle(palette()));
}

StiffnessView::~StiffnessView() = default;

void StiffnessView::followTrail(const PlotPanel *panel)
{
    connect(panel, &PlotPanel::repainted, this, [this, panel] { updateTrail(panel); });
}

void StiffnessView::updateTrail(const PlotPanel *panel)
{
    const SampleBuffer *src = panel->shownSource();
    if (!src || src->isEmpty()) {
        if (m_trail->pointCount() > 0) {
            m_trail->clear();
            requestReplot(true);
        }
        return;
    }
    const double end = std::min(src->lastTime(), panel->dataEnd().value_or(src->lastTime()));
    m_trail->setFromBuffer(*src, end - kTrailSeconds, end, Channel::Theta, scale(), Channel::Tau,
                           1.0);
    requestReplot(true);
}

void StiffnessView::setReplaying(bool replaying)
{
    m_replaying = replaying;
    m_deviceTorque->setName(replaying ? tr("recording") : tr("device"));
    m_deviceStiffness->setName(m_deviceTorque->name());
    updateNames();
    requestReplot();
}

bool StiffnessView::effectsShown() const
{
    return shapesStaticTorque(m_tuning.edited().effects) ||
           (m_other && shapesStaticTorque(m_otherEffects)) ||
           (m_device && m_deviceEffects && shapesStaticTorque(*m_deviceEffects));
}

void StiffnessView::updateNames()
{
    // With effects the torques are τ_rec + τ_fx; without, the names are as they always were.
    const bool fx = effectsShown();
    setCornerTitle(m_torqueRect, fx ? tr("static τ [N·m]") : tr("τ_rec [N·m]"));
    if (m_replaying)
        m_point->setName(fx ? tr("playhead (θ, τ_rec + τ_fx)") : tr("at the playhead (θ, τ_rec)"));
    else
        m_point->setName(fx ? tr("live (θ, τ_rec + τ_fx)") : tr("live (θ, measured τ_rec)"));
    QCPGraph *rest = m_editedMarks->restPositions();
    if (rest->visible() && !m_legend->hasItemWithPlottable(rest)) {
        rest->addToLegend(m_legend);
        m_legend->itemWithPlottable(rest)->setMargins(QMargins(2, 1, 2, 3));
    } else if (!rest->visible()) {
        rest->removeFromLegend(m_legend);
    }
}

void StiffnessView::setComparison(const std::optional<DeviceParams> &other, int activeSlot,
                                  const EffectParams &otherEffects)
{
    m_other = other;
    m_otherEffects = otherEffects;
    m_activeSlot = activeSlot == 1 ? 1 : 0;
    updateComparisonStyle();
    rebuild();
}

QCPGraph *StiffnessView::slotTorqueGraph(int slot) const
{
    if (!m_other)
        return nullptr;
    return slot == m_activeSlot ? m_torque : m_otherTorque;
}

QCPGraph *StiffnessView::slotStiffnessGraph(int slot) const
{
    if (!m_other)
        return nullptr;
    return slot == m_activeSlot ? m_stiffness : m_otherStiffness;
}

void StiffnessView::updateComparisonStyle()
{
    // Slot A keeps τ_rec's colour, B has its own; the edited slot's line is the wider one.
    auto colour = [](int slot) { return slot == 0 ? kCurveColour : palette::kSlotB; };
    const QString names[] = {tr("A"), tr("B")};
    const int other = 1 - m_activeSlot;
    const QColor editedColour = m_other ? colour(m_activeSlot) : kCurveColour;
    for (QCPGraph *g : {m_torque, m_stiffness}) {
        g->setPen(QPen(editedColour, 2.0));
        g->setName(m_other ? tr("%1 (edited)").arg(names[m_activeSlot]) : tr("edited"));
    }
    for (QCPGraph *g : {m_otherTorque, m_otherStiffness}) {
        g->setPen(QPen(colour(other), 1.5));
        g->setName(names[other]);
        g->setVisible(m_other.has_value());
    }
    if (m_other && !m_legend->hasItemWithPlottable(m_otherTorque)) {
        m_otherTorque->addToLegend(m_legend);
        // Keep the legend's order: edited, other, device, live.
        for (QCPGraph *g : {m_deviceTorque, m_point}) {
            g->removeFromLegend(m_legend);
            g->addToLegend(m_legend);
        }
    } else if (!m_other) {
        m_otherTorque->removeFromLegend(m_legend);
    }
}

double StiffnessView::halfRange(const DeviceParams &params)
{
    const double r = std::max(2.5 * params.N, 0.5);
    return std::isfinite(r) ? std::min(r, kPi / 2) : kPi / 2;
}

double StiffnessView::halfRange(const DeviceParams &params, const EffectParams &effects)
{
    return std::max(halfRange(params), effectsHalfRange(effects));
}

QVector<double> StiffnessView::sampleAngles(const DeviceParams &p, double center, double halfWidth,
                                            const EffectParams &effects)
{
    return staticCurveAngles(p, center, halfWidth, effects, kUniformSamples);
}

void StiffnessView::setDeviceTuning(const DeviceTuning &device)
{
    m_device = device.params;
    m_deviceEffects = device.effects;
    rebuild();
}

void StiffnessView::setOperatingPoint(double theta, double tauRec)
{
    m_operatingPoint = std::make_pair(theta, tauRec);
    updateOperatingPoint();
    requestReplot(true);
}

void StiffnessView::clearOperatingPoint()
{
    m_operatingPoint.reset();
    updateOperatingPoint();
    requestReplot(true);
}

void StiffnessView::setAngleInDegrees(bool degrees)
{
    if (degrees == m_degrees)
        return;
    m_degrees = degrees;
    rebuild();
}

double StiffnessView::scale() const
{
    return m_degrees ? 180.0 / kPi : 1.0;
}

void StiffnessView::fillCurves(const DeviceParams &params, const EffectParams &effects,
                               QCPGraph *torque, QCPGraph *stiffness, double center,
                               double halfWidth)
{
    const QVector<double> angles = sampleAngles(params, center, halfWidth, effects);
    QVector<double> keys, tau, k;
    keys.reserve(angles.size());
    tau.reserve(angles.size());
    k.reserve(angles.size());
    for (double theta : angles) {
        keys << theta * scale();
        tau << staticTorque(params, effects, theta); // τ_rec exactly with default effects
        k << recenteringStiffness(params, theta);
    }
    torque->setData(keys, tau, true);
    stiffness->setData(keys, k, true);
}

void StiffnessView::rebuild()
{
    const Tuning &edited = m_tuning.edited();
    const double tauLimit = edited.host.tau_limit; // drawn ±, and the axis's reach
    const double center = edited.device.theta0;
    const EffectParams deviceEffects = m_deviceEffects.value_or(EffectParams{});
    double half = halfRange(edited.device, edited.effects);
    if (m_other)
        half = std::max(half, halfRange(*m_other, m_otherEffects));
    if (m_device) // the device's effects in sight too (its curve alone keeps the edited range)
        half = std::max(half, std::min(effectsHalfRange(deviceEffects), kPi));
    fillCurves(edited.device, edited.effects, m_torque, m_stiffness, center, half);
    if (m_other) {
        fillCurves(*m_other, m_otherEffects, m_otherTorque, m_otherStiffness, center, half);
    } else {
        m_otherTorque->data()->clear();
        m_otherStiffness->data()->clear();
    }
    if (m_device) {
        fillCurves(*m_device, deviceEffects, m_deviceTorque, m_deviceStiffness, center, half);
    } else {
        m_deviceTorque->data()->clear();
        m_deviceStiffness->data()->clear();
    }
    m_deviceTorque->setVisible(m_device.has_value());
    m_deviceStiffness->setVisible(m_device.has_value());

    const QString unit = m_degrees ? tr("θ [°]") : tr("θ [rad]");
    for (QCPAxisRect *rect : {m_torqueRect, m_stiffnessRect})
        rect->axis(QCPAxis::atBottom)
            ->setRange((center - half) * scale(), (center + half) * scale());
    m_stiffnessRect->axis(QCPAxis::atBottom)->setLabel(unit); // the one θ axis with numbers

    // Symmetric torque range; ±tau_limit shows when it is within reach of the curves.
    double tauMax = 0;
    double kMax = 0;
    for (QCPGraph *g : {m_torque, m_deviceTorque, m_otherTorque}) {
        for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
            if (std::isfinite(it->value))
                tauMax = std::max(tauMax, std::abs(it->value));
        }
    }
    for (QCPGraph *g : {m_stiffness, m_deviceStiffness, m_otherStiffness}) {
        for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
            if (std::isfinite(it->value))
                kMax = std::max(kMax, it->value);
        }
    }
    if (tauLimit > 0 && tauLimit < 2.0 * tauMax)
        tauMax = std::max(tauMax, tauLimit);
    tauMax = std::max(tauMax, 1e-3) * 1.15;
    // A stiff wall's spring grows far beyond what the device renders (it clamps at tau_limit):
    // with effects the axis stops at 1.5 × tau_limit, so the notch and the detents stay legible.
    if (tauLimit > 0 && effectsShown())
        tauMax = std::min(tauMax, 1.5 * tauLimit);
    m_torqueRect->axis(QCPAxis::atLeft)->setRange(-tauMax, tauMax);
    m_stiffnessRect->axis(QCPAxis::atLeft)->setRange(0, std::max(kMax, 1e-3) * 1.15);

    m_limitHigh->point1->setCoords(0, tauLimit);
    m_limitHigh->point2->setCoords(1, tauLimit);
    m_limitLow->point1->setCoords(0, -tauLimit);
    m_limitLow->point2->setCoords(1, -tauLimit);
    m_limitHigh->setVisible(tauLimit > 0);
    m_limitLow->setVisible(tauLimit > 0);

    m_editedMarks->update(edited.device, edited.effects, center - half, center + half, scale());
    m_deviceMarks->update(m_device.value_or(DeviceParams{}),
                          m_device ? m_deviceEffects : std::nullopt, center - half, center + half,
                          scale());
    updateNames();
    updateShading();
    updateOperatingPoint();
    requestReplot();
}

void StiffnessView::updateShading()
{
    const DeviceParams &edited = m_tuning.edited().device;
    const double c = edited.theta0;
    const double bands[] = {edited.N, edited.Q_dz}; // notch band below the dead zone
    for (int i = 0; i < 4; ++i) {
        const double w = bands[i % 2];
        m_shades[i]->topLeft->setCoords((c - w) * scale(), 0);
        m_shades[i]->bottomRight->setCoords((c + w) * scale(), 1);
        m_shades[i]->setVisible(std::isfinite(w) && w > 0);
    }
}

void StiffnessView::updateOperatingPoint()
{
    if (!m_operatingPoint) {
        m_point->data()->clear();
        m_cursor->setVisible(false);
        // The live point moves with every batch of samples; on a buffered layer of its own it is
        // redrawn alone, over the curves, axes and legend drawn before.
        m_plot->layer(u"overlay"_s)->setMode(QCPLayer::lmBuffered);
        m_point->setLayer(u"overlay"_s);
        m_cursor->setLayer(u"overlay"_s);
        return;
    }
    const double x = m_operatingPoint->first * scale();
    m_point->setData(QVector<double>{x}, QVector<double>{m_operatingPoint->second}, true);
    m_cursor->point1->setCoords(x, 0);
    m_cursor->point2->setCoords(x, 1);
    m_cursor->setVisible(true);
}

void StiffnessView::requestReplot(bool pointOnly)
{
    if (!pointOnly)
        m_fullReplot = true;
    if (!m_replotTimer->isActive())
        m_replotTimer->start();
}

} // namespace hatpic
