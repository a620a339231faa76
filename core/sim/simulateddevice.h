// A simulated HATPIC joystick: the device side of model.md and protocol.md on simulated time.
//
// Pure and single-threaded: no timers, no I/O threads. The owner feeds host bytes with
// receive(), advances simulated time with advance(), and drains the device's bytes with
// takeOutput(). hatpic-sim drives it from a pseudo-terminal in real time; the session's
// in-process "sim" port drives it directly; `hatpicctl simulate` uses step() offline.
#pragma once

#include "firmware/controller.h"
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

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <vector>

namespace hatpic {

class SimulatedDevice
{
public:
    //! The load-reading noise hatpic-sim and hatpic-servo-sim run with: std-dev [N·m].
    static constexpr double kProgramNoise = 0.0005;

    //! Which board is simulated.
    enum class Board {
        Knob,      //!< one knob: the master firmware (legacy) or our device core (v2)
        ImuBranch, //!< the published IMU branch: four knobs and a tilt, legacy only (protocol.md §
                   //!< 1)
    };
    //! Knobs beyond the first that an IMU-branch board has.
    static constexpr int kOtherKnobs = legacy::kImuBranchServos - 1;

    struct Config
    {
        WireProtocol protocol = WireProtocol::V2;
        //! ImuBranch speaks the branch's legacy frames whatever `protocol` says.
        Board board = Board::Knob;
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
        //! ImuBranch: the operator inputs on knobs 2–4 (`hand` is knob 1's).
        std::array<HandInput, kOtherKnobs> otherHands{};
        //! ImuBranch: the board's tilt at start, roll and pitch [rad] (legacy::TiltConversion).
        double roll = 0;
        double pitch = 0;

        //! The protocol the board speaks: `protocol`, or legacy for the IMU branch.
        WireProtocol wireProtocol() const
        {
            return board == Board::ImuBranch ? WireProtocol::Legacy : protocol;
        }
    };

    //! One control cycle as the device saw it: its record, on simulated time.
    struct Cycle : fw::CycleRecord<double>
    {
        double t = 0; //!< simulated time at the cycle [s]

        //! The sample of this cycle as TELEMETRY would carry it, with t_s = t and the device's
        //! τ_total; no reference model (v_ref, p_ref 0), no arrival time.
        Sample toSample() const;
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
    //! Switches knob `knob`'s operator input (1 … knobs()); knob 1 is setHand's. Another knob
    //! is ignored.
    void setHand(int knob, const HandInput &hand);
    //! Tilts the IMU-branch board to `roll`, `pitch` [rad]; ignored by a single knob.
    void setTilt(double roll, double pitch);
    //! Knobs on the board: 1, or 4 for the IMU branch.
    int knobs() const;
    //! The angle each knob's servo read at the last cycle, knob 1 first [rad].
    std::vector<double> knobAngles() const;

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
