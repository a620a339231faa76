// Legacy ASCII protocol of the published HATPIC firmware (protocol.md § 1).
#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QList>
#include <QStringList>

namespace hatpic::legacy {

//! One `ia<A>b<B>c<C>d<D>o` frame.
struct Frame
{
    int a = 0;
    int b = 0;
    int c = 0;
    int d = 0;
    friend bool operator==(const Frame &, const Frame &) = default;
};

constexpr int kFieldLimit = 99999; //!< |field| larger than this is malformed

//! Whole frame as ASCII, no terminator: "ia1000b0c0d0o".
QByteArray encodeFrame(const Frame &frame);

struct DecoderStats
{
    quint64 bytes = 0;
    quint64 frames = 0;     //!< valid frames
    quint64 malformed = 0;  //!< started with 'i' but broke a rule
    quint64 textLines = 0;  //!< non-frame text lines (boot messages)
    friend bool operator==(const DecoderStats &, const DecoderStats &) = default;
};

//! Incremental decoder of a byte stream that mixes frames and free text.
//!
//! Frames are recognised by `i` … `o` wherever they stand (the device ends them with CRLF,
//! the host does not). Bytes outside frames form text lines, split at '\n' with '\r'
//! stripped. Memory is bounded: an over-long frame or text line is cut and counted.
class Decoder
{
public:
    static constexpr int kMaxFrameBytes = 64;  //!< longest plausible frame
    static constexpr int kMaxLineBytes = 256;  //!< longest text line kept

    //! Appends complete frames to `frames` and complete text lines to `text` (may be null).
    void feed(QByteArrayView bytes, QList<Frame> &frames, QStringList *text = nullptr);

    const DecoderStats &stats() const { return m_stats; }
    void clear();

private:
    enum class State { Text, Frame };
    void endFrame(QList<Frame> &frames);

    State m_state = State::Text;
    QByteArray m_frame;
    QByteArray m_line;
    DecoderStats m_stats;
};

//! Tick ↔ angle and τ_ext ↔ load-unit conversions of the published firmware and driver.
struct Conversion
{
    static constexpr int kTicksPerRev = 4096;

    int centerTicks = 1000;   //!< tick that maps to θ = 0
    int feedbackClamp = 350;  //!< |load offset| sent at most [load units, ±1000 = 100 %]
    double tauLimit = 0.44;   //!< torque that 1000 load units stand for [N·m]

    double ticksToRad(int ticks) const;
    int radToTicks(double theta) const; //!< rounded to the nearest tick
    //! Host frame field A for a feedback torque: 1000 + round(1000·τ_ext/tau_limit), clamped.
    int feedbackToField(double tauExt) const;
    //! τ_ext that a received field A stands for (device side).
    double fieldToFeedback(int a) const;
};

} // namespace hatpic::legacy
