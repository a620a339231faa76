// hatpicctl zero: make the knob's current angle the new center (ZERO).
#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "paramtext.h"
#include "subcommands.h"
#include "telemetry/numbertext.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

class ZeroSubcommand final : public DeviceSubcommand
{
public:
    ZeroSubcommand()
        : DeviceSubcommand(
              {.name = u"zero"_s,
               .summary = u"Make the current knob angle the center (theta0)."_s,
               .synopsis = u"zero --port PORT [--knob N] [--json]"_s,
               .description =
                   u"Sends ZERO, then prints the parameters read back (as 'get' does), whose\n"
                   "theta0 is the new center. Not saved across power-up until 'save'.\n"
                   "On a device with several knobs, --knob N zeroes knob N alone."_s},
              Knobs::One)
    {}

protected:
    void addCommandOptions(QCommandLineParser &parser) override { addJsonOption(parser); }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        Outcome result;
        if (const int code = runner.runCommand(request::Zero{knob()}, &result); code)
            return code;
        if (const int code = DeviceRunner::reportOutcome(result); code)
            return code;
        const DeviceParams params = result.received.params.value_or(DeviceParams{});
        printNote(u"The center" + ofKnob() + u" is now theta0 = " +
                  compactNumberText(params.theta0) + u" rad.");
        writeOut(tuningOutput(DeviceTuning{params, std::nullopt}, runner.client().deviceInfo(),
                              parser.isSet(u"json"_s)));
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeZeroSubcommand()
{
    return std::make_unique<ZeroSubcommand>();
}

} // namespace hatpic::cli
