// hatpicctl curve: the re-centering stiffness and torque of a profile, as CSV.
#include "common/exitcodes.h"
#include "console.h"
#include "curvetable.h"
#include "profileinput.h"
#include "subcommand.h"
#include "subcommands.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

class CurveSubcommand final : public Subcommand
{
public:
    CurveSubcommand()
        : Subcommand(
              {.name = u"curve"_s,
               .summary =
                   u"Print K_rec, tau_rec and the static effect torques of a profile (CSV)."_s,
               .synopsis = u"curve --profile FILE [--from RAD] [--to RAD] [--step RAD]"_s,
               .description =
                   u"Computes the model offline (no device). Prints CSV with the header\n"
                   "theta,K_rec,tau_rec,tau_det,tau_wall: theta is the absolute knob angle [rad],\n"
                   "K_rec the re-centering stiffness [N·m/rad], tau_rec = -K_rec·(theta - theta0)\n"
                   "[N·m] with the profile's theta0, and tau_det, tau_wall the detent and "
                   "end-stop\n"
                   "torques of the profile's effects at rest (omega = 0) [N·m]; 0 without "
                   "effects.\n"
                   "Rows: theta = FROM + i·STEP while below TO, then TO\n"
                   "itself. Defaults: from -pi/2 to pi/2, step 0.01. Numbers are printed with\n"
                   "the shortest digits that read back as the identical double."_s})
    {}
    void addOptions(QCommandLineParser &parser) override
    {
        parser.addOption(QCommandLineOption(u"profile"_s, u"The profile (required)."_s, u"FILE"_s));
        parser.addOption({u"from"_s, u"First angle (default: -pi/2)."_s, u"RAD"_s});
        parser.addOption(QCommandLineOption(u"to"_s, u"Last angle (default: pi/2)."_s, u"RAD"_s));
        parser.addOption(QCommandLineOption(u"step"_s, u"Angle step (default: 0.01)."_s, u"RAD"_s));
    }

    int run(const QCommandLineParser &parser) override
    {
        if (!parser.isSet(u"profile"_s)) {
            printError(u"curve needs --profile FILE."_s);
            return ExitBadUsage;
        }
        AngleGrid grid;
        for (auto [option, target] :
             {std::pair{u"from"_s, &grid.from}, std::pair{u"to"_s, &grid.to},
              std::pair{u"step"_s, &grid.step}}) {
            if (!parser.isSet(option))
                continue;
            bool ok = false;
            *target = parser.value(option).toDouble(&ok);
            if (!ok) {
                printError(u"--" + option + u" must be a number of radians, got '" +
                           parser.value(option) + u"'.");
                return ExitBadUsage;
            }
        }
        QString error;
        const auto rows = grid.rowCount(&error);
        if (!rows) {
            printError(error);
            return ExitBadUsage;
        }
        const auto profile = loadProfile(parser.value(u"profile"_s));
        if (!profile)
            return ExitBadUsage;

        writeOut(curveHeader());
        QByteArray chunk;
        for (qint64 i = 0; i < *rows; ++i) {
            chunk += curveRow(profile->device, profile->effects, grid.angle(i, *rows));
            if (chunk.size() > 1 << 16) {
                writeOut(chunk);
                chunk.clear();
            }
        }
        writeOut(chunk);
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeCurveSubcommand()
{
    return std::make_unique<CurveSubcommand>();
}

} // namespace hatpic::cli
