// hatpicctl vibrate: a vibration cue on the knob (VIBRATE, effects.md § 1).
#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "subcommands.h"

#include "model/effects.h"
#include "telemetry/numbertext.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <array>
#include <limits>
#include <utility>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

class VibrateSubcommand final : public DeviceSubcommand
{
public:
    VibrateSubcommand()
        : DeviceSubcommand(
              {.name = u"vibrate"_s,
               .summary = u"Play a vibration cue on the knob (devices with effects)."_s,
               .synopsis =
                   u"vibrate --port PORT --amplitude NM --frequency HZ --duration S [--knob N]"_s,
               .description =
                   u"Sends VIBRATE and waits for the device's ACK: the knob renders\n"
                   "a·sin(2π·f·t) for d seconds on top of everything else. The amplitude is at\n"
                   "most the device's tau_limit [N·m], the frequency 1 … 500 Hz and below half\n"
                   "the device's control rate (only the device knows it: it refuses with exit\n"
                   "2), the duration 0 … 10 s. Amplitude 0 stops a running cue. A new cue\n"
                   "replaces the running one. Fire and forget: the command returns once the\n"
                   "device has acknowledged, not when the cue ends. The published firmware and\n"
                   "devices without the effects capability cannot vibrate (exit 2). On a\n"
                   "device with several knobs, --knob N plays it on knob N alone."_s},
              Knobs::One)
    {}

protected:
    void addCommandOptions(QCommandLineParser &parser) override
    {
        parser.addOption({u"amplitude"_s, u"Amplitude a in N·m (required)."_s, u"NM"_s});
        parser.addOption({u"frequency"_s, u"Frequency f in Hz (required)."_s, u"HZ"_s});
        parser.addOption({u"duration"_s, u"Duration d in s (required)."_s, u"S"_s});
    }

    int prepare(const QCommandLineParser &parser, DeviceOptions &) override
    {
        const std::array options3 = {std::pair{u"amplitude"_s, &m_cue.amplitude},
                                     std::pair{u"frequency"_s, &m_cue.frequency},
                                     std::pair{u"duration"_s, &m_cue.duration}};
        for (const auto &[option, target] : options3) {
            if (!parser.isSet(option)) {
                printError(u"vibrate needs --amplitude NM, --frequency HZ and --duration S."_s);
                return ExitBadUsage;
            }
            bool ok = false;
            *target = parser.value(option).toDouble(&ok);
            if (!ok) {
                printError(u"--" + option + u' ' +
                           unreadNumber(u"a number"_s, parser.value(option)));
                return ExitBadUsage;
            }
        }
        // Every rule that does not depend on the device (NaN, the ranges, an amplitude that
        // travels as 0), before any port is opened; the torque limit and the control rate
        // are the device's, checked once it answered.
        const auto violations = validate(m_cue, std::numeric_limits<double>::infinity(),
                                         std::numeric_limits<double>::infinity());
        if (!violations.empty()) {
            printError(u"The vibration cue is not valid; nothing was sent:"_s);
            for (const Violation &violation : violations)
                printNote(u"  " + QString::fromStdString(violation.message()));
            return ExitBadUsage;
        }
        return ExitSuccess;
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &) override
    {
        Outcome result;
        const Vibration cue = m_cue;
        if (const int code = runner.runCommand(request::Vibrate{cue, knob()}, &result); code)
            return code;
        if (const int code = DeviceRunner::reportOutcome(result); code)
            return code;
        printNote((knob() ? u"Knob %1 plays the cue: "_s.arg(int(knob()) + 1)
                          : u"The device plays the cue: "_s) +
                  compactNumberText(cue.amplitude) + u" N·m at " +
                  compactNumberText(cue.frequency) + u" Hz for " + compactNumberText(cue.duration) +
                  u" s.");
        return ExitSuccess;
    }

private:
    Vibration m_cue;
};

} // namespace

std::unique_ptr<Subcommand> makeVibrateSubcommand()
{
    return std::make_unique<VibrateSubcommand>();
}

} // namespace hatpic::cli
