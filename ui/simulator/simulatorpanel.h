// The operator's hand on the simulated joystick: choose an input (idle, constant, step, sine,
// chirp, virtual hand) and its parameters; every change emits the new HandInput.
#pragma once

#include "sim/handinput.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace hatpic {

class SimulatorPanel : public QWidget
{
    Q_OBJECT
public:
    static constexpr double kMaxTorque = 2.0;   //!< spin box range ±, [N·m]
    static constexpr double kMaxFrequency = 50; //!< [Hz]
    static constexpr int kAngleTicksPerRad = 1000;

    explicit SimulatorPanel(QWidget *parent = nullptr);

    //! The current input; fields the kind does not use are 0.
    HandInput hand() const;
    //! Shows an input without emitting handChanged().
    void setHand(const HandInput &hand);

    //! The operator input the simulator starts with: a slow sine that crosses the notch.
    static HandInput gentleHand();
    //! Chooses `hand` as the user's (as if picked here), without emitting handChanged().
    void chooseHand(const HandInput &hand);
    //! Whether the user has picked a hand (here or through chooseHand()).
    bool isHandChosen() const { return m_chosen; }
    //! The hand a newly connected simulator gets, and shows it: the user's choice, else the
    //! requested one, else (idle requested) gentleHand().
    HandInput handToStartWith(const HandInput &requested);

    //! The input in words for the status bar: "Hand: sine 0.06 N·m at 0.2 Hz".
    static QString describe(const HandInput &hand);
    //! A label that always says the active input (object name "handStatus"), for the window's
    //! status bar.
    QLabel *statusLabel() const { return m_status; }

    //! While an experiment runs the simulated hand is idle (ExperimentRunner lets go of it and
    //! gives it back afterwards): the panel and the status label say so, and the input cannot
    //! be changed until it ends.
    void setHeldByExperiment(bool held);
    bool isHeldByExperiment() const { return m_held; }

Q_SIGNALS:
    void handChanged(const hatpic::HandInput &hand);

private:
    void updateVisibility();
    void emitIfChanged();

    HandInput m_last;
    bool m_chosen = false;
    bool m_held = false;
    QWidget *m_inputs = nullptr; //!< the kind, its fields and Let go
    QComboBox *m_kind = nullptr;
    QLabel *m_description = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_amplitudeLabel = nullptr;
    QDoubleSpinBox *m_amplitude = nullptr;
    QLabel *m_offsetLabel = nullptr;
    QDoubleSpinBox *m_offset = nullptr;
    QLabel *m_frequencyLabel = nullptr;
    QDoubleSpinBox *m_frequency = nullptr;
    QLabel *m_frequency1Label = nullptr;
    QDoubleSpinBox *m_frequency1 = nullptr;
    QLabel *m_angleLabel = nullptr;
    QDoubleSpinBox *m_angle = nullptr;
    QSlider *m_angleSlider = nullptr;
    QLabel *m_angleDegrees = nullptr;
    QLabel *m_pushesLabel = nullptr;
    QSpinBox *m_pushes = nullptr;
    QLabel *m_pushTimeLabel = nullptr;
    QDoubleSpinBox *m_pushTime = nullptr;
    QLabel *m_releaseTimeLabel = nullptr;
    QDoubleSpinBox *m_releaseTime = nullptr;
};

} // namespace hatpic
