#include "common/ptyprogram.h"

#include "common/connectionoptions.h"

#include "firmware/devicecore.h"
#include "firmware/sts3032.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <csignal>

#include <utility>

namespace hatpic {

namespace {

constexpr qint64 kMaxCenterTick = 4095; //!< highest --center-tick (12-bit position)
//! Lowest --rate: the device core's, below which the feedback watchdog cannot hold [Hz].
constexpr double kMinRateHz = fw::DeviceCore<double>::kMinControlRate;

struct SharedOptionSpec
{
    SharedOption option;
    const char *name;
    const char *help; //!< nullptr: each program words its own
    const char *valueName;
    const char *fallback;
};

// The table of the shared options: one name, value name, default and (where the programs
// mean the same) help text each.
constexpr SharedOptionSpec kSharedOptions[] = {
    {SharedOption::Hand, "hand",
     "Operator input: idle, const:T, step:T[:T0[:AT]], sine:A:F, chirp:A:F0:F1 or hand:ANGLE (N·m, "
     "Hz, rad).",
     "SPEC", "idle"},
    {SharedOption::Rate, "rate", "Control rate [Hz] (default 1000).", "HZ", "1000"},
    {SharedOption::Seed, "seed", nullptr, "N", "1"},
    {SharedOption::ServoId, "servo-id", nullptr, "N", "1"},
    {SharedOption::Servos, "servos", nullptr, "N", "1"},
    {SharedOption::CenterTick, "center-tick", nullptr, "N", "1000"},
    {SharedOption::State, "state", "Profile file that SAVE_PARAMS writes and power-up reads.",
     "FILE", nullptr},
    {SharedOption::Faults, "faults", nullptr, "SPEC", nullptr},
    {SharedOption::Link, "link", "Symlink to create to the terminal (removed on exit).", "PATH",
     nullptr},
};

const SharedOptionSpec &spec(SharedOption option)
{
    for (const SharedOptionSpec &entry : kSharedOptions) {
        if (entry.option == option)
            return entry;
    }
    Q_UNREACHABLE();
}

QCommandLineOption makeOption(const char *name, const char *help, const char *valueName,
                              const char *fallback)
{
    return QCommandLineOption(QLatin1String(name), QString::fromUtf8(help),
                              valueName ? QLatin1String(valueName) : QString(),
                              fallback ? QLatin1String(fallback) : QString());
}

} // namespace

PtyProgram::PtyProgram(QCoreApplication &app, const char *program, const QString &description)
    : m_app(app), m_program(program), m_help(m_parser.addHelpOption())
{
    QCoreApplication::setApplicationName(QLatin1String(program));
    QCoreApplication::setApplicationVersion(QStringLiteral("0.1"));
    m_parser.setApplicationDescription(description +
                                       QStringLiteral(" Prints the terminal's path as the first "
                                                      "line, then runs until SIGINT or SIGTERM."));
}

void PtyProgram::add(SharedOption option, const char *help)
{
    const SharedOptionSpec &entry = spec(option);
    Q_ASSERT(help || entry.help);
    m_parser.addOption(
        makeOption(entry.name, help ? help : entry.help, entry.valueName, entry.fallback));
}

QCommandLineOption PtyProgram::add(const char *name, const char *help, const char *valueName,
                                   const char *fallback)
{
    QCommandLineOption option = makeOption(name, help, valueName, fallback);
    m_parser.addOption(option);
    return option;
}

bool PtyProgram::parse()
{
    if (!m_parser.parse(m_app.arguments())) {
        QString text = m_parser.errorText();
        if (!text.endsWith(QLatin1Char('.')))
            text += QLatin1Char('.');
        printError(text);
        return false;
    }
    if (m_parser.isSet(m_help))
        m_parser.showHelp(kExitOk); // exits
    if (!m_parser.positionalArguments().isEmpty()) {
        printError(QStringLiteral("Unexpected argument \"%1\"; %2 takes only options.")
                       .arg(m_parser.positionalArguments().first(), QLatin1String(m_program)));
        return false;
    }
    return true;
}

QString PtyProgram::optionValue(SharedOption option) const
{
    return m_parser.value(QLatin1String(spec(option).name));
}

bool PtyProgram::optionIsSet(SharedOption option) const
{
    return m_parser.isSet(QLatin1String(spec(option).name));
}

bool PtyProgram::readHand(HandInput &hand) const
{
    return parseInto(optionValue(SharedOption::Hand), &HandInput::parse, hand);
}

PtyProgram::OtherHandOptions PtyProgram::addOtherHands(const char *where)
{
    const auto make = [&](int knob) {
        const QString name = QStringLiteral("hand-%1").arg(knob);
        const QString help =
            knob == 2 ? QStringLiteral("%1: the hand on knob 2, as --hand (default idle).")
                            .arg(QString::fromUtf8(where))
                      : QStringLiteral("%1: the hand on knob %2, likewise.")
                            .arg(QString::fromUtf8(where))
                            .arg(knob);
        QCommandLineOption option(name, help, QStringLiteral("SPEC"));
        m_parser.addOption(option);
        return option;
    };
    return {make(2), make(3), make(4)};
}

bool PtyProgram::readOtherHands(const OtherHandOptions &options,
                                std::array<HandInput, kMaxAxes - 1> &hands) const
{
    for (std::size_t k = 0; k < options.size(); ++k) {
        if (!isSet(options[k]))
            continue;
        QString error;
        const auto hand = HandInput::parse(value(options[k]), &error);
        if (!hand) {
            printError(QStringLiteral("--hand-%1: %2").arg(k + 2).arg(error));
            return false;
        }
        hands[k] = *hand;
    }
    return true;
}

bool PtyProgram::readRate(double &hz) const
{
    const QString text = optionValue(SharedOption::Rate);
    bool ok = false;
    const double rate = text.toDouble(&ok);
    if (!ok || !(rate >= kMinRateHz && rate <= kMaxRateHz)) {
        printError(QStringLiteral("The control rate \"%1\" must be a number of Hz from %2 to %3 "
                                  "(a period of at most half the %4 ms feedback watchdog).")
                       .arg(text)
                       .arg(kMinRateHz)
                       .arg(PtyProgram::kMaxRateHz)
                       .arg(fw::Controller<double>::kFeedbackWatchdogUs / 1000));
        return false;
    }
    hz = rate;
    return true;
}

std::optional<quint64> PtyProgram::seedValue() const
{
    QString error;
    const std::optional<quint64> seed = parseSeed(optionValue(SharedOption::Seed), &error);
    if (!seed)
        printError(error);
    return seed;
}

bool PtyProgram::readServoId(std::uint8_t &id) const
{
    return assign(wholeNumber(optionValue(SharedOption::ServoId), 0, fw::sts::kMaxId, "servo id"),
                  id);
}

bool PtyProgram::readServos(std::uint8_t firstId, int &servos) const
{
    const auto count = wholeNumber(optionValue(SharedOption::Servos), 1, kMaxAxes, "servo count");
    if (!count)
        return false;
    const int last = int(firstId) + int(*count) - 1;
    if (last > int(fw::sts::kMaxId)) {
        printError(QStringLiteral("servo id: %1 servos from id %2 would end at id %3, beyond %4.")
                       .arg(*count)
                       .arg(firstId)
                       .arg(last)
                       .arg(int(fw::sts::kMaxId)));
        return false;
    }
    servos = int(*count);
    return true;
}

bool PtyProgram::readCenterTick(std::int32_t &tick) const
{
    return assign(
        wholeNumber(optionValue(SharedOption::CenterTick), 0, kMaxCenterTick, "center tick"), tick);
}

bool PtyProgram::readStateFile(QString &file) const
{
    if (!optionIsSet(SharedOption::State))
        return true;
    const QString name = optionValue(SharedOption::State);
    if (name.isEmpty()) {
        printError(QStringLiteral("The state file name is empty."));
        return false;
    }
    const QFileInfo state(name);
    if (state.exists() && !state.isFile()) {
        printError(QStringLiteral("The state file \"%1\" is not a regular file (a pipe, a "
                                  "device or a folder).")
                       .arg(name));
        return false;
    }
    file = name;
    return true;
}

bool PtyProgram::readFaults(FaultSpec &faults) const
{
    if (!optionIsSet(SharedOption::Faults))
        return true;
    QString error;
    const std::optional<FaultSpec> parsed = parseFaults(optionValue(SharedOption::Faults), &error);
    if (!parsed) {
        printError(error);
        return false;
    }
    faults = *parsed;
    return true;
}

bool PtyProgram::readLink()
{
    if (!optionIsSet(SharedOption::Link))
        return true;
    m_link = optionValue(SharedOption::Link);
    if (m_link.isEmpty()) {
        printError(QStringLiteral("The link path is empty."));
        return false;
    }
    return true;
}

std::optional<qint64> PtyProgram::wholeNumber(const QString &text, qint64 low, qint64 high,
                                              const char *what) const
{
    bool ok = false;
    const qint64 value = text.toLongLong(&ok);
    if (ok && value >= low && value <= high)
        return value;
    printError(QStringLiteral("The %1 \"%2\" must be a whole number from %3 to %4.")
                   .arg(QLatin1String(what), text)
                   .arg(low)
                   .arg(high));
    return std::nullopt;
}

void PtyProgram::printError(const QString &sentence) const
{
    std::fprintf(stderr, "%s: %s\n", m_program, qPrintable(sentence));
}

Serving::~Serving()
{
    if (m_running)
        onFatalSignal(nullptr);
}

int PtyProgram::exitCode(int loopCode)
{
    const int signal = quitSignal();
    if (signal != 0 && signal != SIGINT && signal != SIGTERM)
        return 128 + signal;
    return loopCode == 0 ? kExitOk : kExitFailure;
}

bool PtyProgram::installSignalHandlers() const
{
    if (quitOnSignals())
        return true;
    printError(QStringLiteral("Cannot set up signal handling."));
    return false;
}

bool PtyProgram::reportOnSignal(std::function<void()> report) const
{
    if (hatpic::reportOnSignal(std::move(report)))
        return true;
    printError(QStringLiteral("Cannot set up signal handling."));
    return false;
}

} // namespace hatpic
