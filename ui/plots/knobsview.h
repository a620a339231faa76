// The knobs of a board with several (the published IMU branch's four) and its tilt, drawn live:
// one dial per knob with its angle, and a horizon tilted by the board's roll and pitch. A single
// knob's plots already show everything, so the window shows this only for such a board
// (docs/user-guide.md § Several knobs).
#pragma once

#include "plots/displayunits.h"
#include "telemetry/sample.h"

#include <QWidget>

#include <optional>

namespace hatpic {

class KnobsView : public QWidget
{
    Q_OBJECT
public:
    explicit KnobsView(QWidget *parent = nullptr);

    //! The newest sample of `batch` is drawn (at the next repaint).
    void showSamples(const SampleBatch &batch);
    //! Nothing to show: the device went away.
    void clear();
    void setUnits(const DisplayUnits &units);

    //! Knobs drawn (0 before a sample), and whether the tilt is.
    int knobs() const;
    bool showsTilt() const;
    //! θ of knob n (1 …) as drawn [rad]; NaN when there is no such knob.
    double knobAngle(int n) const;
    //! What is drawn, as text: "Knob 1: 0.12 rad; …; roll 0.30 rad, pitch −0.20 rad".
    QString text() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    std::optional<Sample> m_sample;
    DisplayUnits m_units;
};

} // namespace hatpic
