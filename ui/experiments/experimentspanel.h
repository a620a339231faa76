// The Experiments panel (docs/experiments.md): choose a step, a frequency response or a
// spectrum and its parameters, run it on the connected device (Run / Cancel), and read the
// measured figures next to the model's derived ones, with the plots (ExperimentPlots). The
// spectrum of the main plots' visible window is one button away. Results export as CSV and
// as PNG or SVG.
#pragma once

#include "experiment/experimentresult.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace hatpic {

class DeviceClient;
class ExperimentPlots;
class ExperimentRunner;
class PlotPanel;

class ExperimentsPanel : public QWidget
{
    Q_OBJECT
public:
    //! `plots` (may be null) gives the visible window for the spectrum button.
    ExperimentsPanel(DeviceClient *client, PlotPanel *plots, QWidget *parent = nullptr);
    ~ExperimentsPanel() override;

    //! The plan the form describes.
    ExperimentPlan plan() const;
    //! Fills the form with the defaults for the chosen kind and the device's parameters.
    void fillDefaults();
    //! Starts the plan; false with the reason in the status line.
    bool run();
    void cancel();
    bool running() const;

    const std::optional<ExperimentResult> &result() const { return m_result; }
    //! Writes the last result's curves (experimentCsv); false with `error` set.
    bool exportCsv(const QString &path, QString *error = nullptr) const;
    bool exportImage(const QString &path, QString *error = nullptr) const;
    //! The spectra of θ and τ over the main plots' visible window.
    void showVisibleSpectrum();

    ExperimentPlots *plots() const { return m_plots; }
    QTableWidget *figures() const { return m_figures; }
    QString status() const;

Q_SIGNALS:
    void finished(const hatpic::ExperimentResult &result);

private:
    void buildForm();
    void onKindChanged();
    void onFinished(const ExperimentResult &result);
    void showFigures(const ExperimentResult &result);
    void updateButtons();
    void saveCsvAs();
    void saveImageAs();

    DeviceClient *m_client;
    PlotPanel *m_mainPlots;
    ExperimentRunner *m_runner;
    std::optional<ExperimentResult> m_result;

    // The form (its levels, frequencies, periods and times), the buttons, the results.
    QComboBox *m_kind{};
    QDoubleSpinBox *m_from{}, *m_to{}, *m_offset{}, *m_amplitude{}, *m_settle{}, *m_duration{};
    QLineEdit *m_frequencies{};
    QSpinBox *m_cycles{};
    QPushButton *m_defaults{}, *m_run{}, *m_cancel{}, *m_visible{}, *m_csv{}, *m_image{};
    QProgressBar *m_progress{};
    QLabel *m_status{};
    QTableWidget *m_figures{};
    ExperimentPlots *m_plots{};
};

} // namespace hatpic
