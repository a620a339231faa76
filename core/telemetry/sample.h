// One complete sample as the session emits it: device telemetry plus the host's reference model.
#pragma once

#include "model/axes.h"

#include <QList>
#include <QMetaType>
#include <QtGlobal>

#include <array>
#include <chrono>
#include <limits>
#include <memory>

namespace hatpic {

//! Host-side flag bits, above the device's 8 telemetry flag bits (v2::kFlag*).
constexpr quint16 kFlagModelEstimated = 0x0100; //!< τ_rec etc. computed by the host (legacy)
constexpr quint16 kFlagReferenceGap = 0x0200;   //!< p_ref held across a gap before this sample

//! What one further axis of a multi-axis device did (axes 2…; Sample's own fields are axis 1),
//! each as its namesake in Sample.
struct AxisSample
{
    double theta = 0;
    double omega = 0;
    double tau = 0;
    double tau_rec = 0;
    double tau_ext = 0;
    double tau_total = 0;
    double v_ref = 0;
    double p_ref = 0;
};

//! What a board with several knobs or a tilt sensor adds to a sample (Sample::board).
struct BoardSample
{
    int axes = 1; //!< 1…kMaxAxes: Sample's own knob, then more[0 … axes − 2]
    std::array<AxisSample, kMaxAxes - 1> more{};
    //! The board's tilt (docs/protocol.md § 1) [rad]; NaN when it has no tilt sensor.
    double roll = std::numeric_limits<double>::quiet_NaN();
    double pitch = std::numeric_limits<double>::quiet_NaN();
};

//! Quantities are SI. Values a protocol does not carry are NaN (legacy has no ω or τ).
struct Sample
{
    double t_s = 0;       //!< session time: device clock where it has one, monotonic [s]
    quint32 t_us = 0;     //!< raw device timestamp (legacy: host clock) [µs, wraps]
    double theta = 0;     //!< knob angle, absolute [rad]
    double omega = 0;     //!< knob rate [rad/s]
    double tau = 0;       //!< interaction torque of eq. (1); operator torque is −tau [N·m]
    double tau_rec = 0;   //!< re-centering torque [N·m]
    double tau_ext = 0;   //!< external feedback torque [N·m]
    double tau_total = 0; //!< τ_rec + τ_fx + τ_ext as rendered, clamped to tau_limit [N·m]
    double v_ref = 0;     //!< reference velocity [m/s or rad/s]
    double p_ref = 0;     //!< reference position [m or rad]
    //! τ_det + τ_wall + τ_vib rendered (effects.md) [N·m]; NaN when the device does not send it
    //! (legacy, or a v2 device without the effects capability): unknown, not zero.
    double tau_fx = 0;
    quint16 flags = 0; //!< device flags (low byte) | host flags (kFlag*)
    //! When the frame that carried it was decoded, on sampleClockNs(); 0 when not known
    //! (replay, offline simulation). Not recorded: it measures the host, not the knob [ns].
    qint64 arrival_ns = 0;
    //! τ_pc = −β·ω, the passivity controller's torque, and its reserve R (passivity.md)
    //! [N·m, J]; NaN when the device does not send them (no passivity capability).
    double tau_pc = 0;
    double pc_reserve = 0;
    //! What a board with several knobs or a tilt sensor adds (the IMU branch's); null for a
    //! single knob, so its samples stay this size. Shared between copies, never changed once made.
    std::shared_ptr<const BoardSample> board;

    //! Axes this sample carries, 1…kMaxAxes: this knob, then board->more.
    int axes() const { return board ? board->axes : 1; }
    //! Axis n's quantities (2 … axes()), or null.
    const AxisSample *axis(int n) const
    {
        return board && n >= 2 && n <= board->axes ? &board->more[std::size_t(n - 2)] : nullptr;
    }
    //! Knob n's quantities (1 … axes()), knob 1's being the sample's own.
    AxisSample knob(int n) const
    {
        if (const AxisSample *other = axis(n))
            return *other;
        return {theta, omega, tau, tau_rec, tau_ext, tau_total, v_ref, p_ref};
    }
    //! The board's tilt [rad]; NaN without a tilt sensor.
    double roll() const { return board ? board->roll : std::numeric_limits<double>::quiet_NaN(); }
    double pitch() const { return board ? board->pitch : std::numeric_limits<double>::quiet_NaN(); }
};

using SampleBatch = QList<Sample>;

//! The host's steady clock that Sample::arrival_ns is read from [ns].
inline qint64 sampleClockNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace hatpic

Q_DECLARE_METATYPE(hatpic::Sample)
Q_DECLARE_METATYPE(hatpic::SampleBatch)
