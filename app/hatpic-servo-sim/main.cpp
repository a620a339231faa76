// hatpic-servo-sim: an emulated Feetech STS3032 on a pseudo-terminal, in real time — the servo
// bus of servo.md for hatpic-fw-host to drive without hardware; with --servos N, N of them on
// one bus (ids ID … ID + N − 1), each with a knob and a hand of its own, as on the IMU
// branch's board.
//
// Prints the slave path as the first stdout line, then runs until SIGINT/SIGTERM (exit 0).
// Changes of the torque enable register are reported on stderr ("torque on" / "torque off";
// with several servos "id 2 torque on").
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
    program.add(SharedOption::Servos, "Servos on the bus, 1 to 4, with ids ID, ID + 1, … "
                                      "(default 1; 4: the IMU branch's board).");
    const PtyProgram::OtherHandOptions otherHands = program.addOtherHands("--servos 2 or more");
    program.add(SharedOption::Seed, "Seed of the load-reading noise.");
    program.add(SharedOption::ServoId, "Servo id on the bus (the first's), 0…253 (default 1).");
    program.add(SharedOption::CenterTick,
                "Present position at the knob's rest, 0…4095 (default 1000).");
    program.add(SharedOption::Link);

    ServoBusHost::Config config;
    config.noise = SimulatedDevice::kProgramNoise;
    if (!program.parse() || !program.readHand(config.hand) ||
        !program.readOtherHands(otherHands, config.otherHands) || !program.readSeed(config.seed) ||
        !program.readServoId(config.id) || !program.readServos(config.id, config.servos) ||
        !program.readCenterTick(config.centerTick) || !program.readLink())
        return PtyProgram::kExitBadOptions;

    ServoBusHost host(config);
    const Serving serving = program.serve(host); // after the host, which it must not outlive
    if (!serving)
        return PtyProgram::kExitFailure;
    QObject::connect(
        &host, &ServoBusHost::torqueEnableChanged, &app, [&host, &config](int k, bool enabled) {
            if (host.servos() == 1)
                std::fprintf(stderr, "hatpic-servo-sim: torque %s\n", enabled ? "on" : "off");
            else
                std::fprintf(stderr, "hatpic-servo-sim: id %d torque %s\n", int(config.id) + k,
                             enabled ? "on" : "off");
        });
    for (int k = 0; k < host.servos(); ++k) {
        const HandInput &hand = k == 0 ? config.hand : config.otherHands[std::size_t(k - 1)];
        std::fprintf(stderr,
                     "hatpic-servo-sim: STS3032 id %d, center tick %d, hand %s; torque %s\n",
                     int(config.id) + k, int(config.centerTick), qPrintable(hand.toSpec()),
                     host.torqueEnabled(k) ? "on" : "off");
    }

    const int code = app.exec();
    host.stop();
    return PtyProgram::exitCode(code);
}
