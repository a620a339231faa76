/* ddspeer [--domain ID] [--seconds S] [--windows K] [--wait-for N]
 *
 * The plainest ROS 2 peer of hatpic-bridge: a C program on Cyclone DDS's own API with its own
 * IDL-generated types, without type information (tests/core/bridge/rostestmessages.idl, as
 * rmw_cyclonedds registers its types), at normal priority, reading /hatpic/joint_states
 * (DDS topic rt/hatpic/joint_states) with ROS 2's default subscription QoS (reliable, volatile,
 * keep last 10) and a waitset, as an rclcpp executor waits. Nothing of the project's code is
 * in it.
 *
 * It waits until N JointStates (default 1000) have arrived, prints "ready", then measures K
 * windows (default 3) of S seconds (default 40): for every JointState, its arrival (wall clock,
 * CLOCK_REALTIME, read as take() returns) minus its header.stamp, which hatpic-bridge sets to
 * the wall-clock time at which the sample's frame was decoded. One row per window and the
 * worst of them; exit 1 when nothing arrives. The environment's CYCLONEDDS_URI says where it
 * looks (bench/bridge-as-peer confines it to lo).
 */
#include "rostestmessages.h"

#include <dds/dds.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { kBatch = 64 };

static double wallSeconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_REALTIME, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int compareDoubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Nearest-rank percentile of n sorted values. */
static double percentile(const double *sorted, size_t n, double p)
{
    if (n == 0)
        return NAN;
    size_t rank = (size_t)ceil(p * (double)n);
    if (rank < 1)
        rank = 1;
    if (rank > n)
        rank = n;
    return sorted[rank - 1];
}

struct Latencies
{
    double *ms;
    size_t count, capacity;
    unsigned long long seen;
};

/* Takes every JointState waiting; when `into` has room, records each one's latency [ms]. */
static void takeAll(dds_entity_t reader, struct Latencies *into, int recording)
{
    for (;;) {
        void *samples[kBatch] = {0};
        dds_sample_info_t infos[kBatch];
        const dds_return_t n = dds_take(reader, samples, infos, kBatch, kBatch);
        if (n <= 0)
            return;
        const double now = wallSeconds();
        for (int i = 0; i < n; ++i) {
            if (!infos[i].valid_data)
                continue;
            const sensor_msgs_msg_dds__JointState_ *joints = samples[i];
            ++into->seen;
            if (recording && into->count < into->capacity) {
                const double stamp =
                    (double)joints->header.stamp.sec + (double)joints->header.stamp.nanosec * 1e-9;
                into->ms[into->count++] = (now - stamp) * 1e3;
            }
        }
        dds_return_loan(reader, samples, n);
    }
}

/* Waits on the waitset until `until` (wall clock) and takes what arrives. */
static void pump(dds_entity_t waitset, dds_entity_t reader, struct Latencies *into, int recording,
                 double until)
{
    for (double now = wallSeconds(); now < until; now = wallSeconds()) {
        const dds_duration_t left = (dds_duration_t)((until - now) * 1e9);
        if (dds_waitset_wait(waitset, NULL, 0, left < DDS_MSECS(100) ? left : DDS_MSECS(100)) > 0)
            takeAll(reader, into, recording);
    }
}

static int usage(const char *bad)
{
    fprintf(stderr,
            "ddspeer: bad option %s; usage: ddspeer [--domain ID] [--seconds S] [--windows K] "
            "[--wait-for N]\n",
            bad);
    return 4;
}

int main(int argc, char *argv[])
{
    int domain = 81, windows = 3;
    double seconds = 40;
    unsigned long long waitFor = 1000;
    for (int i = 1; i < argc; ++i) {
        if (i + 1 >= argc)
            return usage(argv[i]);
        const char *name = argv[i], *value = argv[++i];
        if (strcmp(name, "--domain") == 0 && atoi(value) >= 0)
            domain = atoi(value);
        else if (strcmp(name, "--seconds") == 0 && atof(value) > 0)
            seconds = atof(value);
        else if (strcmp(name, "--windows") == 0 && atoi(value) > 0)
            windows = atoi(value);
        else if (strcmp(name, "--wait-for") == 0 && atoi(value) > 0)
            waitFor = (unsigned long long)atoi(value);
        else
            return usage(name);
    }

    const dds_entity_t participant = dds_create_participant((dds_domainid_t)domain, NULL, NULL);
    if (participant < 0) {
        fprintf(stderr, "ddspeer: no participant: %s\n", dds_strretcode(participant));
        return 1;
    }
    const dds_entity_t topic = dds_create_topic(participant, &sensor_msgs_msg_dds__JointState__desc,
                                                "rt/hatpic/joint_states", NULL, NULL);
    /* ROS 2's default subscription: reliable, volatile, keep last 10 (rmw_cyclonedds'
       create_readwrite_qos of rmw_qos_profile_default). */
    dds_qos_t *qos = dds_create_qos();
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 10);
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_INFINITY);
    dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    const dds_entity_t reader = dds_create_reader(participant, topic, qos, NULL);
    dds_delete_qos(qos);
    const dds_entity_t waitset = dds_create_waitset(participant);
    const dds_entity_t readable = dds_create_readcondition(reader, DDS_ANY_STATE);
    if (topic < 0 || reader < 0 || waitset < 0 || readable < 0 ||
        dds_waitset_attach(waitset, readable, reader) < 0) {
        fprintf(stderr, "ddspeer: cannot read rt/hatpic/joint_states\n");
        dds_delete(participant);
        return 1;
    }

    const size_t capacity = (size_t)(seconds * 1500) + 1000;
    struct Latencies latencies = {calloc(capacity, sizeof(double)), 0, capacity, 0};
    const double readyBy = wallSeconds() + 30;
    while (latencies.seen < waitFor && wallSeconds() < readyBy)
        pump(waitset, reader, &latencies, 0, wallSeconds() + 0.05);
    if (latencies.seen < waitFor) {
        fprintf(stderr, "ddspeer: no JointState arrives on rt/hatpic/joint_states\n");
        dds_delete(participant);
        return 1;
    }
    printf("ready\n");
    fflush(stdout);

    printf("%-32s %7s %8s %8s %8s %8s\n", "knob -> /hatpic/joint_states", "count", "p50", "p95",
           "p99", "max");
    double worstP99 = 0, worstRate = INFINITY;
    for (int w = 0; w < windows; ++w) {
        latencies.count = 0;
        const double start = wallSeconds();
        pump(waitset, reader, &latencies, 1, start + seconds);
        const double span = wallSeconds() - start;
        qsort(latencies.ms, latencies.count, sizeof(double), compareDoubles);
        const double p99 = percentile(latencies.ms, latencies.count, 0.99);
        const double rate = (double)latencies.count / span;
        char label[16];
        snprintf(label, sizeof label, "[%d]", w + 1);
        printf("%-32s %7zu %8.2f %8.2f %8.2f %8.2f  %.1f messages/s over %.1f s\n", label,
               latencies.count, percentile(latencies.ms, latencies.count, 0.50),
               percentile(latencies.ms, latencies.count, 0.95), p99,
               latencies.count ? latencies.ms[latencies.count - 1] : NAN, rate, span);
        fflush(stdout);
        worstP99 = latencies.count && p99 > worstP99 ? p99 : worstP99;
        worstRate = rate < worstRate ? rate : worstRate;
    }
    printf("worst of %d windows: p99 %.2f ms, %.1f messages/s\n", windows, worstP99, worstRate);
    free(latencies.ms);
    dds_delete(participant);
    return 0;
}
