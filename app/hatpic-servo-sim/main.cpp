// hatpic-servo-sim: an emulated Feetech STS3032 on a pseudo-terminal, in real time — the servo
// bus of servo.md for hatpic-fw-host to drive without hardware.
//
// Prints the slave path as the first stdout line, then runs until SIGINT/SIGTERM (exit 0).
// Changes of the torque enable register are reported on stderr ("torque on" / "torque off").
// Bad options: one sentence on stderr, exit 4. Runtime failure (no pty, no link): exit 1.
#include "common/ptyprogram.h"
#include "sim/servobushost.h"
#include "sim/simulateddevice.h"

#include <QCoreApplication>

#include <cstdio>

using namespace hatpic;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    PtyProgram program(app, "hatpic-servo-sim",
                       QStringLiteral("Emulated STS3032 servo (bus of servo.md) on a "
                                      "pseudo-terminal."));
    program.add(SharedOption::Hand);
    program.add(SharedOption::Seed, "Seed of the load-reading noise.");
    program.add(SharedOption::ServoId, "Servo id on the bus, 0…253 (default 1).");
    program.add(SharedOption::CenterTick,
                "Present position at the knob's rest, 0…4095 (default 1000).");
    program.add(SharedOption::Link);

    ServoBusHost::Config config;
    config.noise = SimulatedDevice::kProgramNoise;
    if (!program.parse() || !program.readHand(config.hand) || !program.readSeed(config.seed) ||
        !program.readServoId(config.id) || !program.readCenterTick(config.centerTick) ||
        !program.readLink())
        return PtyProgram::kExitBadOptions;

    ServoBusHost host(config);
    const Serving serving = program.serve(host); // after the host, which it must not outlive
    if (!serving)
        return PtyProgram::kExitFailure;
    QObject::connect(&host, &ServoBusHost::torqueEnableChanged, &app, [](bool enabled) {
        std::fprintf(stderr, "hatpic-servo-sim: torque %s\n", enabled ? "on" : "off");
    });
    std::fprintf(stderr, "hatpic-servo-sim: STS3032 id %d, center tick %d, hand %s; torque %s\n",
                 int(config.id), int(config.centerTick), qPrintable(config.hand.toSpec()),
                 host.torqueEnabled() ? "on" : "off");

    const int code = app.exec();
    host.stop();
    return PtyProgram::exitCode(code);
}
