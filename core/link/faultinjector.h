// Seeded faults on a byte link, whole frames at a time (docs/simulator.md § Faults).
//
// Sits at the byte boundary of a simulated or hosted device (SimLink, SimulatorHost,
// hatpic-fw-host's host port) and acts on the frames of each direction: drops them, flips one
// bit in them, sends them twice or holds them back, and cuts the link for a while. Frames end
// at the v2 delimiter 0x00 (legacy: at '\n'). Every decision is drawn from a seeded
// std::mt19937_64 per direction, the same number of draws per frame, so the n-th frame meets
// the same fate in every run with the same seed; cuts are placed on the link's own clock.
#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <deque>
#include <optional>
#include <random>
#include <vector>

namespace hatpic {

struct FaultSpec
{
    //! Faults of one direction: probabilities per frame, a delay in seconds.
    struct Lane
    {
        double drop = 0;
        double corrupt = 0;
        double dup = 0;
        double delay = 0;
        double delaySeconds = 0;
        bool any() const { return drop > 0 || corrupt > 0 || dup > 0 || delay > 0; }
        friend bool operator==(const Lane &, const Lane &) = default;
    };
    //! Both directions lose every frame from `at` for `seconds` (link clock) [s].
    struct Cut
    {
        double at = 0;
        double seconds = 0;
        friend bool operator==(const Cut &, const Cut &) = default;
    };
    static constexpr double kMaxDelaySeconds = 10; //!< longest delay a spec may ask for [s]
    static constexpr int kMaxCuts = 64;            //!< cut= items one spec may hold

    Lane toHost;   //!< device → host (drop, corrupt, dup, delay)
    Lane toDevice; //!< host → device (hdrop, hcorrupt, hdup, hdelay)
    std::vector<Cut> cuts;

    bool isEmpty() const { return !toHost.any() && !toDevice.any() && cuts.empty(); }
    //! Parses "drop=0.01,corrupt=0.005,dup=0.002,delay=0.01:20ms,cut=30s:2s,hdrop=0.05".
    //! On a bad spec returns nothing and sets `error` to a sentence naming the field, the rule
    //! it breaks and the value given.
    static std::optional<FaultSpec> parse(const QString &text, QString *error);
    QString toString() const; //!< the canonical spec text; empty when there is no fault
    friend bool operator==(const FaultSpec &, const FaultSpec &) = default;
};

//! What one direction's injector did, in frames.
struct FaultCounts
{
    quint64 frames = 0;     //!< whole frames seen (empty frames, a lone delimiter, aside)
    quint64 dropped = 0;    //!< not passed on
    quint64 corrupted = 0;  //!< passed on with one bit flipped
    quint64 duplicated = 0; //!< passed on twice
    quint64 delayed = 0;    //!< held back for the delay (frames behind them wait too)
    quint64 cut = 0;        //!< lost to a cut
    quint64 unframed = 0;   //!< bytes passed on untouched: no delimiter within kMaxFrameBytes
    //! Of the dropped and cut frames, the corrupted and the duplicated ones, those that were
    //! stream frames: v2 TELEMETRY (which the receiver numbers by seq), every legacy frame. A
    //! v2 receiver misses streamLost + streamCorrupted frames by seq.
    quint64 streamLost = 0;
    quint64 streamCorrupted = 0;
    quint64 streamDuplicated = 0;
    //! Frames the receiver never gets: dropped + cut.
    quint64 lost() const { return dropped + cut; }
    FaultCounts &operator+=(const FaultCounts &other);
    friend bool operator==(const FaultCounts &, const FaultCounts &) = default;
};

class FaultInjector
{
public:
    enum class Framing { V2, Legacy };                  //!< delimiter 0x00, or '\n'
    static constexpr qsizetype kMaxFrameBytes = 1024;   //!< longer runs pass untouched
    static constexpr qsizetype kMaxHeldBytes = 1 << 20; //!< more held goes early

    FaultInjector(const FaultSpec &spec, quint64 seed, Framing framing);

    //! Device → host bytes, any chunking; returns the bytes due for the host at `now`
    //! (seconds on the link's clock). Call with no bytes to release delayed frames.
    QByteArray toHost(QByteArrayView bytes, double now) { return m_toHost.pass(bytes, now); }
    //! Host → device bytes, as toHost().
    QByteArray toDevice(QByteArrayView bytes, double now) { return m_toDevice.pass(bytes, now); }

    const FaultSpec &spec() const { return m_spec; }
    //! What was injected so far, counted as each frame's fate is drawn.
    const FaultCounts &toHostCounts() const { return m_toHost.counts(); }
    const FaultCounts &toDeviceCounts() const { return m_toDevice.counts(); }
    //! What the receiver can have noticed so far: faults of frames already passed on, and
    //! losses followed by a frame passed on (a gap shows only when the next frame comes).
    //! A receiver on the same thread compares its counters with these at any moment.
    const FaultCounts &toHostSeen() const { return m_toHost.seen(); }
    const FaultCounts &toDeviceSeen() const { return m_toDevice.seen(); }
    //! Whether `now` falls in a cut [s].
    bool cutAt(double now) const;
    //! Four lines, "injected device→host: frames=120000 dropped=1187 …", the same for
    //! host→device, then "seen device→host: …" and "seen host→device: …".
    QString summary() const;

private:
    class Lane
    {
    public:
        Lane(const FaultSpec::Lane &faults, const FaultInjector &owner, quint64 seed);
        QByteArray pass(QByteArrayView bytes, double now);
        const FaultCounts &counts() const { return m_counts; }
        const FaultCounts &seen() const { return m_seen; }

    private:
        struct Held
        {
            QByteArray bytes;
            double release = 0;
            FaultCounts outcome; //!< added to m_seen when the bytes are passed on
        };
        void frame(QByteArray frame, double now);
        //! Flips one bit; false when the frame has no byte that may change.
        bool corrupt(QByteArray &frame, double draw) const;
        bool isStream(const QByteArray &frame) const;
        void hold(QByteArray bytes, double release, const FaultCounts &outcome = {});
        double draw();

        FaultSpec::Lane m_faults;
        const FaultInjector &m_owner;
        std::mt19937_64 m_random;
        QByteArray m_partial;
        std::deque<Held> m_held;
        qsizetype m_heldBytes = 0;
        FaultCounts m_counts;
        FaultCounts m_seen;
        FaultCounts m_unseenLoss; //!< losses no passed frame has revealed yet
    };

    FaultSpec m_spec;
    char m_delimiter;
    Lane m_toHost;
    Lane m_toDevice;
};

//! "frames=120000 dropped=1187 corrupted=… duplicated=… delayed=… cut=… stream_lost=…
//! stream_corrupted=… stream_duplicated=… unframed_bytes=…": one direction's counts, as
//! summary() gives them.
QString describeFaultCounts(const FaultCounts &counts);

} // namespace hatpic
