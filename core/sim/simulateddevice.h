// A simulated HATPIC joystick: the device side of model.md and protocol.md on simulated time.
//
// Pure and single-threaded: no timers, no I/O threads. The owner feeds host bytes with
// receive(), advances simulated time with advance(), and drains the device's bytes with
// takeOutput(). hatpic-sim drives it from a pseudo-terminal in real time; the session's
// in-process "sim" port drives it directly; `hatpicctl simulate` uses step() offline.
#pragma once

#include "link/faultinjector.h"
#include "model/admittance.h"
#include "model/params.h"
#include "model/passivity.h"
#include "protocol/deviceinfo.h"
#include "protocol/legacy.h"
#include "protocol/v2codec.h"
#include "sim/handinput.h"
#include "telemetry/sample.h"

#include <QByteArray>
#include <QString>

#include <cmath>
#include <functional>
#include <memory>
#include <random>

namespace hatpic {

class SimulatedDevice
{
public:
    //! The load-reading noise hatpic-sim and hatpic-servo-sim run with: std-dev [N·m].
    static constexpr double kProgramNoise = 0.0005;

    struct Config
    {
        WireProtocol protocol = WireProtocol::V2;
        double controlRateHz = 1000;   //!< control loop rate [Hz]
        qint32 baud = 0;               //!< emulated link; 0 = the protocol's defaultBaud()
        bool throttle = true;          //!< limit output to the link's byte rate
        bool ideal = false;            //!< no servo lag, quantisation or noise: model.md alone
        double noise = 0;              //!< std-dev of load-reading noise [N·m]; 0 = none
        quint64 seed = 1;              //!< noise seed, and the faults' seed
        QString stateFile;             //!< SAVE_PARAMS persists here (a profile file) if set
        HandInput hand;                //!< operator input at start
        quint32 deviceId = 0x53494D31; //!< "SIM1"
        double tauLimit = 0.44;        //!< actuator torque limit [N·m]
        DeviceParams params;           //!< power-up parameters (a valid stateFile overrides)
        PassivityParams passivity;     //!< power-up passivity block (the same; v2 only)
        //! Faults the link to the host injects (SimLink, SimulatorHost); empty = none.
        FaultSpec faults;
    };

    //! One control cycle as the device saw it (what TELEMETRY reports).
    struct Cycle
    {
        double t = 0;          //!< simulated time at the cycle [s]
        double theta = 0;      //!< measured knob angle used this cycle [rad]
        double omega = 0;      //!< knob rate [rad/s]
        double tau = 0;        //!< measured interaction torque [N·m]
        double tau_rec = 0;    //!< [N·m]
        double tau_ext = 0;    //!< [N·m]
        double tau_fx = 0;     //!< τ_det + τ_wall + τ_vib (effects.md; legacy: 0) [N·m]
        double tau_total = 0;  //!< clamped to tau_limit [N·m]
        double tau_pc = 0;     //!< the passivity controller's −β·ω (passivity.md) [N·m]
        double pc_reserve = 0; //!< its energy reserve R [J]
        quint8 flags = 0;      //!< v2::kFlag* bits

        //! The sample of this cycle as TELEMETRY would carry it: t_s = t, t_us the wrapping
        //! 32-bit microseconds of t, the torques, the passivity reserve and flags; no reference
        //! model (v_ref, p_ref 0), no arrival time.
        Sample toSample() const
        {
            Sample sample;
            sample.t_s = t;
            // Device timestamps are 32-bit microseconds that wrap (protocol.md); so do these.
            sample.t_us = static_cast<quint32>(static_cast<quint64>(std::llround(t * 1e6)));
            sample.theta = theta;
            sample.omega = omega;
            sample.tau = tau;
            sample.tau_rec = tau_rec;
            sample.tau_ext = tau_ext;
            sample.tau_fx = tau_fx;
            sample.tau_total = tau_total;
            sample.tau_pc = tau_pc;
            sample.pc_reserve = pc_reserve;
            sample.flags = flags;
            return sample;
        }
    };

    explicit SimulatedDevice(const Config &config);
    ~SimulatedDevice();
    SimulatedDevice(const SimulatedDevice &) = delete;
    SimulatedDevice &operator=(const SimulatedDevice &) = delete;

    //! Host → device bytes (any chunking).
    void receive(QByteArrayView bytes);
    //! Runs the control loop for `dt` seconds of simulated time, queueing output.
    void advance(double dt);
    //! Runs exactly one control cycle and returns it (offline simulation).
    Cycle step();
    //! Device → host bytes the emulated link has carried so far (bounded queue).
    QByteArray takeOutput();

    //! Called with every control cycle once it has run, on the thread that runs the device
    //! (hatpic-sim's --cycle-log). Empty: none.
    void setCycleObserver(std::function<void(const Cycle &)> observer);

    void setHand(const HandInput &hand); //!< switch the operator input while running
    HandInput hand() const;

    const Config &config() const;
    DeviceParams params() const;
    double time() const;        //!< simulated time [s]
    qint32 baud() const;        //!< effective emulated baud rate
    quint16 streamRate() const; //!< telemetry rate in force [Hz]
    bool feedbackStale() const;
    //! Highest telemetry rate the link can carry at this baud [Hz].
    quint16 linkLimitedRate() const;
    //! Telemetry frames dropped because the output queue was full (seen as seq gaps).
    quint64 telemetryDropped() const;
    //! SET_PARAMS blocks the device accepted (v2; a retry it answered again does not count).
    quint64 paramsApplied() const;
    //! Why the state file (or config.params) was not used at power-up; empty when fine.
    QString stateWarning() const;
    //! Why SAVE_PARAMS could not write the state file, as far as start can tell (its folder is
    //! missing or read-only, or the file would not be overwritten); empty when nothing is in
    //! the way (ProfileParamStore::saveProblem).
    QString saveWarning() const;

private:
    class Private;
    std::unique_ptr<Private> d;
};

//! The injector for config.faults (seeded with config.seed, framed by config.protocol), or
//! null when the spec holds no fault.
std::unique_ptr<FaultInjector> makeFaultInjector(const SimulatedDevice::Config &config);

} // namespace hatpic
