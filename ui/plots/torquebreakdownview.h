// The torque breakdown: the terms of the admittance filter's balance (model/torquebreakdown.h)
// over the time plots' visible range, each on one torque axis — the inertial term D_adm·ω̇,
// the damping term M_adm·ω, the operator's τ_op = −τ, τ_rec, τ_ext and the amount the
// tau_limit clamp removed — with the saturated samples shaded.
//
// It follows a PlotPanel: what it shows (live, paused or replayed), its time range, and the
// parameters D_adm and M_adm (the device's live, the recording's in replay). ω̇ is estimated
// by the forward difference of ω to the next sample (model/torquebreakdown.h).
#pragma once

#include <QWidget>

#include <array>

class QCPGraph;
class QCustomPlot;
class QLabel;

namespace hatpic {

class PlotPanel;

class TorqueBreakdownView : public QWidget
{
    Q_OBJECT
public:
    enum class Term { Inertial, Damping, TauOp, TauRec, TauExt, TauFx, Clipped };
    static constexpr int kTermCount = 7;

    //! Follows `panel` (not owned), refreshing after each of its repaints while visible.
    explicit TorqueBreakdownView(PlotPanel *panel, QWidget *parent = nullptr);

    //! Recomputes the terms from what the panel shows, over its visible range.
    void refresh();

    //! "D_adm·ω̇", "τ_op = −τ", … (short: the legend sits in three columns above the plot;
    //! the tooltip says D_adm·ω̇ is the inertial term and M_adm·ω the damping term)
    static QString termLabel(Term term);

    QCustomPlot *plot() const { return m_plot; }
    QCPGraph *graph(Term term) const { return m_graphs[static_cast<int>(term)]; }
    //! 1 over saturated samples, 0 elsewhere (a filled step graph on a hidden axis).
    QCPGraph *saturationGraph() const { return m_saturation; }
    //! Why the inertial and damping terms are missing, or empty.
    QString notice() const;

private:
    PlotPanel *m_panel;
    QCustomPlot *m_plot = nullptr;
    QLabel *m_notice = nullptr;
    std::array<QCPGraph *, kTermCount> m_graphs{};
    QCPGraph *m_saturation = nullptr;
};

} // namespace hatpic
