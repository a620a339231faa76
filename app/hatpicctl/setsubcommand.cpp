// hatpicctl set: push parameters and effects (a profile, or single values over the device's
// current ones).
#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "paramtext.h"
#include "profileinput.h"
#include "session/sessionwording.h"
#include "subcommands.h"

#include "model/effects.h"
#include "model/params.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <algorithm>
#include <optional>
#include <utility>

namespace hatpic::cli {

namespace {

struct Assignment
{
    int index = -1;      //!< ParamBlock index, or effect block index when `effect`
    bool effect = false; //!< a field of the effect block (effects.md § 2)
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

QString effectNames()
{
    QStringList names;
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        const auto name = effectFieldName(i);
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
    int index = deviceFieldIndex(name.toStdString());
    const bool effect = index < 0 && effectFieldIndex(name.toStdString()) >= 0;
    if (effect)
        index = effectFieldIndex(name.toStdString());
    if (index < 0) {
        printError(u"Unknown parameter '" + name + u"' in --set; the parameters are " +
                   fieldNames() + u", and the effects " + effectNames() + u'.');
        return std::nullopt;
    }
    bool ok = false;
    const double value = valueText.toDouble(&ok);
    if (!ok) {
        printError(u"The value of " + name + u" in --set must be a number, got '" + valueText +
                   u"'.");
        return std::nullopt;
    }
    return Assignment{index, effect, value};
}

class SetSubcommand final : public DeviceSubcommand
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
                   "Effect fields (effects.md) go the same way with SET_EFFECTS: with --set\n"
                   "alone only the named ones change over the device's block (GET_EFFECTS);\n"
                   "a profile's effects (its defaults when it has none) are sent whole. A\n"
                   "device without the effects capability refuses them (exit 2) and a\n"
                   "profile's non-default effects are then not sent.\n"
                   "Names: ") +
               fieldNames() + u"\nEffects: " + effectNames() + u"\n\n" + portHelp();
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
            if (const int code = checkValidEffects(withEffectAssignments(m_profile->effects),
                                                   m_profile->host.tau_limit);
                code)
                return code;
        }
        return ExitSuccess;
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        const DeviceInfo info = runner.client().deviceInfo();
        const bool pushesParams = m_profile || assigns(false);
        // A profile's effects go whole, but one without any asks nothing of a device that has
        // no effects; named effect fields always need the capability.
        const bool wantsEffects =
            assigns(true) || (m_profile && roundedForWire(m_profile->effects, info.tauLimit) !=
                                               roundedForWire(EffectParams{}, info.tauLimit));
        const bool pushesEffects = info.hasEffects() && (m_profile || assigns(true));
        if (wantsEffects && !info.hasEffects()) {
            // The session refuses it with the reason (legacy, or no capability); nothing sent.
            CommandResult refused;
            const DeviceTuning none{std::nullopt, EffectParams{}};
            if (const int code = runner.runCommand(
                    [&none](DeviceClient &client) { return client.pushTuning(none); }, &refused);
                code)
                return code;
            return DeviceRunner::reportResult(refused);
        }

        DeviceTuning held; // what --set starts from without a profile: the device's own
        if (!m_profile) {
            CommandResult read;
            if (const int code = runner.runCommand(&DeviceClient::readTuning, &read); code)
                return code;
            if (const int code = DeviceRunner::reportResult(read); code)
                return code;
            held = read.received;
        }

        DeviceTuning tuning;
        if (m_profile) {
            tuning.params = withAssignments(m_profile->device);
        } else {
            // The device's floats as their shortest decimals: the same floats go back, and any
            // violation names readable values (0.4, not 0.4000000059604645).
            const DeviceParams from = tidyDeviceParams(held.params.value_or(DeviceParams{}));
            tuning.params = withAssignments(from);
            if (!validate(*tuning.params).empty()) {
                // Not the user's fault when the values --set starts from are the problem.
                if (const QString problem = deviceParamsProblem(from); !problem.isEmpty()) {
                    printError(u"The device's current parameters are not valid (" + problem +
                               u"), so --set cannot start from them; nothing was sent. Give "
                               u"every parameter with --profile.");
                    return ExitNoDevice;
                }
            }
            if (const int code = checkValid(*tuning.params); code)
                return code;
        }
        if (!pushesParams)
            tuning.params.reset();

        if (pushesEffects) {
            if (m_profile) {
                tuning.effects = withEffectAssignments(m_profile->effects);
            } else {
                const EffectParams from = tidyEffectParams(held.effects.value_or(EffectParams{}));
                tuning.effects = withEffectAssignments(from);
                if (!validate(*tuning.effects, info.tauLimit).empty()) {
                    if (const QString problem = deviceEffectsProblem(from, info.tauLimit);
                        !problem.isEmpty()) {
                        printError(u"The device's current effects are not valid (" + problem +
                                   u"), so --set cannot start from them; nothing was sent. Give "
                                   u"every effect with --profile.");
                        return ExitNoDevice;
                    }
                }
            }
            // Against the device's own torque limit, before anything is sent.
            if (const int code = checkValidEffects(*tuning.effects, info.tauLimit); code)
                return code;
        }

        // Shown as `get` shows it: the read-back of the push, else what was read before.
        DeviceTuning shown = runner.client().deviceTuning();
        if (tuning.params || tuning.effects) {
            CommandResult result;
            const int code = runner.runCommand(
                [&tuning](DeviceClient &client) { return client.pushTuning(tuning); }, &result);
            if (code) {
                // The link went after part of the push: say what it had changed.
                if (const QString applied = SessionWording::appliedBeforeFailure(result);
                    !applied.isEmpty())
                    printNote(applied);
                writeInForce(shown, result, info, parser);
                return code;
            }
            if (const int refused = DeviceRunner::reportResult(result); refused) {
                writeInForce(shown, result, info, parser);
                return refused;
            }
            const DeviceTuning &back = result.received;
            if (tuning.params) {
                if (!back.params || !sameOnWire(*back.params, *tuning.params))
                    printNote(QStringLiteral("warning: the parameters read back differ from "
                                             "those sent (beyond 32-bit rounding)."));
                printNote(QStringLiteral("The device accepted the parameters."));
            }
            if (tuning.effects) {
                if (!back.effects || !sameOnWire(*back.effects, *result.sent.effects))
                    printNote(QStringLiteral("warning: the effects read back differ from those "
                                             "sent (beyond 32-bit rounding)."));
                printNote(QStringLiteral("The device accepted the effects."));
            }
            shown = shown.updatedBy(back);
        }
        writeOut(parameterOutput(shown.params.value_or(DeviceParams{}),
                                 info.hasEffects() ? shown.effects : std::nullopt, info,
                                 parser.isSet(QStringLiteral("json"))));
        return ExitSuccess;
    }

private:
    //! A push that failed part-way: what is in force goes to stdout as `get` shows it (the
    //! read-back where it came), so a script sees the device's state; the effects are left
    //! out when the failed step leaves them unknown. Nothing when the push changed nothing.
    static void writeInForce(const DeviceTuning &before, const CommandResult &result,
                             const DeviceInfo &info, const QCommandLineParser &parser)
    {
        const DeviceTuning applied = appliedBeforeFailure(result);
        if (!applied.params && !applied.effects)
            return;
        const DeviceTuning inForce = before.updatedBy(applied);
        const bool effectsUnknown = effectsUnknownAfterFailure(result);
        writeOut(
            parameterOutput(inForce.params.value_or(DeviceParams{}),
                            info.hasEffects() && !effectsUnknown ? inForce.effects : std::nullopt,
                            info, parser.isSet(QStringLiteral("json"))));
    }

    bool assigns(bool effect) const
    {
        return std::any_of(m_assignments.cbegin(), m_assignments.cend(),
                           [effect](const Assignment &a) { return a.effect == effect; });
    }

    DeviceParams withAssignments(DeviceParams params) const
    {
        for (const Assignment &assignment : m_assignments) {
            if (!assignment.effect)
                params.setField(assignment.index, assignment.value);
        }
        return params;
    }

    EffectParams withEffectAssignments(EffectParams effects) const
    {
        for (const Assignment &assignment : m_assignments) {
            if (assignment.effect)
                effects.setField(assignment.index, assignment.value);
        }
        return effects;
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

    // The same for the effect block (effects.md § 2) against the torque limit `tauLimit`.
    static int checkValidEffects(const EffectParams &effects, double tauLimit)
    {
        const auto violations = validate(effects, tauLimit);
        if (violations.empty())
            return ExitSuccess;
        printError(QStringLiteral("The effects are not valid; nothing was sent:"));
        for (const Violation &violation : violations)
            printNote(u"  " + QString::fromStdString(violation.message()));
        return ExitBadUsage;
    }

    std::optional<Profile> m_profile;
    std::vector<Assignment> m_assignments;
};

} // namespace

std::unique_ptr<Subcommand> makeSetSubcommand()
{
    return std::make_unique<SetSubcommand>();
}

} // namespace hatpic::cli
