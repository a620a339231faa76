// The Bridge panel's "Passivity at the knob" section (teleop.md § The passivity observer): the
// energy the feedback path has put into the knob, E = ∫ τ_ext·ω dt, as a number and a plot of
// the last kSpan seconds, and a warning — saying what to do — while the loop generates energy
// in contact; above it, the device's passivity controller (passivity.md): idle or damping, how
// hard, what it took out and its reserve. It only shows what the bridge's observer
// (core/analysis) computed.
#pragma once

#include "bridge/bridge.h"

#include <QGroupBox>
#include <QList>

class QCPGraph;
class QCustomPlot;
class QLabel;

namespace hatpic {

class PassivityView : public QGroupBox
{
    Q_OBJECT
public:
    static constexpr double kSpan = 30; //!< the plot's time span [s]

    explicit PassivityView(QWidget *parent = nullptr);

    //! The observer's state now (a point on the plot when its time moved on).
    void setState(const analysis::PassivityObserver::State &state,
                  const analysis::PassivitySettings &settings = {});
    //! Forgets the plotted history (the bridge started again: E is 0 again).
    void clear();
    bool isWarning() const; //!< the warning is shown
    //! The readout and the warning (when shown) as text.
    QString text() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void applyPalette();

    QLabel *m_controller = nullptr;
    QLabel *m_energy = nullptr;
    QLabel *m_warning = nullptr;
    QCustomPlot *m_plot = nullptr;
    QCPGraph *m_graph = nullptr;
    QList<double> m_times;    //!< the observer's sample times [s]
    QList<double> m_energies; //!< E at those times [J]
};

} // namespace hatpic
