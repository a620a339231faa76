// hatpicctl validate: is this profile usable? OK, or every error; warnings either way.
#include "common/exitcodes.h"
#include "console.h"
#include "subcommand.h"
#include "subcommands.h"

#include "model/derived.h"
#include "profile/profile.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

// Figures in warnings are for a person: three significant digits.
QString roughly(double value)
{
    return QString::number(value, 'g', 3);
}

// Valid in double, but not once rounded to the 32-bit floats the device holds.
QStringList floatRoundingErrors(const DeviceParams &params)
{
    QStringList errors;
    for (const Violation &violation : validate(roundedForWire(params))) {
        errors << u"device." + QString::fromStdString(violation.message()) +
                      u" (after rounding to the device's 32-bit floats)";
    }
    return errors;
}

class ValidateSubcommand final : public Subcommand
{
public:
    ValidateSubcommand()
        : Subcommand(
              {.name = u"validate"_s,
               .summary = u"Check a profile: OK, or every error; warnings either way."_s,
               .synopsis = u"validate FILE"_s,
               .description =
                   u"Reads the profile as the tuner would. A usable profile prints OK on stdout "
                   u"and\n"
                   "exits with 0; otherwise every error goes to stderr and the exit code is 4.\n"
                   "Warnings (ignored keys, a re-centering torque the actuator cannot render,\n"
                   "a lightly damped knob) go to stderr in both cases. --profile FILE is accepted\n"
                   "as well."_s,
               .acceptsPositional = true})
    {}
    void addOptions(QCommandLineParser &parser) override
    {
        parser.addPositionalArgument(u"FILE"_s, u"The profile."_s);
        parser.addOption({u"profile"_s, u"The profile (instead of FILE)."_s, u"FILE"_s});
    }

    int run(const QCommandLineParser &parser) override
    {
        QStringList files = parser.positionalArguments();
        if (parser.isSet(u"profile"_s))
            files << parser.value(u"profile"_s);
        if (files.size() != 1) {
            printError(u"validate takes exactly one profile FILE."_s);
            return ExitBadUsage;
        }
        const QString path = files.front();
        const ProfileReadResult read = readProfile(path);

        QStringList errors = read.errors;
        if (read.ok())
            errors << floatRoundingErrors(read.profile->device);

        QStringList warnings = read.warnings;
        if (read.ok() && errors.isEmpty()) {
            const DerivedFigures figures = deriveFigures(read.profile->device, read.profile->host);
            if (figures.saturates()) {
                warnings << u"the largest re-centering torque within ±π/2 of theta0, " +
                                roughly(figures.peakTauRec) + u" N·m at |θ−θ0| = " +
                                roughly(figures.peakAngle) + u" rad, exceeds tau_limit (" +
                                roughly(figures.tauLimit) + u" N·m); the device clamps it";
            }
            if (figures.rings()) {
                warnings << u"the damping ratio ζ = " + roughly(figures.zeta) + u" is below " +
                                roughly(DerivedFigures::kRingingZeta) + u"; the knob will ring";
            }
        }

        for (const QString &warning : std::as_const(warnings))
            printNote(u"warning: " + path + u": " + warning);
        if (errors.isEmpty()) {
            writeOut(QByteArrayLiteral("OK\n"));
            return ExitSuccess;
        }
        if (errors.size() == 1) {
            printError(u"The profile " + path + u" is not usable: " + asSentence(errors.front()));
            return ExitBadUsage;
        }
        printError(u"The profile " + path + u" is not valid (" + QString::number(errors.size()) +
                   u" errors):");
        for (const QString &error : std::as_const(errors))
            printNote(u"  " + error);
        return ExitBadUsage;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeValidateSubcommand()
{
    return std::make_unique<ValidateSubcommand>();
}

} // namespace hatpic::cli
