// The Experiments panel's plots, one tab each: the step (measured θ with the ideal model's
// overlaid, aligned at the step), the Bode plot (magnitude and phase of θ/τ_ext over a
// logarithmic frequency axis, measured points against the model's curve) and the spectra of θ
// and τ (dB). Angles in the step plot follow the window's degrees setting.
#pragma once

#include "analysis/spectrum.h"
#include "experiment/experimentresult.h"

#include <QTabWidget>

class QCustomPlot;

namespace hatpic {

class ExperimentPlots : public QTabWidget
{
    Q_OBJECT
public:
    enum Tab { StepTab, BodeTab, SpectrumTab };

    explicit ExperimentPlots(QWidget *parent = nullptr);

    //! Draws `result` in its tab and shows that tab.
    void showResult(const ExperimentResult &result);
    //! Draws spectra of θ [rad] and τ [N·m] in the spectrum tab; `title` says of what.
    void showSpectra(const analysis::Spectrum &theta, const analysis::Spectrum &tau,
                     const QString &title);

    QCustomPlot *plot(Tab tab) const;
    //! Saves the shown tab's plot: SVG for a ".svg" path, else PNG. False with `error` set.
    bool exportImage(const QString &path, QString *error = nullptr) const;

private:
    void showStep(const ExperimentResult &result);
    void showBode(const ExperimentResult &result);

    QCustomPlot *m_step = nullptr;
    QCustomPlot *m_bode = nullptr;
    QCustomPlot *m_spectrum = nullptr;
};

} // namespace hatpic
