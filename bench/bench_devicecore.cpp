// bench_devicecore [--cycles N]
//
// The device core's cost per control cycle on this machine, in the arithmetic each build
// runs: float (the ESP32's single-precision FPU) and double (hatpic-fw-host, the simulator).
//   model:  Controller::cycle with an actuator that only hands back a measurement — the
//           haptic model alone (K_rec, τ_total, flags, one admittance step);
//   bus:    DeviceCore::controlCycle + serviceHost with the real StsActuator/StsBus building
//           and parsing the READ and WRITE packets, and a TELEMETRY frame encoded per cycle,
//           against a servo that answers from canned registers (no bus time);
//   params: one parameter change (the coefficients computed in double).
// Prints ns of CPU time per operation (best of 5 runs, bench/benchclock.h).
#include "benchactuator.h"
#include "benchclock.h"
#include "devicecoretest.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace hatpic;
using namespace devicecoretest;

namespace {

//! θ of the k-th cycle: a ramp over −0.1 … 0.099 rad, over and over.
double angleAt(std::size_t k)
{
    return double(k % 200) * 1e-3 - 0.1;
}

using benchclock::bestNsPer;

template<typename T> void measure(const char *name, long cycles)
{
    bench::CannedActuator<T, double (*)(std::size_t)> replay(angleAt);
    fw::Controller<T> controller({}, replay);
    controller.start(DeviceParams{}, 0);
    std::uint32_t now = 0;
    const double model = bestNsPer(cycles, [&](long n) {
        for (long i = 0; i < n; ++i)
            controller.cycle(now += 1000);
    });

    CannedServo servo;
    FixedHostPort host;
    ManualClock clock;
    fw::StsBus bus(servo, 0);
    fw::StsActuator<T> actuator(bus, {});
    typename fw::DeviceCore<T>::Config config;
    config.firmware = "bench";
    fw::DeviceCore<T> core(config, host, actuator, clock, nullptr);
    core.start(0);
    v2::FrameBuffer frame;
    host.toDevice.push(std::span(frame).first(v2::encodeFrame(1, v2::SetStream{1000}, frame)));
    core.serviceHost();
    std::array<std::uint8_t, 4096> drain;
    const double full = bestNsPer(cycles, [&](long n) {
        for (long i = 0; i < n; ++i) {
            servo.setPresent(1000 + int(i % 64), 3, -40);
            core.controlCycle(clock.now += 1000);
            core.serviceHost();
            while (host.toHost.pop(drain) > 0) {
            }
        }
    });

    DeviceParams p;
    const double params = bestNsPer(cycles / 10, [&](long n) {
        for (long i = 0; i < n; ++i) {
            p.M_adm = 0.01 + 1e-9 * double(i % 100);
            controller.setParams(p);
        }
    });
    std::printf("%-7s model %7.1f ns/cycle   bus+telemetry %7.1f ns/cycle   "
                "parameter change %7.1f ns   (sink %g)\n",
                name, model, full, params, double(replay.sink()));
}

} // namespace

int main(int argc, char **argv)
{
    long cycles = 2'000'000;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--cycles") == 0)
            cycles = std::max(10L, std::atol(argv[i + 1]));
    }
    std::printf("device core, %ld cycles per run, best of 5\n", cycles);
    measure<float>("float", cycles);
    measure<double>("double", cycles);
    return 0;
}
