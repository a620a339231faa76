// hatpicctl experiment: a step, a frequency response or a spectrum measured on the device,
// printed next to the model's figures (docs/experiments.md).
#include "common/exitcodes.h"
#include "common/quitonsignal.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "experimenttext.h"
#include "subcommands.h"

#include "experiment/experimentcsv.h"
#include "experiment/experimentrunner.h"
#include "profile/jsonfile.h"
#include "sim/simulatedjoystick.h"
#include "telemetry/numbertext.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QFile>
#include <QFileInfo>

#include <cmath>
#include <optional>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

//! Options that override the plan's defaults: name → the field it sets.
struct NumberOption
{
    const char16_t *name;
    const char16_t *help;
    double ExperimentPlan::*field;
};

const NumberOption kNumberOptions[] = {
    {u"from", u"Step: tau_ext before the step, N·m (default: a quarter into the notch band).",
     &ExperimentPlan::tauFrom},
    {u"to", u"Step: tau_ext after it, N·m (default: three quarters into the band).",
     &ExperimentPlan::tauTo},
    {u"offset", u"Bode: the bias tau_ext, N·m (default: the middle of the band).",
     &ExperimentPlan::offset},
    {u"amplitude", u"Bode: the sine's amplitude, N·m (default: a quarter band's torque).",
     &ExperimentPlan::amplitude},
    {u"settle", u"Seconds at the bias before the step or the sines, and per frequency.",
     &ExperimentPlan::settle},
    {u"duration", u"Step: seconds recorded after the step; spectrum: seconds recorded.",
     &ExperimentPlan::duration},
};

std::optional<ExperimentKind> kindOf(const QString &name)
{
    for (ExperimentKind kind :
         {ExperimentKind::Step, ExperimentKind::Frequency, ExperimentKind::Spectrum}) {
        if (experimentKindName(kind) == name)
            return kind;
    }
    return std::nullopt;
}

class ExperimentSubcommand final : public DeviceSubcommand
{
public:
    ExperimentSubcommand()
        : DeviceSubcommand(
              {.name = u"experiment"_s,
               .summary = u"Measure the knob's step or frequency response, or a spectrum."_s,
               .synopsis = u"experiment step|bode|spectrum --port PORT [options] [--csv FILE "
                           "[--force]]"_s,
               .description =
                   u"Applies tau_ext through the feedback stream and measures how the knob\n"
                   "responds (hands off the knob; with --port sim the simulated hand is idle\n"
                   "for the run): 'step' steps tau_ext and fits omega_n and\n"
                   "zeta; 'bode' applies stepped sines (--frequencies) and prints theta/tau_ext\n"
                   "in dB and degrees with the -3 dB bandwidth; 'spectrum' records theta and\n"
                   "tau at rest and prints their strongest lines (Hann window, dB). The model's\n"
                   "figures for the device's parameters stand next to the measured ones.\n"
                   "Defaults keep the knob in the notch band (docs/experiments.md); tau_ext is\n"
                   "0 again when the experiment ends, fails or is interrupted. A protocol v2\n"
                   "device is needed. --csv FILE writes the curves (never overwritten without\n"
                   "--force)."_s,
               .acceptsPositional = true})
    {}

protected:
    void addCommandOptions(QCommandLineParser &parser) override
    {
        for (const NumberOption &o : kNumberOptions) {
            parser.addOption(
                {QStringList{QString::fromUtf16(o.name)}, QString::fromUtf16(o.help), u"X"_s});
        }
        parser.addOption({u"frequencies"_s,
                          u"Bode: ascending frequencies in Hz, comma-separated (default: 8 from\n"
                          "a tenth to three times the model's bandwidth)."_s,
                          u"LIST"_s});
        parser.addOption(
            {u"cycles"_s, u"Bode: whole periods measured per frequency (default: 4)."_s, u"N"_s});
        parser.addOption(QCommandLineOption(u"csv"_s, u"Write the curves to FILE."_s, u"FILE"_s));
        parser.addOption(QCommandLineOption(u"force"_s, u"Overwrite FILE if it exists."_s));
    }

    int prepare(const QCommandLineParser &parser, DeviceOptions &) override
    {
        const QStringList positional = parser.positionalArguments();
        const std::optional<ExperimentKind> kind =
            positional.size() == 1 ? kindOf(positional.first()) : std::nullopt;
        if (!kind) {
            printError(u"Name one experiment: step, bode or spectrum; run "
                       "'hatpicctl experiment --help' for the options."_s);
            return ExitBadUsage;
        }
        m_kind = *kind;
        for (const QString &option : parser.optionNames()) {
            if (const QString owner = experimentOfOption(option); !owner.isEmpty()) {
                printError(u"--" + option + u" is an option of '" + owner + u"', not of '" +
                           experimentKindName(m_kind) +
                           u"'; run 'hatpicctl experiment --help' for the options.");
                return ExitBadUsage;
            }
        }
        for (const NumberOption &o : kNumberOptions) {
            const QString name = QString::fromUtf16(o.name);
            if (!parser.isSet(name))
                continue;
            bool ok = false;
            const double v = parser.value(name).toDouble(&ok);
            if (!ok || !std::isfinite(v)) {
                printError(u"--" + name + u' ' + unreadNumber(u"a number"_s, parser.value(name)));
                return ExitBadUsage;
            }
            m_overrides.append({o.field, v});
        }
        if (parser.isSet(u"frequencies"_s)) {
            for (const QString &item : parser.value(u"frequencies"_s).split(u',')) {
                bool ok = false;
                const double f = item.trimmed().toDouble(&ok);
                if (!ok) {
                    printError(u"--frequencies must list numbers of Hz separated by commas, "
                               u"got '" +
                               item + u"'.");
                    return ExitBadUsage;
                }
                m_frequencies.append(f);
            }
        }
        if (parser.isSet(u"cycles"_s)) {
            bool ok = false;
            m_cycles = parser.value(u"cycles"_s).toInt(&ok);
            if (!ok) {
                printError(u"--cycles " +
                           unreadNumber(u"a whole number"_s, parser.value(u"cycles"_s), true));
                return ExitBadUsage;
            }
        }
        m_csvPath = parser.value(u"csv"_s);
        if (parser.isSet(u"csv"_s) && m_csvPath.isEmpty()) {
            printError(u"--csv needs a file name."_s);
            return ExitBadUsage;
        }
        // Checked before the port is opened: a bad target must not cost a measurement.
        if (!m_csvPath.isEmpty()) {
            if (const QString problem =
                    outputTargetProblem({m_csvPath}, parser.isSet(u"force"_s),
                                        u"the curves need a file of their own"_s);
                !problem.isEmpty()) {
                printError(problem);
                return ExitBadUsage;
            }
        }
        return ExitSuccess;
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &) override
    {
        DeviceClient &client = runner.client();
        if (const QString why = ExperimentRunner::refusal(client);
            !why.isEmpty() && client.deviceInfo().protocol == WireProtocol::Legacy) {
            printError(why);
            return ExitRejected;
        }
        Outcome read;
        if (const int code = runner.runCommand(request::Read{}, &read); code)
            return code;
        if (const int code = DeviceRunner::reportOutcome(read); code)
            return code;

        ExperimentPlan plan =
            ExperimentPlan::defaults(m_kind, read.received.params.value_or(DeviceParams{}));
        for (const auto &[field, value] : m_overrides)
            plan.*field = value;
        if (!m_frequencies.isEmpty())
            plan.frequencies = m_frequencies;
        if (m_cycles)
            plan.cycles = *m_cycles;

        // On --port sim the runner holds the simulated hand idle (the link is ours).
        const auto simulator =
            std::dynamic_pointer_cast<SimulatedJoystick>(runner.options().connect.link);
        ExperimentRunner experiment(client, simulator.get());
        std::optional<ExperimentResult> result;
        QObject::connect(&experiment, &ExperimentRunner::finished, [&](const ExperimentResult &r) {
            result = r;
            runner.wake();
        });
        if (const QString why = experiment.start(plan); !why.isEmpty()) {
            printError(why);
            return ExitBadUsage;
        }
        printNote(u"Running the " + experimentKindName(m_kind) + u" experiment for " +
                  QString::number(plan.totalDuration(), 'f', 1) + u" s; " +
                  (experiment.hand() == RunHand::SimulatedIdle
                       ? u"the simulated hand is idle meanwhile."_s
                       : u"keep hands off the knob."_s));
        int code = ExitSuccess;
        {
            // SIGINT, SIGTERM, SIGHUP: cancelled (it reports Cancelled at once), τ_ext back to 0.
            const InterruptsCall interrupts([&] { experiment.cancel(); });
            code = runner.runFor(0, [&] { return result.has_value(); });
        }
        if (!result) {
            experiment.cancel();
            return code == ExitSuccess ? ExitNoDevice : runner.reportLoss();
        }
        if (!result->completed()) {
            printError(result->problem);
            return ExitNoDevice;
        }
        // A run without its measurement (no step in τ_ext, frequencies without samples, a
        // spectrum of too few samples) prints no figures: a table of dashes is no result.
        if (result->unmeasured) {
            printError(result->problem);
            return ExitNoDevice;
        }
        if (!result->problem.isEmpty())
            printNote(u"Note: " + result->problem);
        writeOut(experimentReport(*result));
        if (!m_csvPath.isEmpty()) {
            // Through a temporary file renamed over it: a failed write (a full disk) leaves
            // an old FILE as it was, never cut short.
            if (const QString why = replaceFileContents(m_csvPath, experimentCsv(*result));
                !why.isEmpty()) {
                printError(u"Cannot write " + m_csvPath + u": " + why + u'.');
                return ExitBadUsage;
            }
        }
        return ExitSuccess;
    }

private:
    //! The experiments `option` belongs to when it is not one of m_kind's ("bode"); empty
    //! when it is, or when it is no experiment's own option.
    QString experimentOfOption(const QString &option) const
    {
        static const QStringList step{u"from"_s, u"to"_s};
        static const QStringList bode{u"offset"_s, u"amplitude"_s, u"frequencies"_s, u"cycles"_s};
        static const QStringList shared{u"duration"_s}; // step and spectrum, not bode
        if (step.contains(option) && m_kind != ExperimentKind::Step)
            return u"step"_s;
        if (bode.contains(option) && m_kind != ExperimentKind::Frequency)
            return u"bode"_s;
        if (shared.contains(option) && m_kind == ExperimentKind::Frequency)
            return u"step' and 'spectrum"_s;
        return {};
    }

    ExperimentKind m_kind = ExperimentKind::Step;
    QList<std::pair<double ExperimentPlan::*, double>> m_overrides;
    QList<double> m_frequencies;
    std::optional<int> m_cycles;
    QString m_csvPath;
};

} // namespace

std::unique_ptr<Subcommand> makeExperimentSubcommand()
{
    return std::make_unique<ExperimentSubcommand>();
}

} // namespace hatpic::cli
