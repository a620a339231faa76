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

#include "model/devicetuning.h"
#include "model/paramtable.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <algorithm>
#include <optional>
#include <utility>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

//! The blocks of a tuning that --set names fields of.
enum class Part { Params, Effects, Passivity };

struct Assignment
{
    Part part = Part::Params;
    int index = -1; //!< the field's index in its block's table
    double value = 0;
};

template<typename Block, std::size_t N>
QString namesOf(const std::array<FieldSpec<Block>, N> &fields)
{
    QStringList names;
    for (const FieldSpec<Block> &spec : fields)
        names << QString::fromUtf8(spec.name.data(), static_cast<qsizetype>(spec.name.size()));
    return names.join(u", "_s);
}

QString allNames()
{
    return u"the parameters are " + namesOf(kDeviceFields) + u", the effects " +
           namesOf(kEffectFields) + u", and the passivity controller's " +
           namesOf(kPassivityFields);
}

// "K_max=0.5" → {Params, 3, 0.5}; prints one sentence and gives nullopt when it is not that.
std::optional<Assignment> parseAssignment(const QString &text)
{
    const qsizetype equals = text.indexOf(u'=');
    if (equals <= 0) {
        printError(u"--set takes NAME=VALUE, got '" + text + u"'.");
        return std::nullopt;
    }
    const QString name = text.left(equals).trimmed();
    const QString valueText = text.mid(equals + 1).trimmed();
    const std::string key = name.toStdString();
    Assignment assignment;
    if (const int i = deviceFieldIndex(key); i >= 0)
        assignment = {Part::Params, i, 0};
    else if (const int e = effectFieldIndex(key); e >= 0)
        assignment = {Part::Effects, e, 0};
    else if (const int p = passivityFieldIndex(key); p >= 0)
        assignment = {Part::Passivity, p, 0};
    else {
        printError(u"Unknown parameter '" + name + u"' in --set; " + allNames() + u'.');
        return std::nullopt;
    }
    bool ok = false;
    assignment.value = valueText.toDouble(&ok);
    if (!ok) {
        printError(u"The value of " + name + u" in --set must be a number, got '" + valueText +
                   u"'.");
        return std::nullopt;
    }
    return assignment;
}

//! How a block is named in set's sentences.
struct BlockWords
{
    const char16_t *plural;   //!< "parameters"
    const char16_t *singular; //!< "parameter"
    const char16_t *accepted; //!< "The device accepted the parameters."
    const char16_t *differ;   //!< what the read-back warning calls them
};

constexpr BlockWords kParamsWords{u"parameters", u"parameter",
                                  u"The device accepted the parameters.", u"parameters"};
constexpr BlockWords kEffectsWords{u"effects", u"effect", u"The device accepted the effects.",
                                   u"effects"};
constexpr BlockWords kPassivityWords{u"passivity settings", u"passivity setting",
                                     u"The device accepted the passivity settings.",
                                     u"passivity settings"};

class SetSubcommand final : public DeviceSubcommand
{
public:
    SetSubcommand()
        : DeviceSubcommand(
              {.name = u"set"_s,
               .summary = u"Push parameters from a profile or as NAME=VALUE."_s,
               .synopsis =
                   u"set --port PORT (--profile FILE | --set NAME=VALUE …) [--knob N] [--json]"_s,
               .description =
                   u"Sends SET_PARAMS and waits for the device's ACK, then prints the\n"
                   "parameters read back (as 'get' does). With --set alone, the device's current\n"
                   "parameters are read first (GET_PARAMS) and only the named ones change;\n"
                   "with --profile, the profile's device parameters are the starting point and\n"
                   "any --set applies on top. The whole set is validated before anything is\n"
                   "sent: a violation exits with 4 and the device is left untouched.\n"
                   "Effect fields (effects.md) go the same way with SET_EFFECTS, and the\n"
                   "passivity controller's (passivity.md) with SET_PASSIVITY: with --set alone\n"
                   "only the named ones change over the device's block; a profile's blocks\n"
                   "(their defaults when it has none) are sent whole. A device without the\n"
                   "capability refuses named fields (exit 2); a profile's non-default effects\n"
                   "are then not sent either, and its passivity block is left out with a note.\n"
                   "A device with several knobs keeps a tuning per knob: --knob N tunes knob N\n"
                   "alone (its blocks are read first, and --set starts from them).\n"
                   "Names: "_s +
                   namesOf(kDeviceFields) + u"\nEffects: " + namesOf(kEffectFields) +
                   u"\nPassivity: " + namesOf(kPassivityFields)},
              Knobs::One)
    {}

protected:
    void addCommandOptions(QCommandLineParser &parser) override
    {
        parser.addOption({u"profile"_s, u"Profile whose device parameters are sent."_s, u"FILE"_s});
        parser.addOption({u"set"_s, u"Set one parameter, e.g. K_max=0.5 (SI units). Repeatable."_s,
                          u"NAME=VALUE"_s});
        addJsonOption(parser);
    }

    int prepare(const QCommandLineParser &parser, DeviceOptions &) override
    {
        m_assignments.clear();
        for (const QString &text : parser.values(u"set"_s)) {
            const auto assignment = parseAssignment(text);
            if (!assignment)
                return ExitBadUsage;
            m_assignments.push_back(*assignment);
        }
        if (parser.isSet(u"profile"_s)) {
            m_profile = loadProfile(parser.value(u"profile"_s));
            if (!m_profile)
                return ExitBadUsage;
        }
        if (!m_profile && m_assignments.empty()) {
            printError(u"Nothing to set; give --profile FILE or at least one --set NAME=VALUE."_s);
            return ExitBadUsage;
        }
        // Without --set, the profile alone is already known to be valid; with --set on top
        // of a profile, check now, before any port is opened.
        if (m_profile) {
            const double tauLimit = m_profile->host.tau_limit;
            if (const int code =
                    checkValid(validate(withAssignments(m_profile->device)), kParamsWords);
                code)
                return code;
            if (const int code = checkValid(validate(withAssignments(m_profile->effects), tauLimit),
                                            kEffectsWords);
                code)
                return code;
            if (const int code =
                    checkValid(validate(withAssignments(m_profile->passivity)), kPassivityWords);
                code)
                return code;
        }
        return ExitSuccess;
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        const DeviceInfo info = runner.client().deviceInfo();
        const double tauLimit = info.tauLimit;
        // A profile's effects go whole, but one without any asks nothing of a device that has
        // no effects; named fields of a block always need its capability.
        const bool wantsEffects =
            assigns(Part::Effects) || (m_profile && roundedForWire(m_profile->effects, tauLimit) !=
                                                        roundedForWire(EffectParams{}, tauLimit));
        const bool refusedPart = (wantsEffects && !info.hasEffects()) ||
                                 (assigns(Part::Passivity) && !info.hasPassivity());
        if (refusedPart) {
            // The session refuses it with the reason (legacy, or no capability); nothing sent.
            Outcome refused;
            DeviceTuning none{std::nullopt, std::nullopt};
            if (wantsEffects && !info.hasEffects())
                none.effects = EffectParams{};
            else
                none.passivity = PassivityParams{};
            if (const int code = runner.runCommand(request::Push{none, knob()}, &refused); code)
                return code;
            return DeviceRunner::reportOutcome(refused);
        }
        if (m_profile && !info.hasPassivity() &&
            !sameOnWire(m_profile->passivity, PassivityParams{}))
            printNote(u"note: this device has no passivity controller (its "
                      "firmware does not announce the capability), so the "
                      "profile's device.passivity is not sent."_s);

        // What --set starts from without a profile: the device's own. The session follows
        // knob 1's tuning; another knob's is read here (which also checks the device has it).
        DeviceTuning held;
        if (!m_profile || knob()) {
            Outcome read;
            if (const int code = runner.runCommand(request::Read{knob()}, &read); code)
                return code;
            if (const int code = DeviceRunner::reportOutcome(read); code)
                return code;
            held = read.received;
        }

        DeviceTuning tuning;
        if (m_profile || assigns(Part::Params)) {
            if (const int code = compose(
                    m_profile ? &m_profile->device : nullptr, held.params, &tidyDeviceParams,
                    [](const DeviceParams &p) { return validate(p); }, kParamsWords, tuning.params);
                code)
                return code;
        }
        if (info.hasEffects() && (m_profile || assigns(Part::Effects))) {
            // Against the device's own torque limit, before anything is sent.
            if (const int code = compose(
                    m_profile ? &m_profile->effects : nullptr, held.effects, &tidyEffectParams,
                    [tauLimit](const EffectParams &e) { return validate(e, tauLimit); },
                    kEffectsWords, tuning.effects);
                code)
                return code;
        }
        if (info.hasPassivity() && (m_profile || assigns(Part::Passivity))) {
            if (const int code = compose(
                    m_profile ? &m_profile->passivity : nullptr, held.passivity,
                    &tidyPassivityParams, [](const PassivityParams &p) { return validate(p); },
                    kPassivityWords, tuning.passivity);
                code)
                return code;
        }

        // Shown as `get` shows it: the read-back of the push, else what was read before.
        DeviceTuning shown = knob() ? held : runner.client().deviceTuning();
        if (tuning.params || tuning.effects || tuning.passivity) {
            Outcome result;
            const int code = runner.runCommand(request::Push{tuning, knob()}, &result);
            if (code) {
                // The link went after part of the push: say what it had changed.
                if (const QString applied = SessionWording::appliedBeforeFailure(result);
                    !applied.isEmpty())
                    printNote(applied);
                writeInForce(shown, result, info, parser);
                return code;
            }
            if (const int refused = DeviceRunner::reportOutcome(result); refused) {
                writeInForce(shown, result, info, parser);
                return refused;
            }
            const DeviceTuning &back = result.received;
            const DeviceTuning &sent = *result.pushed();
            noteAccepted(sent.params, back.params, kParamsWords);
            noteAccepted(sent.effects, back.effects, kEffectsWords);
            noteAccepted(sent.passivity, back.passivity, kPassivityWords);
            shown = shown.updatedBy(back);
        }
        writeOut(tuningOutput(shownBlocks(shown, info), info, parser.isSet(u"json"_s)));
        return ExitSuccess;
    }

private:
    //! The blocks `get` would show of `tuning` on this device.
    static DeviceTuning shownBlocks(DeviceTuning tuning, const DeviceInfo &info)
    {
        if (!tuning.params)
            tuning.params = DeviceParams{};
        if (!info.hasEffects())
            tuning.effects.reset();
        if (!info.hasPassivity())
            tuning.passivity.reset();
        return tuning;
    }

    //! A push that failed part-way: what is in force goes to stdout as `get` shows it (the
    //! read-back where it came), so a script sees the device's state; the blocks after the
    //! failed step are left out when it leaves them unknown. Nothing when the push changed
    //! nothing.
    static void writeInForce(const DeviceTuning &before, const Outcome &result,
                             const DeviceInfo &info, const QCommandLineParser &parser)
    {
        const outcome::Stopped *stop = result.stopped();
        if (!stop || (!stop->applied.params && !stop->applied.effects && !stop->applied.passivity))
            return;
        DeviceTuning inForce = shownBlocks(before.updatedBy(stop->applied), info);
        if (const auto step = result.unknownStep(); step == CommandKind::SetEffects)
            inForce.effects.reset();
        else if (step == CommandKind::SetPassivity)
            inForce.passivity.reset();
        writeOut(tuningOutput(inForce, info, parser.isSet(u"json"_s)));
    }

    //! "The device accepted the …", after a warning when the read-back is not what was sent.
    template<typename Block>
    static void noteAccepted(const std::optional<Block> &sent, const std::optional<Block> &back,
                             const BlockWords &words)
    {
        if (!sent)
            return;
        if (!back || !sameOnWire(*back, *sent))
            printNote(u"warning: the " + QString::fromUtf16(words.differ) +
                      u" read back differ from those sent (beyond 32-bit rounding).");
        printNote(QString::fromUtf16(words.accepted));
    }

    //! The block a push sends: the profile's (already checked in prepare()) or the device's
    //! `held` one as its shortest decimals — so the same floats go back and a violation names
    //! readable values — with the --set assignments on top, validated before anything is sent.
    template<typename Block, typename Validate>
    int compose(const Block *fromProfile, const std::optional<Block> &held,
                Block (*tidy)(const Block &), Validate validateBlock, const BlockWords &words,
                std::optional<Block> &out) const
    {
        const Block from = fromProfile ? *fromProfile : tidy(held.value_or(Block{}));
        const Block block = withAssignments(from);
        if (!fromProfile && !validateBlock(block).empty()) {
            // Not the user's fault when the values --set starts from are the problem.
            if (const QString problem = problemText(validateBlock(from)); !problem.isEmpty()) {
                printError(u"The device's current " + QString::fromUtf16(words.plural) +
                           u" are not valid (" + problem +
                           u"), so --set cannot start from them; nothing was sent. Give every " +
                           QString::fromUtf16(words.singular) + u" with --profile.");
                return ExitNoDevice;
            }
        }
        if (const int code = checkValid(validateBlock(block), words); code)
            return code;
        out = block;
        return ExitSuccess;
    }

    bool assigns(Part part) const
    {
        return std::any_of(m_assignments.cbegin(), m_assignments.cend(),
                           [part](const Assignment &a) { return a.part == part; });
    }

    static constexpr Part partOf(const DeviceParams *) { return Part::Params; }
    static constexpr Part partOf(const EffectParams *) { return Part::Effects; }
    static constexpr Part partOf(const PassivityParams *) { return Part::Passivity; }

    //! `block` with the --set assignments to its fields.
    template<typename Block> Block withAssignments(Block block) const
    {
        for (const Assignment &assignment : m_assignments) {
            if (assignment.part == partOf(&block))
                block.setField(assignment.index, assignment.value);
        }
        return block;
    }

    // Host-side validation (model.md § 1, effects.md § 2, passivity.md); prints the violations
    // and gives 4 when refused.
    static int checkValid(const std::vector<Violation> &violations, const BlockWords &words)
    {
        if (violations.empty())
            return ExitSuccess;
        printError(u"The " + QString::fromUtf16(words.plural) +
                   u" are not valid; nothing was sent:");
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
