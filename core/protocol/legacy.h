// Legacy ASCII protocol of the published HATPIC firmware (protocol.md § 1).
#pragma once

#include "model/axes.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QList>
#include <QStringList>

#include <array>
#include <optional>

namespace hatpic::legacy {

//! The tilt fields of the IMU branch's device frame: `p<ROLL>r<PITCH>` (docs/protocol.md § 1, the
//! IMU branch's frames), each 0…2000 with 1000 level. Note the letter `p` comes before ROLL and `r`
//! before PITCH.
struct Tilt
{
    int roll = 1000;
    int pitch = 1000;
    friend bool operator==(const Tilt &, const Tilt &) = default;
};

//! One frame: the master firmware's `ia<A>b<B>c<C>d<D>o`, or the IMU branch's device frame
//! `ia<P1>b<P2>c<P3>d<P4>p<ROLL>r<PITCH>o`, which carries `tilt`.
struct Frame
{
    Frame() = default;
    Frame(int a, int b, int c, int d, std::optional<Tilt> tilt = std::nullopt)
        : a(a), b(b), c(c), d(d), tilt(tilt)
    {}

    int a = 0;
    int b = 0;
    int c = 0;
    int d = 0;
    std::optional<Tilt> tilt; //!< only in the IMU branch's device → host frame
    friend bool operator==(const Frame &, const Frame &) = default;

    //! The four fields in order, A…D: the IMU branch's four servos.
    std::array<int, 4> fields() const { return {a, b, c, d}; }
};

//! Servos of the IMU-branch board (ids 1–4), one per frame field A…D.
constexpr int kImuBranchServos = 4;
static_assert(kImuBranchServos <= kMaxAxes);

//! θ [rad] of the IMU branch's position field P_n: (P_n − 1000) · 2π / 4096 (its firmware
//! centres every servo on 1000).
double imuBranchAngle(int field);
//! The position field P_n the branch sends for θ [rad]: 1000 + round(θ · 4096 / 2π), clamped to
//! 0…2000 as the firmware clamps it; NaN gives 1000.
int imuBranchField(double theta);

constexpr int kFieldLimit = 99999; //!< |field| larger than this is malformed

//! Whole frame as ASCII, no terminator: "ia1000b0c0d0o", or with its tilt
//! "ia1000b1000c1000d1000p1000r1000o". Fields beyond ±kFieldLimit are clamped so that the frame
//! is always one a receiver accepts.
QByteArray encodeFrame(const Frame &frame);

struct DecoderStats
{
    quint64 bytes = 0;
    quint64 frames = 0;     //!< valid frames
    quint64 tiltFrames = 0; //!< of which the IMU branch's, with the tilt fields
    quint64 malformed = 0;  //!< started with 'i' but broke a rule
    quint64 textLines = 0;  //!< non-frame text lines (boot messages)
    quint64 longLines = 0;  //!< text lines cut at kMaxLineBytes (each piece is a text line)
    friend bool operator==(const DecoderStats &, const DecoderStats &) = default;
};

//! Incremental decoder of a byte stream that mixes frames and free text.
//!
//! Frames are recognised by `i` … `o` wherever they stand (the device ends them with CRLF,
//! the host does not). Bytes outside frames form text lines, split at '\n' with '\r'
//! stripped. Memory is bounded: an over-long frame or text line is cut and counted.
//!
//! Boot text may contain "ia" ("serial", "Initializing"), so a candidate frame only counts
//! as a frame once "ia" is followed by a digit or sign; before that a failing candidate is
//! given back to the text. A committed candidate that breaks a rule is counted as malformed
//! and dropped; decoding resumes at the first byte that cannot belong to the broken frame
//! (an 'i' starts a new candidate, a newline ends the text line). docs/protocol.md has the
//! full rules.
class Decoder
{
public:
    static constexpr int kMaxFrameBytes = 64; //!< longest plausible frame
    static constexpr int kMaxLineBytes = 256; //!< longest text line kept
    static constexpr int kMaxDigits = 6;      //!< more digits in one field is "over-long"

    //! Appends complete frames to `frames` and complete text lines to `text` (may be null).
    void feed(QByteArrayView bytes, QList<Frame> &frames, QStringList *text = nullptr);

    const DecoderStats &stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }
    //! Forgets a partial frame and a partial text line (e.g. after reopening a port).
    void clear();
    //! Bytes of an unfinished frame and text line held right now (bounded).
    qsizetype pendingBytes() const { return m_frame.size() + m_line.size(); }

private:
    enum class State {
        Text,  //!< outside frames
        Frame, //!< inside a candidate frame that is still a valid prefix
        Skip,  //!< after a malformed frame, discarding the rest of its frame characters
    };
    enum class Step { More, Done, Fail };

    Step stepFrame(char c);
    void startFrame();
    void textByte(char c, QStringList *text);
    void appendText(char c, QStringList *text);
    void endLine(QStringList *text);

    State m_state = State::Text;
    QByteArray m_frame;          //!< raw bytes of the candidate frame
    QByteArray m_line;           //!< text line so far, '\r' removed
    bool m_lineConsumed = false; //!< a frame or a cut piece came from this line already
    int m_field = 0;             //!< field being read: 0 = A … 3 = D, 4 = roll, 5 = pitch
    int m_digits = 0;            //!< digits read in this field
    bool m_signed = false;       //!< sign read in this field
    bool m_negative = false;
    int m_value = 0; //!< magnitude read so far
    Frame m_current;
    DecoderStats m_stats;
};

//! Tick ↔ angle and τ_ext ↔ load-unit conversions of the published firmware and driver.
struct Conversion
{
    static constexpr int kTicksPerRev = 4096;

    int centerTicks = 1000;  //!< tick that maps to θ = 0
    int feedbackClamp = 350; //!< |load offset| sent at most [load units, ±1000 = 100 %]
    double tauLimit = 0.44;  //!< torque that 1000 load units stand for [N·m]

    static constexpr int kFeedbackZero = 1000; //!< field A for zero feedback

    //! θ [rad] of a position reading.
    double ticksToRad(int ticks) const;
    //! Position reading for θ, rounded to the nearest tick (half away from zero), not wrapped,
    //! limited to ±kFieldLimit; NaN gives centerTicks.
    int radToTicks(double theta) const;
    //! Host frame field A for a feedback torque: 1000 + round(1000·τ_ext/tau_limit), the offset
    //! clamped to ±feedbackClamp. NaN (or a tau_limit that is not a positive number) gives 1000,
    //! i.e. no force.
    int feedbackToField(double tauExt) const;
    //! τ_ext that a received field A stands for (device side), not clamped [N·m].
    double fieldToFeedback(int a) const;
};

//! The IMU branch's tilt fields ↔ angles (docs/protocol.md § 1). The firmware maps its sensor's
//! pitch −90°…90° onto 0…2000 and, the board being mounted upside down, its roll away from the
//! ±180° it reads level onto 1000…0 (rolling one way) and 1000…2000 (the other), both clamped.
//! Here roll is the board's roll away from level and pitch the sensor's pitch, each with the
//! sensor's own sign, in −π/2…π/2.
struct TiltConversion
{
    static constexpr int kLevel = 1000;                //!< the field of a level board
    static constexpr int kFieldMax = 2000;             //!< fields span 0…kFieldMax
    static constexpr int kFieldsPerQuarterTurn = 1000; //!< 90° is 1000 field units

    //! roll [rad] of a ROLL field; fields outside 0…2000 are clamped first.
    static double rollFromField(int roll);
    //! pitch [rad] of a PITCH field; the same clamp.
    static double pitchFromField(int pitch);
    //! The ROLL field the firmware sends for `roll` [rad], rounded, clamped to 0…2000; NaN
    //! gives level.
    static int rollToField(double roll);
    //! The PITCH field for `pitch` [rad], likewise.
    static int pitchToField(double pitch);
};

} // namespace hatpic::legacy
