// Chatter at the dead-zone edge, detected from telemetry (model.md § 2, "Chatter"): the
// re-centering torque jumps from 0 to K_max·Q_dz at |θ−θ0| = Q_dz, and a hand that holds the
// knob there with less torque than the jump makes it cross the edge back and forth, the
// torque flipping by the whole jump each time: a buzz. How fast depends on the servo's loop
// and on the hand, which the tuner cannot know, so it counts the crossings instead.
//
// ChatterWatch feeds the live samples of the knob the editor tunes to a detector, against that
// knob's tuning as the window's TuningModel holds it (no copy), and shows what it finds in the
// editor's derived figures.
#pragma once

#include "model/params.h"
#include "telemetry/sample.h"

#include <QObject>

#include <deque>
#include <optional>

namespace hatpic {

class ParameterEditor;

class ChatterDetector
{
public:
    static constexpr double kWindow = 1.0;   //!< crossings are counted over the last second [s]
    static constexpr int kMinCrossings = 16; //!< 8 back-and-forths a second is chatter

    //! The edge to watch: ±Q_dz around θ0; nullopt or Q_dz = 0 (no jump) watches nothing.
    //! Counting starts again.
    void setParams(const std::optional<DeviceParams> &params);
    //! Whether `params` put the edge where it is watched now.
    bool watchesEdgeOf(const std::optional<DeviceParams> &params) const;
    void add(const Sample &sample);
    //! Back-and-forths per second at the edge over the last window [Hz] while they are chatter.
    std::optional<double> frequency() const;

private:
    void restart(); //!< forgets the crossings counted

    double m_theta0 = 0;
    double m_qdz = 0;
    std::optional<bool> m_outside;  //!< the last sample's side of the edge
    double m_last = 0;              //!< the last sample's time [s]
    std::deque<double> m_crossings; //!< times within the window; ≤ one per sample
};

class ChatterWatch : public QObject
{
    Q_OBJECT
public:
    explicit ChatterWatch(ParameterEditor *editor);
    void addSamples(const SampleBatch &batch);

private:
    ParameterEditor *m_editor;
    ChatterDetector m_detector;
};

} // namespace hatpic
