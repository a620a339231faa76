// The Experiments panel (docs/experiments.md): choose a step, a frequency response or a
// spectrum and its parameters, run it on the connected device (Run / Cancel), and read the
// measured figures next to the model's derived ones, with the plots (ExperimentPlots). The
// spectrum of the main plots' visible window is one button away. Results export as CSV and
// as PNG or SVG.
#pragma once

#include "experiment/experimentresult.h"

#include <QSet>
#include <QWidget>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QSplitter;
class QTableWidget;

namespace hatpic {

class DeviceClient;
class ExperimentPlots;
class ExperimentRunner;
class PlotPanel;
class SimulatedJoystick;

class ExperimentsPanel : public QWidget
{
    Q_OBJECT
public:
    //! Narrowest the plots get beside the figures; narrower, the figures are one of their tabs.
    static constexpr int kMinPlotWidth = 320;

    //! `simulator`: the simulated joystick the client connects through, if any (its hand is idle
    //! for a run); `plots` (may be null) gives the visible window for the spectrum button.
    ExperimentsPanel(DeviceClient *client, SimulatedJoystick *simulator, PlotPanel *plots,
                     QWidget *parent = nullptr);
    ~ExperimentsPanel() override;

    //! The plan the form describes.
    ExperimentPlan plan() const;
    //! Fills the form with the defaults for the chosen kind and the device's parameters
    //! (the Defaults button): the fields the user typed too.
    void fillDefaults();
    //! True when the user changed `field` since the last fillDefaults(): the device's new
    //! tuning then leaves it as typed.
    bool typed(const QWidget *field) const;
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
    //! A run started (true) or ended (false); on the simulator its hand is idle meanwhile.
    void runningChanged(bool running);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void buildForm();
    //! The figures beside the plots, or behind a tab when the panel is narrow.
    void placeFigures();
    void onKindChanged();
    //! The defaults for the device's parameters into the fields the user has not typed.
    void refreshDefaults();
    void onFinished(const ExperimentResult &result);
    void showFigures(const ExperimentResult &result);
    //! The result's main figures next to the model's, in one sentence.
    static QString headline(const ExperimentResult &result);
    void updateButtons();
    ExperimentKind currentKind() const;
    //! `text`, then "Caution: …" on a line of its own when `cautions` has any.
    static QString withCaution(const QString &text, const QStringList &cautions);
    //! Before a run: what to do with the hand, for the connected device.
    void showReadyHint();
    void saveCsvAs();
    void saveImageAs();

    DeviceClient *m_client;
    PlotPanel *m_mainPlots;
    ExperimentRunner *m_runner;
    std::optional<ExperimentResult> m_result;

    // The form (its levels, frequencies, periods and times), the buttons, the results.
    QComboBox *m_kind{};
    QFormLayout *m_form{}; //!< the kind's fields (the others' rows hidden)
    QDoubleSpinBox *m_from{}, *m_to{}, *m_offset{}, *m_amplitude{}, *m_settle{}, *m_duration{};
    QLineEdit *m_frequencies{};
    QSpinBox *m_cycles{};
    QPushButton *m_defaults{}, *m_run{}, *m_cancel{}, *m_visible{}, *m_csv{}, *m_image{};
    QProgressBar *m_progress{};
    QLabel *m_status{};
    QTableWidget *m_figures{};
    QWidget *m_results{}; //!< the figures and their export buttons
    QSplitter *m_split{}; //!< controls | plots [| results]
    ExperimentPlots *m_plots{};
    QSet<const QWidget *> m_typed; //!< fields the user changed since the last Defaults
    bool m_filling = false;        //!< the panel, not the user, is setting the fields
};

} // namespace hatpic
