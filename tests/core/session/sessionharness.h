// A DeviceSession with everything it emits collected, and the in-process simulator's options:
// what the session's tests on the test thread share (tst_devicesession,
// tst_devicesessioncommands, tst_devicesessionstream).
#pragma once

#include "session/devicesession.h"
#include "sim/simulateddevice.h"
#include "simulatoroptions.h"

#include <QList>
#include <QObject>
#include <QPair>

#include <algorithm>
#include <map>

namespace hatpic::test {

inline constexpr int kConnectTimeoutMs = 5000;
inline constexpr int kCommandWaitMs = 3000;

inline ConnectOptions simOptions(WireProtocol protocol,
                                 ProtocolChoice choice = ProtocolChoice::Auto,
                                 const HandInput &hand = {})
{
    SimulatedDevice::Config config;
    config.protocol = protocol;
    config.hand = hand;
    return test::simulatorOptions(config, choice);
}

//! Parameters as a device holds them: each field rounded to float32.
inline DeviceParams asFloat(const DeviceParams &p)
{
    DeviceParams out;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        out.setField(i, double(float(p.field(i))));
    return out;
}

//! A session with everything it emits collected.
struct Harness
{
    DeviceSession session;
    QList<Sample> samples;
    // A std::map: a QHash of Outcome trips GCC 12 -O3 -Wmaybe-uninitialized (a false positive).
    std::map<quint64, Outcome> results;
    QList<QPair<SessionState, StateDetail>> states;
    QList<DeviceParams> params;
    QList<RecordingStatus> recording;
    LinkStats lastStats;
    quint64 nextId = 0;

    Harness()
    {
        QObject::connect(&session.samples(), &SamplePipeline::samplesReady,
                         [this](const SampleBatch &b) { samples.append(b); });
        QObject::connect(&session, &DeviceSession::stateChanged,
                         [this](SessionState s, const StateDetail &d) {
                             states.append({s, d});
                         });
        QObject::connect(&session.samples(), &SamplePipeline::deviceTuningChanged,
                         [this](const DeviceTuning &t) {
                             if (t.params)
                                 params.append(*t.params);
                         });
        QObject::connect(&session.samples(), &SamplePipeline::recordingChanged,
                         [this](const RecordingStatus &r) { recording.append(r); });
        QObject::connect(&session, &DeviceSession::statsUpdated,
                         [this](const LinkStats &s) { lastStats = s; });
    }
    //! Sends `request`; its outcome lands in `results` under `id`.
    void send(quint64 id, const Request &request)
    {
        session.request(request, [this, id](const Outcome &o) { results.insert_or_assign(id, o); });
    }
    bool sawState(SessionState s) const
    {
        return std::any_of(states.cbegin(), states.cend(),
                           [s](const auto &p) { return p.first == s; });
    }
    StateDetail detailOf(SessionState s) const
    {
        for (auto it = states.crbegin(); it != states.crend(); ++it) {
            if (it->first == s)
                return it->second;
        }
        return {};
    }
    qsizetype samplesAfter(double t) const
    {
        return std::count_if(samples.cbegin(), samples.cend(),
                             [t](const Sample &s) { return s.t_s > t; });
    }
    double lastT() const { return samples.isEmpty() ? -1.0 : samples.last().t_s; }
    ~Harness() { QObject::disconnect(&session, nullptr, nullptr, nullptr); }
};

} // namespace hatpic::test
