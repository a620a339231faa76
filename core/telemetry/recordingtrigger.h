// When a recording starts and how long it runs: now, on the next push, or when θ or τ crosses
// a threshold; optionally with a span before the trigger (kept from the recent samples) and a
// fixed length after it. RecordingTrigger decides on each sample whether the trigger fired;
// the session's sample pipeline keeps the recent samples and opens the file when it does.
#pragma once

#include "telemetry/sample.h"

#include <QString>

namespace hatpic {

struct RecordingPlan
{
    static constexpr double kMaxPreTrigger_s = 10; //!< longest span kept before the trigger [s]

    enum class Start { Now, NextPush, Threshold };
    enum class Quantity { Theta, Tau }; //!< θ [rad] or τ [N·m] (Sample::theta, Sample::tau)
    enum class Edge { Rising, Falling };

    Start start = Start::Now;
    Quantity quantity = Quantity::Theta;
    Edge edge = Edge::Rising;
    double level = 0;        //!< threshold in SI units of `quantity`
    double preTrigger_s = 0; //!< recorded before the trigger, within [0, kMaxPreTrigger_s] [s]
    double duration_s = 0;   //!< recorded from the trigger on; 0: until stopped [s]

    //! The same plan with its numbers made usable: NaN/negative spans are 0, the pre-trigger
    //! span at most kMaxPreTrigger_s, a non-finite level 0.
    RecordingPlan sanitized() const;
    bool operator==(const RecordingPlan &) const = default;
};

//! The trigger as the recording's event text names it (part of the file format, recording.md):
//! "trigger: theta rising through 0.2", "trigger: push", "trigger: start".
QString triggerEventText(const RecordingPlan &plan);

//! Detects the crossing of a threshold in a stream of samples: fires on the first sample at or
//! beyond the level (in the edge's direction) whose predecessor was on the other side. A
//! sample with a NaN value is skipped; the first sample only sets the side.
class RecordingTrigger
{
public:
    explicit RecordingTrigger(const RecordingPlan &plan = {});

    //! True when `sample` fires a Threshold plan; then the trigger stays spent (reset() arms it
    //! again). Never true for other plans.
    bool feed(const Sample &sample);
    bool fired() const { return m_fired; }
    void reset();

    const RecordingPlan &plan() const { return m_plan; }

private:
    RecordingPlan m_plan;
    bool m_havePrevious = false;
    bool m_previousBeyond = false; //!< the previous value was at or beyond the level
    bool m_fired = false;
};

} // namespace hatpic
