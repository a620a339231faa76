// Offline response of the simulated joystick to a hand input: one Sample per control step,
// as fast as the CPU allows (no link, no clock). Used by `hatpicctl simulate`.
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "model/reference.h"
#include "sim/handinput.h"
#include "telemetry/sample.h"

#include <QByteArray>
#include <QString>
#include <QtGlobal>

#include <memory>

namespace hatpic {

class SimulatedDevice;

struct OfflineSimulationConfig
{
    DeviceParams device;   //!< rendered parameters
    EffectParams effects;  //!< rendered effects (effects.md); the defaults render nothing
    HostParams host;       //!< tau_limit and the reference model settings
    HandInput hand;        //!< the operator's torque on the knob
    double rateHz = 1000;  //!< control rate: one row per step [Hz]
    double duration = 2.0; //!< simulated time; rows at t = 0 … duration inclusive [s]
    bool ideal = false;    //!< model.md alone: no servo lag, quantisation or noise
    double noise = 0;      //!< std-dev of the load-reading noise, when not ideal [N·m]
    quint64 seed = 1;      //!< noise seed
};

class OfflineSimulation
{
public:
    static constexpr qint64 kMaxRows = 10'000'000;

    //! Empty when the configuration can run; otherwise one sentence naming the problem.
    static QString check(const OfflineSimulationConfig &config);

    //! `config` must pass check().
    explicit OfflineSimulation(const OfflineSimulationConfig &config);
    ~OfflineSimulation();
    OfflineSimulation(const OfflineSimulation &) = delete;
    OfflineSimulation &operator=(const OfflineSimulation &) = delete;

    //! Rows in the whole run: floor(duration·rate) + 1.
    qint64 rowCount() const { return m_rows; }
    //! True after the last row, and at once after a row that failed().
    bool atEnd() const { return m_done >= m_rows || m_failed; }
    //! The next control step. The first is t = 0 with θ = theta0 and ω = 0. When one of its
    //! numbers is not finite the run has failed: that row is not a result and there is no next.
    Sample next();
    //! The simulation left the finite numbers; problem() says where.
    bool failed() const { return m_failed; }
    //! Empty unless failed(): one sentence naming the time of the first non-finite row.
    QString problem() const { return m_problem; }

private:
    static qint64 rowsFor(const OfflineSimulationConfig &config);

    OfflineSimulationConfig m_config;
    std::unique_ptr<SimulatedDevice> m_device;
    DeviceParams m_rendered; //!< the device's parameters (32-bit floats) [SI]
    QByteArray m_feedback;   //!< SET_FEEDBACK τ_ext = 0, fed before every step
    ReferenceGenerator m_reference;
    qint64 m_rows = 0;
    qint64 m_done = 0;
    bool m_failed = false;
    QString m_problem;
};

} // namespace hatpic
