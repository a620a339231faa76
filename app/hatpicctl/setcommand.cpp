// hatpicctl set: push parameters (a profile, or single values over the device's current ones).
#include "commands.h"
#include "console.h"
#include "devicecommand.h"
#include "devicerunner.h"
#include "exitcode.h"
#include "paramtext.h"
#include "profileinput.h"

#include "model/params.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <optional>
#include <utility>

namespace hatpic::cli {

namespace {

struct Assignment
{
    int index = -1; //!< ParamBlock index
    double value = 0;
};

QString fieldNames()
{
    QStringList names;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const auto name = deviceFieldName(i);
        names << QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
    }
    return names.join(QStringLiteral(", "));
}

// "K_max=0.5" → {3, 0.5}; prints one sentence and gives nullopt when it is not that.
std::optional<Assignment> parseAssignment(const QString &text)
{
    const qsizetype equals = text.indexOf(u'=');
    if (equals <= 0) {
        printError(u"--set takes NAME=VALUE, got '" + text + u"'.");
        return std::nullopt;
    }
    const QString name = text.left(equals).trimmed();
    const QString valueText = text.mid(equals + 1).trimmed();
    const int index = deviceFieldIndex(name.toStdString());
    if (index < 0) {
        printError(u"Unknown parameter '" + name + u"' in --set; the parameters are " +
                   fieldNames() + u'.');
        return std::nullopt;
    }
    bool ok = false;
    const double value = valueText.toDouble(&ok);
    if (!ok) {
        printError(u"The value of " + name + u" in --set must be a number, got '" + valueText +
                   u"'.");
        return std::nullopt;
    }
    return Assignment{index, value};
}

class SetCommand final : public DeviceCommand
{
public:
    QString name() const override { return QStringLiteral("set"); }
    QString summary() const override
    {
        return QStringLiteral("Push parameters from a profile or as NAME=VALUE.");
    }
    QString synopsis() const override
    {
        return QStringLiteral("set --port PORT (--profile FILE | --set NAME=VALUE …) [--json]");
    }
    QString description() const override
    {
        return QStringLiteral(
                   "Sends SET_PARAMS and waits for the device's ACK, then prints the\n"
                   "parameters read back (as 'get' does). With --set alone, the device's current\n"
                   "parameters are read first (GET_PARAMS) and only the named ones change;\n"
                   "with --profile, the profile's device parameters are the starting point and\n"
                   "any --set applies on top. The whole set is validated before anything is\n"
                   "sent: a violation exits with 4 and the device is left untouched.\n"
                   "Names: ") +
               fieldNames() + u"\n\n" + portHelp();
    }

protected:
    void addCommandOptions(QCommandLineParser &parser) override
    {
        parser.addOption(QCommandLineOption(
            QStringList{QStringLiteral("profile")},
            QStringLiteral("Profile whose device parameters are sent."), QStringLiteral("FILE")));
        parser.addOption(QCommandLineOption(
            QStringList{QStringLiteral("set")},
            QStringLiteral("Set one parameter, e.g. K_max=0.5 (SI units). Repeatable."),
            QStringLiteral("NAME=VALUE")));
        parser.addOption(QCommandLineOption(QStringList{QStringLiteral("json")},
                                            QStringLiteral("Print a profile (JSON).")));
    }

    int prepare(const QCommandLineParser &parser, DeviceOptions &options) override
    {
        Q_UNUSED(options);
        m_assignments.clear();
        for (const QString &text : parser.values(QStringLiteral("set"))) {
            const auto assignment = parseAssignment(text);
            if (!assignment)
                return ExitBadUsage;
            m_assignments.push_back(*assignment);
        }
        if (parser.isSet(QStringLiteral("profile"))) {
            m_profile = loadProfile(parser.value(QStringLiteral("profile")));
            if (!m_profile)
                return ExitBadUsage;
        }
        if (!m_profile && m_assignments.empty()) {
            printError(QStringLiteral(
                "Nothing to set; give --profile FILE or at least one --set NAME=VALUE."));
            return ExitBadUsage;
        }
        // Without --set, the profile alone is already known to be valid; with --set on top
        // of a profile, check now, before any port is opened.
        if (m_profile) {
            if (const int code = checkValid(withAssignments(m_profile->device)); code)
                return code;
        }
        return ExitSuccess;
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        DeviceParams params;
        if (m_profile) {
            params = withAssignments(m_profile->device);
        } else {
            CommandResult read;
            if (const int code = runner.runCommand(&DeviceClient::readParams, &read); code)
                return code;
            if (const int code = DeviceRunner::reportResult(read); code)
                return code;
            // The device's floats as their shortest decimals: the same floats go back, and any
            // violation names readable values (0.4, not 0.4000000059604645).
            const DeviceParams held = tidyDeviceParams(runner.client().deviceParams());
            params = withAssignments(held);
            if (!validate(params).empty()) {
                // Not the user's fault when the values --set starts from are the problem.
                if (const QString problem = deviceParamsProblem(held); !problem.isEmpty()) {
                    printError(u"The device's current parameters are not valid (" + problem +
                               u"), so --set cannot start from them; nothing was sent. Give "
                               u"every parameter with --profile.");
                    return ExitNoDevice;
                }
            }
            if (const int code = checkValid(params); code)
                return code;
        }

        CommandResult result;
        const int code = runner.runCommand(
            [&params](DeviceClient &client) { return client.pushParams(params); }, &result);
        if (code)
            return code;
        if (const int refused = DeviceRunner::reportResult(result); refused)
            return refused;

        const DeviceParams readBack = runner.client().deviceParams();
        if (!sameOnWire(readBack, params))
            printNote(QStringLiteral("warning: the parameters read back differ from those "
                                     "sent (beyond 32-bit rounding)."));
        printNote(QStringLiteral("The device accepted the parameters."));
        writeOut(parameterOutput(readBack, runner.client().deviceInfo(),
                                 parser.isSet(QStringLiteral("json"))));
        return ExitSuccess;
    }

private:
    DeviceParams withAssignments(DeviceParams params) const
    {
        for (const Assignment &assignment : m_assignments)
            params.setField(assignment.index, assignment.value);
        return params;
    }

    // Host-side validation (model.md § 1); prints the violations and gives 4 when refused.
    static int checkValid(const DeviceParams &params)
    {
        const auto violations = validate(params);
        if (violations.empty())
            return ExitSuccess;
        printError(QStringLiteral("The parameters are not valid; nothing was sent:"));
        for (const Violation &violation : violations)
            printNote(u"  " + QString::fromStdString(violation.message()));
        return ExitBadUsage;
    }

    std::optional<Profile> m_profile;
    std::vector<Assignment> m_assignments;
};

} // namespace

std::unique_ptr<Command> makeSetCommand()
{
    return std::make_unique<SetCommand>();
}

} // namespace hatpic::cli
