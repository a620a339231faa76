// The stability map in the Experiments panel (docs/experiments.md § Stability map): the
// teleoperation loop of robot.md run in process for the tuning being edited over a grid of
// one-way delays × feedback gains (× hands, each making one or more contacts), the passivity
// controller off and as edited, drawn as
// `hatpicctl teleop-map` draws it (teleop/stabilitymap.h) with the settings in use marked.
// The cells run on threads of their own; the GUI thread only starts, cancels and shows.
#pragma once

#include "teleop/stabilitymap.h"

#include <QWidget>

#include <atomic>
#include <memory>
#include <thread>
#include <vector>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QSvgWidget;

namespace hatpic {

class TuningModel;

class StabilityMapView : public QWidget
{
    Q_OBJECT
public:
    //! Maps `tuning`'s edited tuning: the next map runs it; an edit marks a map on screen
    //! stale. With pc_damping_max > 0 the map shows the passivity controller off and on side
    //! by side, else one map with it off.
    explicit StabilityMapView(const TuningModel &tuning, QWidget *parent = nullptr);
    ~StabilityMapView() override; //!< cancels a map being computed and waits for its threads

    //! The map the form describes for the tuning, or the reason it cannot run.
    teleop::MapSpec spec(QString *error = nullptr) const;
    //! Starts computing; false with the reason in the status line.
    bool compute();
    void cancel();
    bool computing() const { return m_worker.joinable() && !m_done; }

    const std::vector<teleop::MapCell> &cells() const { return m_cells; }
    //! The chart on screen (SVG), empty before the first map.
    const QByteArray &svg() const { return m_svg; }
    QString status() const;

Q_SIGNALS:
    void finished(); //!< a map arrived (or was cancelled)

private:
    void onProgress(qsizetype done, qsizetype total);
    void onFinished(quint64 generation, std::vector<teleop::MapCell> cells);
    //! The chart for the cells on screen with the settings in use marked.
    void redraw();
    void updateButtons();
    void joinWorker();

    const TuningModel &m_tuning;

    QLineEdit *m_delays{}, *m_gains{}, *m_hands{};
    QSpinBox *m_contacts{};
    QDoubleSpinBox *m_duration{}, *m_delayInUse{}, *m_gainInUse{};
    QPushButton *m_compute{}, *m_cancel{};
    QProgressBar *m_progress{};
    QLabel *m_status{};
    QSvgWidget *m_chart{};

    std::vector<teleop::MapCell> m_cells;
    teleop::MapSpec m_shown; //!< the spec of the cells on screen
    QByteArray m_svg;
    std::thread m_worker;
    std::atomic<bool> m_cancelled{false};
    std::atomic<bool> m_done{true};
    quint64 m_generation = 0; //!< the map being computed; older ones' results are dropped
};

} // namespace hatpic
