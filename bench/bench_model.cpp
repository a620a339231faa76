// bench_model [--steps N]
//
// One step of the haptic model (model.md: K_rec, τ_rec, the admittance filter) on this
// machine, in the forms the programs run it (docs/performance.md, "The model step"):
//   from the parameters: recenteringTorque(DeviceParams, θ) and admittanceStep(DeviceParams,
//           …), which derive everything (e^{−αh}, φ1, φ2) from the parameter set at each step;
//   precomputed: StiffnessShape<T> and AdmittanceStepper<T> made once per parameter change,
//           then a step in double (host, simulator) and in float (the ESP32's FPU);
//   device cycle: fw::Controller<T>::cycle, the whole model as the device core runs it (K_rec,
//           τ_rec, effects, τ_total, flags, one admittance step) against an actuator that
//           only hands back a measurement;
//   host per sample: SampleBuilder::fromTelemetry (session clock, τ_total, v_ref, p_ref) and
//           fromLegacy (θ from ticks, K_rec and τ_rec estimated, flags, v_ref, p_ref), what the
//           session thread runs for each frame.
// The angles sweep the dead zone, the notch band and the outer zone. Prints ns of CPU time
// per step (best of 5 runs).
#include "benchactuator.h"
#include "benchclock.h"

#include "firmware/controller.h"
#include "model/admittance.h"
#include "model/stiffness.h"
#include "session/samplebuilder.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace hatpic;

namespace {

constexpr std::size_t kAngles = 4096;
constexpr double kPeriod = 1e-3; //!< [s]

//! A slow swing over ±0.3 rad: a third of the steps in each zone of the default parameters.
std::array<double, kAngles> angles()
{
    std::array<double, kAngles> a{};
    for (std::size_t i = 0; i < kAngles; ++i)
        a[i] = 0.3 * std::sin(2.0 * 3.141592653589793 * double(i) / double(kAngles));
    return a;
}

//! θ of the k-th cycle: the sweep of angles(), over and over.
struct AngleAt
{
    const std::array<double, kAngles> *theta;
    double operator()(std::size_t k) const { return (*theta)[k % kAngles]; }
};

double g_sink = 0; //!< keeps results alive

template<typename T> double precomputed(const std::array<double, kAngles> &theta, long steps)
{
    std::array<T, kAngles> th{};
    for (std::size_t i = 0; i < kAngles; ++i)
        th[i] = T(theta[i]);
    const DeviceParams p;
    const StiffnessShape<T> shape = StiffnessShape<T>::from(p);
    const AdmittanceStepper<T> stepper(AdmittanceCoefficients::compute(p, kPeriod));
    return benchclock::bestNsPer(steps, [&](long n) {
        BasicAdmittanceState<T> s;
        for (long i = 0; i < n; ++i) {
            const T tauRec = recenteringTorque(shape, th[std::size_t(i) % kAngles]);
            s = stepper.step(s, T(0.02) + tauRec);
        }
        g_sink += double(s.theta);
    });
}

template<typename T> double deviceCycle(const std::array<double, kAngles> &theta, long steps)
{
    bench::CannedActuator<T, AngleAt> replay(AngleAt{&theta});
    fw::Controller<T> controller({}, replay);
    controller.start(DeviceParams{}, 0);
    std::uint32_t now = 0;
    const double ns = benchclock::bestNsPer(steps, [&](long n) {
        for (long i = 0; i < n; ++i)
            controller.cycle(now += 1000);
    });
    g_sink += double(replay.sink());
    return ns;
}

} // namespace

int main(int argc, char **argv)
{
    long steps = 4'000'000;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--steps") == 0)
            steps = std::max(10L, std::atol(argv[i + 1]));
    }
    const std::array<double, kAngles> theta = angles();
    std::printf("model step, %ld steps per run, CPU time of this thread, best of 5\n", steps);

    const DeviceParams params;
    const double fromParams = benchclock::bestNsPer(steps / 4, [&](long n) {
        AdmittanceState s;
        for (long i = 0; i < n; ++i) {
            const double tauRec = recenteringTorque(params, theta[std::size_t(i) % kAngles]);
            s = admittanceStep(params, s, 0.02 + tauRec, kPeriod);
        }
        g_sink += s.theta;
    });
    std::printf("%-52s %6.1f ns\n", "K_rec + tau_rec + admittance, from the parameters",
                fromParams);
    std::printf("%-52s %6.1f ns\n", "K_rec + tau_rec + admittance, precomputed, double",
                precomputed<double>(theta, steps));
    std::printf("%-52s %6.1f ns\n", "K_rec + tau_rec + admittance, precomputed, float",
                precomputed<float>(theta, steps));
    std::printf("%-52s %6.1f ns\n", "device cycle (Controller<double>::cycle)",
                deviceCycle<double>(theta, steps));
    std::printf("%-52s %6.1f ns\n", "device cycle (Controller<float>::cycle)",
                deviceCycle<float>(theta, steps));

    SampleBuilder builder;
    builder.setDeviceParams(params);
    v2::Telemetry tm;
    const double host = benchclock::bestNsPer(steps, [&](long n) {
        double sum = 0;
        for (long i = 0; i < n; ++i) {
            tm.t_us += 1000;
            tm.theta = float(theta[std::size_t(i) % kAngles]);
            sum += builder.fromTelemetry(tm, qint64(tm.t_us)).p_ref;
        }
        g_sink += sum;
    });
    std::printf("%-52s %6.1f ns\n", "host per sample (SampleBuilder::fromTelemetry)", host);

    builder.clear();
    const legacy::Conversion conversion;
    std::array<legacy::Frame, kAngles> frames{};
    for (std::size_t i = 0; i < kAngles; ++i)
        frames[i].a = conversion.radToTicks(theta[i]);
    const double legacyNs = benchclock::bestNsPer(steps, [&](long n) {
        double sum = 0;
        for (long i = 0; i < n; ++i) {
            sum +=
                builder
                    .fromLegacy(frames[std::size_t(i) % kAngles], conversion, {}, qint64(i) * 1000)
                    .tau_rec;
        }
        g_sink += sum;
    });
    std::printf("%-52s %6.1f ns\n", "host per legacy sample (SampleBuilder::fromLegacy)", legacyNs);
    std::printf("(sink %g)\n", g_sink);
    return 0;
}
