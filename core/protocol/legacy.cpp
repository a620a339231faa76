#include "legacy.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

namespace hatpic::legacy {

namespace {

//! The letter that ends field n (A…D, roll, pitch). Field D also ends at 'o' (the master
//! firmware's frame, and the host's); 'p' there goes on to the IMU branch's tilt.
constexpr char kFieldEnd[6] = {'b', 'c', 'd', 'p', 'r', 'o'};
constexpr int kFieldD = 3;
constexpr int kFieldRoll = 4;
constexpr int kFieldPitch = 5;

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

//! Bytes that can occur inside a frame after "ia" (the 'o' ends it).
bool isFrameInner(char c)
{
    return isDigit(c) || c == '-' || c == '+' || c == 'b' || c == 'c' || c == 'd' || c == 'p' ||
           c == 'r';
}

double tiltAngle(int field)
{
    const int clamped = std::clamp(field, 0, TiltConversion::kFieldMax);
    return double(clamped - TiltConversion::kLevel) * (std::numbers::pi / 2) /
           TiltConversion::kFieldsPerQuarterTurn;
}

int tiltField(double angle)
{
    if (std::isnan(angle))
        return TiltConversion::kLevel;
    const double field = TiltConversion::kLevel +
                         angle * TiltConversion::kFieldsPerQuarterTurn / (std::numbers::pi / 2);
    return int(std::lround(std::clamp(field, 0.0, double(TiltConversion::kFieldMax))));
}

} // namespace

QByteArray encodeFrame(const Frame &frame)
{
    const auto field = [](int v) {
        return QByteArray::number(std::clamp(v, -kFieldLimit, kFieldLimit));
    };
    QByteArray bytes =
        "ia" + field(frame.a) + 'b' + field(frame.b) + 'c' + field(frame.c) + 'd' + field(frame.d);
    if (frame.tilt)
        bytes += 'p' + field(frame.tilt->roll) + 'r' + field(frame.tilt->pitch);
    return bytes + 'o';
}

// ---- Decoder ----

void Decoder::clear()
{
    m_state = State::Text;
    m_frame.resize(0);
    m_line.resize(0);
    m_lineConsumed = false;
}

void Decoder::feed(QByteArrayView bytes, QList<Frame> &frames, QStringList *text)
{
    m_stats.bytes += static_cast<quint64>(bytes.size());
    for (const char c : bytes) {
        // A byte that ends a broken frame without belonging to it is looked at again in the
        // Text state; that state always consumes its byte, so this loop runs at most twice.
        bool again = true;
        while (again) {
            again = false;
            switch (m_state) {
            case State::Text:
                textByte(c, text);
                break;
            case State::Frame:
                switch (stepFrame(c)) {
                case Step::More:
                    break;
                case Step::Done:
                    frames.append(m_current);
                    ++m_stats.frames;
                    if (m_current.tilt)
                        ++m_stats.tiltFrames;
                    m_lineConsumed = true;
                    m_frame.resize(0);
                    m_state = State::Text;
                    break;
                case Step::Fail:
                    if (m_frame.size() >= 3) {
                        // "ia" and a number had started: a real frame went wrong.
                        ++m_stats.malformed;
                        m_lineConsumed = true;
                        m_frame.resize(0);
                        if (c == 'o') {
                            m_state = State::Text; // the broken frame's end, consumed
                        } else if (isFrameInner(c)) {
                            m_state = State::Skip;
                        } else {
                            m_state = State::Text;
                            again = true;
                        }
                    } else {
                        // Only "i" or "ia" so far: it was text after all.
                        const QByteArray held = m_frame;
                        m_frame.resize(0);
                        m_state = State::Text;
                        for (const char h : held)
                            appendText(h, text);
                        again = true;
                    }
                    break;
                }
                break;
            case State::Skip:
                if (c == 'o') {
                    m_state = State::Text;
                } else if (!isFrameInner(c)) {
                    m_state = State::Text;
                    again = true;
                }
                break;
            }
        }
    }
}

void Decoder::startFrame()
{
    m_state = State::Frame;
    m_frame.resize(0);
    m_frame.append('i');
    m_field = 0;
    m_digits = 0;
    m_signed = false;
    m_negative = false;
    m_value = 0;
    m_current = {};
}

Decoder::Step Decoder::stepFrame(char c)
{
    if (m_frame.size() >= kMaxFrameBytes)
        return Step::Fail; // safety net; the per-field digit limit keeps frames far shorter
    if (m_frame.size() == 1) {
        if (c != 'a')
            return Step::Fail;
        m_frame.append(c);
        return Step::More;
    }
    if (isDigit(c)) {
        if (++m_digits > kMaxDigits)
            return Step::Fail; // over-long number
        m_value = m_value * 10 + (c - '0');
        m_frame.append(c);
        return Step::More;
    }
    if ((c == '-' || c == '+') && m_digits == 0 && !m_signed) {
        m_signed = true;
        m_negative = c == '-';
        m_frame.append(c);
        return Step::More;
    }
    const bool masterEnd = m_field == kFieldD && c == 'o';
    if ((c != kFieldEnd[m_field] && !masterEnd) || m_digits == 0)
        return Step::Fail; // wrong or missing letter, or a letter where a number belongs
    const int value = m_negative ? -m_value : m_value;
    if (value < -kFieldLimit || value > kFieldLimit)
        return Step::Fail;
    switch (m_field) {
    case 0:
        m_current.a = value;
        break;
    case 1:
        m_current.b = value;
        break;
    case 2:
        m_current.c = value;
        break;
    case kFieldD:
        m_current.d = value;
        if (masterEnd)
            return Step::Done;
        m_current.tilt = Tilt{};
        break;
    case kFieldRoll:
        m_current.tilt->roll = value;
        break;
    default:
        m_current.tilt->pitch = value;
        return Step::Done;
    }
    static_assert(kFieldPitch + 1 == std::size(kFieldEnd));
    ++m_field;
    m_digits = 0;
    m_signed = false;
    m_negative = false;
    m_value = 0;
    m_frame.append(c);
    return Step::More;
}

void Decoder::textByte(char c, QStringList *text)
{
    if (c == 'i')
        startFrame();
    else if (c == '\n')
        endLine(text);
    else if (c != '\r')
        appendText(c, text);
}

void Decoder::appendText(char c, QStringList *text)
{
    m_line.append(c);
    if (m_line.size() < kMaxLineBytes)
        return;
    // Cut: the piece becomes a line of its own; the rest of the line starts a new one.
    ++m_stats.longLines;
    ++m_stats.textLines;
    if (text)
        text->append(QString::fromUtf8(m_line));
    m_line.resize(0);
    m_lineConsumed = true;
}

void Decoder::endLine(QStringList *text)
{
    // The CRLF after a frame (or after a cut piece) is not a line of its own.
    if (!(m_line.isEmpty() && m_lineConsumed)) {
        ++m_stats.textLines;
        if (text)
            text->append(QString::fromUtf8(m_line));
    }
    m_line.resize(0);
    m_lineConsumed = false;
}

// ---- Conversion ----

double Conversion::ticksToRad(int ticks) const
{
    return static_cast<double>(ticks - centerTicks) * 2.0 * std::numbers::pi / kTicksPerRev;
}

int Conversion::radToTicks(double theta) const
{
    if (std::isnan(theta))
        return centerTicks;
    const double ticks = centerTicks + theta * kTicksPerRev / (2.0 * std::numbers::pi);
    return static_cast<int>(
        std::lround(std::clamp(ticks, -double(kFieldLimit), double(kFieldLimit))));
}

int Conversion::feedbackToField(double tauExt) const
{
    if (std::isnan(tauExt) || !(tauLimit > 0) || !std::isfinite(tauLimit))
        return kFeedbackZero;
    // The clamp itself is kept inside what a frame field can carry.
    const double limit = std::clamp(feedbackClamp, 0, kFieldLimit - kFeedbackZero);
    const double offset = std::clamp(1000.0 * tauExt / tauLimit, -limit, limit);
    return kFeedbackZero + static_cast<int>(std::lround(offset));
}

double Conversion::fieldToFeedback(int a) const
{
    return static_cast<double>(a - kFeedbackZero) * tauLimit / 1000.0;
}

double imuBranchAngle(int field)
{
    return Conversion{}.ticksToRad(field); // the default centre is the branch's
}

int imuBranchField(double theta)
{
    constexpr int kFieldMax = 2000; // the firmware's clamp of a position
    return std::clamp(Conversion{}.radToTicks(theta), 0, kFieldMax);
}

// ---- TiltConversion ----

double TiltConversion::rollFromField(int roll)
{
    return -tiltAngle(roll); // the upside-down mount: the field falls as the roll grows
}

double TiltConversion::pitchFromField(int pitch)
{
    return tiltAngle(pitch);
}

int TiltConversion::rollToField(double roll)
{
    return tiltField(-roll);
}

int TiltConversion::pitchToField(double pitch)
{
    return tiltField(pitch);
}

} // namespace hatpic::legacy
