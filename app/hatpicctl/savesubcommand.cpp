// hatpicctl save: persist the device's parameters across power-up (SAVE_PARAMS).
#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "subcommands.h"

#include <QCommandLineParser>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

class SaveSubcommand final : public DeviceSubcommand
{
public:
    SaveSubcommand()
        : DeviceSubcommand(
              {.name = u"save"_s,
               .summary = u"Make the device keep its current parameters at power-up."_s,
               .synopsis = u"save --port PORT"_s,
               .description = u"Sends SAVE_PARAMS. Prints nothing on stdout."_s})
    {}

protected:
    int runConnected(DeviceRunner &runner, const QCommandLineParser &) override
    {
        Outcome result;
        if (const int code = runner.runCommand(request::Save{}, &result); code)
            return code;
        if (const int code = DeviceRunner::reportOutcome(result); code)
            return code;
        printNote(u"The device saved its parameters."_s);
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeSaveSubcommand()
{
    return std::make_unique<SaveSubcommand>();
}

} // namespace hatpic::cli
