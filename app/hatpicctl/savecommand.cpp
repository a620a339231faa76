// hatpicctl save: persist the device's parameters across power-up (SAVE_PARAMS).
#include "commands.h"
#include "common/exitcodes.h"
#include "console.h"
#include "devicecommand.h"
#include "devicerunner.h"

#include <QCommandLineParser>

namespace hatpic::cli {

namespace {

class SaveCommand final : public DeviceCommand
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
        CommandResult result;
        if (const int code = runner.runCommand(&DeviceClient::saveParams, &result); code)
            return code;
        if (const int code = DeviceRunner::reportResult(result); code)
            return code;
        printNote(QStringLiteral("The device saved its parameters."));
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Command> makeSaveCommand()
{
    return std::make_unique<SaveCommand>();
}

} // namespace hatpic::cli
