// Figures that follow from the edited parameters (model.md § 3): ω_n, ζ, time constant and
// the peak re-centering torque against the actuator limit, with saturation/ringing warnings.
#pragma once

#include "model/derived.h"

#include <QWidget>

#include <optional>

class QLabel;
class QProgressBar;
class QScrollArea;

namespace hatpic {

class DerivedFiguresView : public QWidget
{
    Q_OBJECT
public:
    explicit DerivedFiguresView(QWidget *parent = nullptr);

    //! Shows the figures; `valid` false shows dashes (figures of an invalid set mean nothing).
    void setFigures(const DerivedFigures &figures, bool valid);
    void setAngleInDegrees(bool degrees);

    const DerivedFigures &figures() const { return m_figures; }
    bool isShowingSaturation() const; //!< the saturation warning is visible
    bool isShowingRinging() const;    //!< the ringing warning is visible
    //! Chatter seen in the telemetry (chatterdetector.h): its frequency [Hz] and the jump
    //! K_max·Q_dz [N·m] of the device's parameters; nullopt hides the warning.
    void setChatter(std::optional<double> frequency, double jump);
    bool isShowingChatter() const;
    QString warningText() const; //!< all warnings shown, one per line

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();
    void showWarnings(); //!< the warnings' area only while one shows, sized to them
    void applyPalette(); //!< the warnings' look from the current palette

    DerivedFigures m_figures;
    bool m_valid = false;
    bool m_degrees = false;
    QLabel *m_omega = nullptr;
    QLabel *m_zeta = nullptr;
    QLabel *m_timeConstant = nullptr;
    QLabel *m_peak = nullptr;
    QProgressBar *m_peakBar = nullptr;
    QLabel *m_peakPercent = nullptr; //!< "54 % of tau_limit", beside the bar
    QLabel *m_saturation = nullptr;
    QLabel *m_ringing = nullptr;
    QLabel *m_chatter = nullptr;
    QScrollArea *m_warnings = nullptr; //!< the three warnings, scrolling when the editor is short
};

} // namespace hatpic
