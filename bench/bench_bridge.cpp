// bench_bridge [--seconds S] [--steps N] [--feedback-rate HZ]
//
// The robot bridge on this machine, over Cyclone DDS on loopback (lo only, no multicast):
//   rate:    messages per second a subscriber receives on /hatpic/joint_states with the
//            default --rate (100 Hz) and with every sample (1000 Hz), the simulated joystick
//            behind a real pseudo-terminal streaming 1 kHz telemetry;
//   latency: wrench → τ_ext: from dds_write of a WrenchStamped to the first control cycle of
//            the simulated device that renders the new τ_ext — the first telemetry sample that
//            shows it, dated by the device clock relative to its batch's arrival — for N steps
//            between +0.5 N and −0.5 N, 100 ms apart, with the session streaming SET_FEEDBACK
//            at HZ (default 100, hatpic-bridge's default). Prints median and maximum, and
//            the same up to the Bridge's feedbackChanged (the DDS part alone).
// Everything but the session's thread runs on one event loop: the figures include its waits.
#include "bridge/bridge.h"
#include "session/deviceclient.h"
#include "sim/simulatorhost.h"

#include "rosmessages.h"

#include <dds/dds.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace hatpic;
using namespace hatpic::bridge;

namespace {

constexpr int kDomain = 73;

void confineToLoopback()
{
    qputenv("CYCLONEDDS_URI",
            "<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface name=\"lo\"/>"
            "</Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery>"
            "<ParticipantIndex>auto</ParticipantIndex><Peers><Peer Address=\"127.0.0.1\"/>"
            "</Peers></Discovery></Domain></CycloneDDS>");
}

void waitMs(int ms)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
}

int takeCount(dds_entity_t reader)
{
    int count = 0;
    for (;;) {
        void *samples[64] = {};
        dds_sample_info_t infos[64];
        const dds_return_t n = dds_take(reader, samples, infos, 64, 64);
        if (n <= 0)
            return count;
        for (int i = 0; i < n; ++i)
            count += infos[i].valid_data ? 1 : 0;
        dds_return_loan(reader, samples, n);
    }
}

} // namespace

int main(int argc, char *argv[])
{
    confineToLoopback();
    QCoreApplication app(argc, argv);
    registerSessionMetaTypes();
    double seconds = 5;
    int steps = 200;
    double feedbackRate = 100;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (QByteArray(argv[i]) == "--seconds")
            seconds = std::atof(argv[i + 1]);
        else if (QByteArray(argv[i]) == "--steps")
            steps = std::atoi(argv[i + 1]);
        else if (QByteArray(argv[i]) == "--feedback-rate")
            feedbackRate = std::atof(argv[i + 1]);
    }

    SimulatorHost host(SimulatedDevice::Config{});
    if (const QString error = host.start(); !error.isEmpty()) {
        std::fprintf(stderr, "bench_bridge: %s\n", qPrintable(error));
        return 1;
    }
    DeviceClient client;
    ConnectOptions options;
    options.port = host.slavePath();
    options.feedbackRateHz = feedbackRate;
    client.connectDevice(options);
    while (client.state() != SessionState::Connected)
        waitMs(10);

    const dds_entity_t participant = dds_create_participant(kDomain, nullptr, nullptr);
    dds_qos_t *qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1000);
    const dds_entity_t joints =
        dds_create_reader(participant,
                          dds_create_topic(participant, &sensor_msgs_msg_dds__JointState__desc,
                                           "rt/hatpic/joint_states", nullptr, nullptr),
                          qos, nullptr);
    const dds_entity_t wrench =
        dds_create_writer(participant,
                          dds_create_topic(participant, &geometry_msgs_msg_dds__WrenchStamped__desc,
                                           "rt/wrench_estimation", nullptr, nullptr),
                          qos, nullptr);
    dds_delete_qos(qos);

    Bridge bridge(client);
    for (const double rate : {100.0, 1000.0}) {
        BridgeSettings settings;
        settings.domainId = kDomain;
        settings.publishRateHz = rate;
        if (const QString error = bridge.start(settings); !error.isEmpty()) {
            std::fprintf(stderr, "bench_bridge: %s\n", qPrintable(error));
            return 1;
        }
        waitMs(1000); // discovery, then a clean window
        takeCount(joints);
        QElapsedTimer window;
        window.start();
        int received = 0;
        while (window.elapsed() < seconds * 1000) {
            waitMs(50);
            received += takeCount(joints);
        }
        std::printf("rate --rate %g: %.1f messages/s received on /hatpic/joint_states\n", rate,
                    received / (double(window.nsecsElapsed()) * 1e-9));
    }

    dds_publication_matched_status_t matched{};
    while (dds_get_publication_matched_status(wrench, &matched) == DDS_RETCODE_OK &&
           matched.current_count == 0)
        waitMs(10);
    std::vector<double> latencies;
    QElapsedTimer since;
    double expected = 0, deviceMs = -1;
    // The first sample that shows the new τ_ext, dated back from its batch's arrival by how
    // much older than the batch's newest sample it is (device clock).
    QObject::connect(&client, &DeviceClient::samplesReady, &app, [&](const SampleBatch &batch) {
        const double arrivalMs = double(since.nsecsElapsed()) * 1e-6;
        for (const Sample &s : batch) {
            if (deviceMs < 0 && std::abs(s.tau_ext - expected) < 1e-6)
                deviceMs = arrivalMs - (batch.last().t_s - s.t_s) * 1e3;
        }
    });
    for (int i = 0; i < steps; ++i) {
        const double force = (i % 2 == 0) ? 0.5 : -0.5;
        geometry_msgs_msg_dds__WrenchStamped_ w{};
        w.header.frame_id = const_cast<char *>("bench");
        w.wrench.force.z = force;
        deviceMs = -1;
        expected = 0.154 * force;
        since.start();
        dds_write(wrench, &w);
        while (deviceMs < 0 && since.elapsed() < 1000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
        latencies.push_back(deviceMs < 0 ? 1000.0 : deviceMs);
        waitMs(100);
    }
    std::sort(latencies.begin(), latencies.end());
    std::printf("latency wrench -> tau_ext at the device: median %.2f ms, max %.2f ms (%d steps, "
                "SET_FEEDBACK at %g Hz)\n",
                latencies[latencies.size() / 2], latencies.back(), steps, feedbackRate);
    bridge.stop();
    dds_delete(participant);
    client.disconnectDevice();
    return 0;
}
