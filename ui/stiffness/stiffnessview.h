// The static torque τ_rec + τ_det + τ_wall (ω = 0) and K_rec over θ of the edited parameters
// and effects (solid) and of the device's (dashed), with the detents' rest positions and the
// walls marked, and the live operating point (θ, measured τ_rec + τ_fx): the dead zone, the
// notch, the slopes and the effects being tuned. With the default effects (which render
// nothing) the curves are τ_rec(θ) and K_rec(θ) alone.
#pragma once

#include "model/devicetuning.h"

#include <QVector>
#include <QWidget>

#include <memory>
#include <optional>

class QCPAxisRect;
class QCPGraph;
class QCPItemRect;
class QCPItemStraightLine;
class QCPLegend;
class QCustomPlot;
class QTimer;

namespace hatpic {

class EffectMarks;
class FadingTrail;
class PlotPanel;
class TuningModel;

class StiffnessView : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kUniformSamples = 601;   //!< evenly spaced samples per curve
    static constexpr int kRepaintIntervalMs = 33; //!< the live point repaints at ≤ 30 Hz

    static constexpr double kTrailSeconds = 3; //!< length of the operating point's trail [s]

    //! Draws `tuning`'s edited parameters and effects with ±tau_limit (the edited host
    //! setting's), and follows its edits.
    explicit StiffnessView(const TuningModel &tuning, QWidget *parent = nullptr);
    ~StiffnessView() override;

    //! The device's tuning, drawn dashed: its parameters (absent: hidden) with its effect block
    //! (absent: a device without the effects capability, drawn without effects).
    void setDeviceTuning(const DeviceTuning &device);
    //! Live operating point: knob angle [rad] and the measured static torque τ_rec + τ_fx
    //! (τ_rec alone where the device does not send τ_fx) [N·m].
    void setOperatingPoint(double theta, double tauRec);
    void clearOperatingPoint();
    //! Display only: the θ axis in degrees; the inputs stay SI.
    void setAngleInDegrees(bool degrees);
    bool angleInDegrees() const { return m_degrees; }
    //! In replay the dashed curve is the recording's parameters and the dot the sample at the
    //! playhead: the legend says so instead of "device" and "live".
    void setReplaying(bool replaying);
    //! A/B comparison: the other slot's parameters, drawn beside the edited (active) slot's;
    //! each slot in its own colour (A: τ_rec's crimson, B: palette::kSlotB), labelled "A" and
    //! "B". nullopt hides them (and the edited curve is "edited" again). `otherEffects` are the
    //! other slot's effects, part of its static torque curve.
    void setComparison(const std::optional<DeviceParams> &other, int activeSlot,
                       const EffectParams &otherEffects = EffectParams{});
    //! The τ_rec(θ) / K_rec(θ) curve of slot 0 (A) or 1 (B) while compared, else nullptr.
    QCPGraph *slotTorqueGraph(int slot) const;
    QCPGraph *slotStiffnessGraph(int slot) const;
    //! Draws the trail of (θ, measured τ) over the last kTrailSeconds of what `panel` shows
    //! (live, paused or replayed), older points fainter, after each of its repaints. τ lies on
    //! τ_rec(θ) at rest and leaves it with the admittance's inertia and damping, so loops show
    //! hysteresis and back-and-forth jumps at the dead-zone edge show chatter.
    void followTrail(const PlotPanel *panel);
    const FadingTrail *trail() const { return m_trail.get(); }

    //! Half-width of the shown θ range around θ0: max(2.5·N, 0.5) rad, at most π/2 [rad].
    static double halfRange(const DeviceParams &params);
    //! halfRange(params), widened to show the effects (effectsHalfRange), at most π [rad].
    static double halfRange(const DeviceParams &params, const EffectParams &effects);
    //! Sorted sample angles [rad] over center ± halfWidth: an even grid plus every breakpoint
    //! of `params` (θ0 ± Q_dz, ± N, ± 2N) and, at ±Q_dz, the last angle inside the dead zone,
    //! so the jump to K_max is drawn vertical; with `effects`, also the angles that resolve
    //! every detent and mark the detent range's edges and the walls (effectSampleAngles).
    static QVector<double> sampleAngles(const DeviceParams &params, double center, double halfWidth,
                                        const EffectParams &effects = EffectParams{});

    QCustomPlot *plot() const { return m_plot; }
    QCPGraph *torqueGraph() const { return m_torque; }
    QCPGraph *stiffnessGraph() const { return m_stiffness; }
    QCPGraph *deviceTorqueGraph() const { return m_deviceTorque; }
    QCPGraph *deviceStiffnessGraph() const { return m_deviceStiffness; }
    QCPGraph *operatingPointGraph() const { return m_point; }
    //! The edited set's and the device's detent rest positions and walls.
    const EffectMarks &editedMarks() const { return *m_editedMarks; }
    const EffectMarks &deviceMarks() const { return *m_deviceMarks; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void rebuild();
    void fillCurves(const DeviceParams &params, const EffectParams &effects, QCPGraph *torque,
                    QCPGraph *stiffness, double center, double halfWidth);
    //! Names the torque axis and the live point after what the curves hold.
    void updateNames();
    //! Some drawn set's effects change its static torque (the defaults do not).
    bool effectsShown() const;
    void updateShading();
    void updateComparisonStyle();
    void updateOperatingPoint();
    void updateTrail(const PlotPanel *panel);
    //! Replots within kRepaintIntervalMs: everything, or (`pointOnly`) just the live point's
    //! layer when nothing else changed since the last replot.
    void requestReplot(bool pointOnly = false);
    double scale() const;

    const TuningModel &m_tuning;
    std::optional<DeviceParams> m_device; //!< the device's tuning, as setDeviceTuning() gave it
    std::optional<DeviceParams> m_other;  //!< the other A/B slot, when compared
    std::optional<EffectParams> m_deviceEffects;
    EffectParams m_otherEffects;
    bool m_replaying = false;
    int m_activeSlot = 0;
    std::optional<std::pair<double, double>> m_operatingPoint; //!< θ [rad], τ_rec [N·m]
    bool m_degrees = false;

    QCustomPlot *m_plot = nullptr;
    QCPAxisRect *m_torqueRect = nullptr;
    QCPAxisRect *m_stiffnessRect = nullptr;
    QCPGraph *m_torque = nullptr;
    QCPGraph *m_stiffness = nullptr;
    QCPGraph *m_deviceTorque = nullptr;
    QCPGraph *m_deviceStiffness = nullptr;
    QCPGraph *m_point = nullptr;
    QCPGraph *m_otherTorque = nullptr;
    QCPGraph *m_otherStiffness = nullptr;
    QCPLegend *m_legend = nullptr;
    std::unique_ptr<FadingTrail> m_trail;
    std::unique_ptr<EffectMarks> m_editedMarks;
    std::unique_ptr<EffectMarks> m_deviceMarks;
    QCPItemStraightLine *m_cursor = nullptr;
    QCPItemStraightLine *m_limitHigh = nullptr;
    QCPItemStraightLine *m_limitLow = nullptr;
    QCPItemRect *m_shades[4] = {}; //!< notch and dead zone, in each of the two plots
    QTimer *m_replotTimer = nullptr;
    bool m_fullReplot = true; //!< something besides the live point changed
};

} // namespace hatpic
