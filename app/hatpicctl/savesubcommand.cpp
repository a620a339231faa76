// hatpicctl save: persist the device's parameters across power-up (SAVE_PARAMS).
#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "subcommands.h"

#include <QCommandLineParser>

namespace hatpic::cli {

namespace {

class SaveSubcommand final : public DeviceSubcommand
{
public:
    QString name() const override { return QStringLiteral("save"); }
    QString summary() const override
    {
        return QStringLiteral("Make the device keep its current parameters at power-up.");
    }
    QString synopsis() const override { return QStringLiteral("save --port PORT"); }
    QString description() const override
    {
        return QStringLiteral("Sends SAVE_PARAMS. Prints nothing on stdout.\n\n") + portHelp();
    }

protected:
    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        Q_UNUSED(parser);
        Outcome result;
        if (const int code = runner.runCommand(request::Save{}, &result); code)
            return code;
        if (const int code = DeviceRunner::reportOutcome(result); code)
            return code;
        printNote(QStringLiteral("The device saved its parameters."));
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeSaveSubcommand()
{
    return std::make_unique<SaveSubcommand>();
}

} // namespace hatpic::cli
