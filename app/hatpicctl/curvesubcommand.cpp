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

namespace {

class CurveSubcommand final : public Subcommand
{
public:
    QString name() const override { return QStringLiteral("curve"); }
    QString summary() const override
    {
        return QStringLiteral(
            "Print K_rec, tau_rec and the static effect torques of a profile (CSV).");
    }
    QString synopsis() const override
    {
        return QStringLiteral("curve --profile FILE [--from RAD] [--to RAD] [--step RAD]");
    }
    QString description() const override
    {
        return QStringLiteral(
            "Computes the model offline (no device). Prints CSV with the header\n"
            "theta,K_rec,tau_rec,tau_det,tau_wall: theta is the absolute knob angle [rad],\n"
            "K_rec the re-centering stiffness [N·m/rad], tau_rec = -K_rec·(theta - theta0)\n"
            "[N·m] with the profile's theta0, and tau_det, tau_wall the detent and end-stop\n"
            "torques of the profile's effects at rest (omega = 0) [N·m]; 0 without effects.\n"
            "Rows: theta = FROM + i·STEP while below TO, then TO\n"
            "itself. Defaults: from -pi/2 to pi/2, step 0.01. Numbers are printed with\n"
            "the shortest digits that read back as the identical double.");
    }
    void addOptions(QCommandLineParser &parser) override
    {
        parser.addOption(QCommandLineOption(QStringList{QStringLiteral("profile")},
                                            QStringLiteral("The profile (required)."),
                                            QStringLiteral("FILE")));
        parser.addOption(QCommandLineOption(QStringList{QStringLiteral("from")},
                                            QStringLiteral("First angle (default: -pi/2)."),
                                            QStringLiteral("RAD")));
        parser.addOption(QCommandLineOption(QStringList{QStringLiteral("to")},
                                            QStringLiteral("Last angle (default: pi/2)."),
                                            QStringLiteral("RAD")));
        parser.addOption(QCommandLineOption(QStringList{QStringLiteral("step")},
                                            QStringLiteral("Angle step (default: 0.01)."),
                                            QStringLiteral("RAD")));
    }

    int run(const QCommandLineParser &parser) override
    {
        if (!parser.isSet(QStringLiteral("profile"))) {
            printError(QStringLiteral("curve needs --profile FILE."));
            return ExitBadUsage;
        }
        AngleGrid grid;
        for (auto [option, target] : {std::pair{QStringLiteral("from"), &grid.from},
                                      std::pair{QStringLiteral("to"), &grid.to},
                                      std::pair{QStringLiteral("step"), &grid.step}}) {
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
        const auto profile = loadProfile(parser.value(QStringLiteral("profile")));
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
