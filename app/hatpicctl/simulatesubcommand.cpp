// hatpicctl simulate: the simulated joystick's response to a hand input, offline, as CSV.
#include "common/exitcodes.h"
#include "console.h"
#include "profileinput.h"
#include "subcommand.h"
#include "subcommands.h"

#include "sim/offlinesimulation.h"
#include "telemetry/samplecolumns.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <cmath>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

constexpr double kDefaultDuration = 2.0; //!< [s]
constexpr double kDefaultRate = 1000;    //!< [Hz]

class SimulateSubcommand final : public Subcommand
{
public:
    SimulateSubcommand()
        : Subcommand(
              {.name = u"simulate"_s,
               .summary = u"Simulate the joystick's response to a hand input (CSV)."_s,
               .synopsis = u"simulate --profile FILE --input SPEC [--duration S] [--rate HZ] "
                           "[--ideal]"_s,
               .description =
                   u"Runs the simulated joystick offline (no device, no clock) with the profile's\n"
                   "device parameters and tau_limit, and prints one CSV row per control step:\n"_s +
                   QString::fromLatin1(sampleCsvHeader()) +
                   u"\n"
                   "from t = 0 (theta = theta0, omega = 0) to t = DURATION inclusive. v_ref and\n"
                   "p_ref come from the profile's host settings. tau is the measured interaction\n"
                   "torque; the operator's torque is -tau.\n"
                   "\n"
                   "SPEC is the operator's torque on the knob [N·m]; positive pushes theta up:\n"
                   "  idle             no hand\n"
                   "  const:T          T from t = 0\n"
                   "  step:T[:T0[:AT]] T0 (default 0) until t = AT (default 0.1 s), then T\n"
                   "  sine:A:F         A·sin(2π·F·t), F in Hz\n"
                   "  chirp:A:F0:F1    sine sweeping linearly from F0 to F1 Hz every 10 s\n"
                   "  hand:ANGLE       a virtual hand (spring 2 N·m/rad, damper 0.05 N·m·s/rad)\n"
                   "                   holding the knob toward ANGLE [rad, absolute]\n"
                   "\n"
                   "The profile's effects (device.effects, docs/effects.md) are rendered too and\n"
                   "reported in tau_fx.\n"
                   "\n"
                   "--ideal removes the servo's lag, tick quantisation and load-reading noise, so\n"
                   "the rows are the model of docs/model.md (with its effects) alone."_s})
    {}
    void addOptions(QCommandLineParser &parser) override
    {
        parser.addOption(QCommandLineOption(u"profile"_s, u"The profile (required)."_s, u"FILE"_s));
        parser.addOption({u"input"_s, u"The hand input (required)."_s, u"SPEC"_s});
        parser.addOption({u"duration"_s, u"Simulated time in seconds (default: 2)."_s, u"S"_s});
        parser.addOption(
            QCommandLineOption(u"rate"_s,
                               u"Control rate in Hz, one row per step (default: 1000, at most "
                               "65535)."_s,
                               u"HZ"_s));
        parser.addOption({u"ideal"_s, u"No servo lag, quantisation or noise: the model alone."_s});
        parser.addOption(
            QCommandLineOption(u"noise"_s,
                               u"Load-reading noise std-dev in N·m (default: 0; ignored with "
                               "--ideal)."_s,
                               u"NM"_s));
        parser.addOption(QCommandLineOption(u"seed"_s, u"Noise seed (default: 1)."_s, u"N"_s));
    }

    int run(const QCommandLineParser &parser) override
    {
        if (!parser.isSet(u"profile"_s) || !parser.isSet(u"input"_s)) {
            printError(u"simulate needs --profile FILE and --input SPEC."_s);
            return ExitBadUsage;
        }
        OfflineSimulationConfig config;
        config.duration = kDefaultDuration;
        config.rateHz = kDefaultRate;
        config.ideal = parser.isSet(u"ideal"_s);

        QString error;
        const auto hand = HandInput::parse(parser.value(u"input"_s), &error);
        if (!hand) {
            printError(asSentence(error));
            return ExitBadUsage;
        }
        config.hand = *hand;

        for (auto [option, target] :
             {std::pair{u"duration"_s, &config.duration}, std::pair{u"rate"_s, &config.rateHz},
              std::pair{u"noise"_s, &config.noise}}) {
            if (!parser.isSet(option))
                continue;
            bool ok = false;
            *target = parser.value(option).toDouble(&ok);
            if (!ok) {
                printError(u"--" + option + u" must be a number, got '" + parser.value(option) +
                           u"'.");
                return ExitBadUsage;
            }
        }
        if (parser.isSet(u"seed"_s)) {
            bool ok = false;
            config.seed = parser.value(u"seed"_s).toULongLong(&ok);
            if (!ok) {
                printError(u"--seed " + unreadNumber(u"a whole number from 0 to "
                                                     "18446744073709551615"_s,
                                                     parser.value(u"seed"_s), true));
                return ExitBadUsage;
            }
        }

        const auto profile = loadProfile(parser.value(u"profile"_s));
        if (!profile)
            return ExitBadUsage;
        config.device = profile->device;
        config.effects = profile->effects;
        config.host = profile->host;

        if (const QString problem = OfflineSimulation::check(config); !problem.isEmpty()) {
            printError(problem);
            return ExitBadUsage;
        }

        OfflineSimulation simulation(config);
        writeOut(sampleCsvHeader() + '\n');
        QByteArray chunk;
        while (!simulation.atEnd()) {
            const Sample sample = simulation.next();
            if (simulation.failed())
                break; // that row is not a result
            appendSampleCsvRow(chunk, sample);
            chunk += '\n';
            if (chunk.size() > 1 << 16) {
                writeOut(chunk);
                chunk.clear();
            }
        }
        writeOut(chunk);
        if (simulation.failed()) {
            printError(simulation.problem());
            return ExitBadUsage;
        }
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeSimulateSubcommand()
{
    return std::make_unique<SimulateSubcommand>();
}

} // namespace hatpic::cli
