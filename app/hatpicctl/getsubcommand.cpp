// hatpicctl get: the parameters the device renders now (GET_PARAMS).
#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "paramtext.h"
#include "subcommands.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

class GetSubcommand final : public DeviceSubcommand
{
public:
    GetSubcommand()
        : DeviceSubcommand(
              {.name = u"get"_s,
               .summary = u"Print the device's current parameters (text or JSON)."_s,
               .synopsis = u"get --port PORT [--knob N] [--json]"_s,
               .description =
                   u"Reads the parameters with GET_PARAMS. The text form has one line per\n"
                   "parameter: name, value, unit, meaning. --json prints a complete profile\n"
                   "that 'hatpicctl set --profile' accepts (host settings are defaults, with\n"
                   "the device's tau_limit). The device holds 32-bit floats; each is shown\n"
                   "as the shortest decimal that gives back that float. A device with the\n"
                   "effects capability is also asked for its effect block (GET_EFFECTS): seven\n"
                   "more lines, and the profile's device.effects. A device with the passivity\n"
                   "capability is asked for its passivity controller (GET_PASSIVITY): two more\n"
                   "lines (pc_damping_max, pc_reserve_max), and the profile's device.passivity.\n"
                   "The profile carries every block the device has, defaults included.\n"
                   "A device with several knobs keeps a tuning per knob: --knob N reads knob N's."_s},
              Knobs::One)
    {}

protected:
    void addCommandOptions(QCommandLineParser &parser) override { addJsonOption(parser); }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        Outcome result;
        if (const int code = runner.runCommand(request::Read{knob()}, &result); code)
            return code;
        if (const int code = DeviceRunner::reportOutcome(result); code)
            return code;
        // A device reporting NaN or values that break model.md is not printed as a profile
        // (nor as a table that looks fine): it is refused with what is wrong, block by block.
        const DeviceTuning &tuning = result.received;
        const DeviceInfo info = runner.client().deviceInfo();
        const auto refuse = [this](const QString &what, const QString &problem) {
            printError(u"The device reported " + what + ofKnob() + u" that are not valid: " +
                       problem + u'.');
            return ExitNoDevice;
        };
        if (const QString p = problemText(validate(tuning.params.value_or(DeviceParams{})));
            !p.isEmpty())
            return refuse(u"parameters"_s, p);
        if (tuning.effects) {
            if (const QString p = problemText(validate(*tuning.effects, info.tauLimit));
                !p.isEmpty())
                return refuse(u"effects"_s, p);
        }
        if (tuning.passivity) {
            if (const QString p = problemText(validate(*tuning.passivity)); !p.isEmpty())
                return refuse(u"passivity settings"_s, p);
        }
        writeOut(tuningOutput(tuning, info, parser.isSet(u"json"_s)));
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeGetSubcommand()
{
    return std::make_unique<GetSubcommand>();
}

} // namespace hatpic::cli
