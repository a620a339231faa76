// What every program behind a pseudo-terminal shares (hatpic-sim, hatpic-fw-host,
// hatpic-servo-sim): the command line (the options two or more of them take, with one name,
// value name, default, bound and sentence each, plus the program's own options), the exit
// codes, and the start-up: start the host, make the --link symlink, print the terminal's path
// as the first stdout line.
#pragma once

#include "common/exitcodes.h"
#include "common/quitonsignal.h"
#include "link/faultinjector.h"
#include "model/axes.h"
#include "sim/handinput.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

#include <array>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>

class QCoreApplication;

namespace hatpic {

//! What PtyProgram::serve() returns: true when the host runs. While it lives, a fatal signal
//! runs the host's emergencyStop() (onFatalSignal); its end withdraws that, so declare it after
//! the host, which it must not outlive.
class [[nodiscard]] Serving
{
public:
    explicit Serving(bool running) : m_running(running) {}
    ~Serving();
    Serving(const Serving &) = delete;
    Serving &operator=(const Serving &) = delete;
    explicit operator bool() const { return m_running; }

private:
    bool m_running;
};

//! The options that more than one pty program takes (see kSharedOptions in ptyprogram.cpp).
enum class SharedOption { Hand, Rate, Seed, ServoId, Servos, CenterTick, State, Faults, Link };

//! One pty program's command line and start-up. Add the options in --help order, parse(),
//! read them; every reader prints its one sentence ("PROGRAM: …" on stderr) and returns false
//! on a bad value, and leaves its output as it is when the option is absent and has no default.
class PtyProgram
{
public:
    // The shared table's codes (common/exitcodes.h).
    static constexpr int kExitOk = ExitSuccess;
    static constexpr int kExitFailure = ExitFailure;     //!< no pty, no link, no servo
    static constexpr int kExitBadOptions = ExitBadUsage; //!< one sentence on stderr
    static constexpr double kMaxRateHz = 20000;          //!< highest --rate accepted [Hz]

    //! `program` names the program in every sentence; `description` heads --help, followed by
    //! what all of them do ("Prints the terminal's path as the first line, …").
    PtyProgram(QCoreApplication &app, const char *program, const QString &description);

    //! Adds a shared option; `help` words it this program's way where the meaning differs
    //! (required for the options that have no shared help text: seed, servo-id, center-tick,
    //! faults).
    void add(SharedOption option, const char *help = nullptr);
    //! Adds an option of this program's own.
    QCommandLineOption add(const char *name, const char *help, const char *valueName = nullptr,
                           const char *fallback = nullptr);

    //! Parses the arguments. --help prints the help and exits 0; an unknown option, a missing
    //! value or a positional argument gets its sentence and false.
    bool parse();
    bool isSet(const QCommandLineOption &option) const { return m_parser.isSet(option); }
    QString value(const QCommandLineOption &option) const { return m_parser.value(option); }

    bool readHand(HandInput &hand) const;
    //! --hand-2 … --hand-N: the hands on a board's other knobs, as --hand (default idle);
    //! `where` says when they apply ("imu-branch", "--servos N").
    using OtherHandOptions = std::array<QCommandLineOption, kMaxAxes - 1>;
    OtherHandOptions addOtherHands(const char *where);
    //! Those of `options` that are set, into `hands`; false after the sentence naming the
    //! option.
    bool readOtherHands(const OtherHandOptions &options,
                        std::array<HandInput, kMaxAxes - 1> &hands) const;
    bool readRate(double &hz) const;
    //! Into quint64 (SimulatedDevice, FirmwareHost) or std::uint64_t (ServoBusHost).
    template<typename Unsigned> bool readSeed(Unsigned &seed) const
    {
        return assign(seedValue(), seed);
    }
    bool readServoId(std::uint8_t &id) const;
    //! --servos: 1…kMaxAxes servos, ids `firstId`, +1, … all within the bus's 0…253.
    bool readServos(std::uint8_t firstId, int &servos) const;
    bool readCenterTick(std::int32_t &tick) const;
    //! Refuses an empty name and an existing pipe, device or folder, which would block open()
    //! (or fail late) before the signal handling runs.
    bool readStateFile(QString &file) const;
    bool readFaults(FaultSpec &faults) const;
    //! The --link path, kept for serve().
    bool readLink();
    //! `text` as a whole number from `low` to `high`, else the sentence naming `what`.
    std::optional<qint64> wholeNumber(const QString &text, qint64 low, qint64 high,
                                      const char *what) const;

    //! "PROGRAM: sentence" on stderr.
    void printError(const QString &sentence) const;
    //! `report` runs on each SIGUSR1 (reportOnSignal); false after the sentence.
    bool reportOnSignal(std::function<void()> report) const;

    //! Makes every signal that would end the program quit the event loop instead, or run the
    //! host's emergencyStop() when it cannot wait for the loop (quitOnSignals), then starts
    //! `host` (SimulatorHost, FirmwareHost, ServoBusHost: start(), createLink(), stop(),
    //! emergencyStop(), slavePath()) and, when --link was given, makes the symlink. On failure
    //! the one sentence is printed, the host is stopped, and the result is false. On success
    //! the slave's path goes to stdout as the first line, flushed.
    template<typename Host> Serving serve(Host &host) const
    {
        static Host *served = nullptr; // for the fatal-signal action, which takes no argument
        if (!installSignalHandlers())
            return Serving(false);
        // Before start(), which switches the torque on: emergencyStop() does what is possible
        // at any point of it.
        served = &host;
        onFatalSignal([] { served->emergencyStop(); });
        if (const QString error = host.start(); !error.isEmpty()) {
            printError(error);
            onFatalSignal(nullptr);
            return Serving(false);
        }
        if (!m_link.isEmpty()) {
            if (const QString error = host.createLink(m_link); !error.isEmpty()) {
                printError(error);
                onFatalSignal(nullptr);
                host.stop();
                return Serving(false);
            }
        }
        std::fprintf(stdout, "%s\n", qPrintable(host.slavePath()));
        std::fflush(stdout);
        return Serving(true);
    }

    //! The exit code for what QCoreApplication::exec() returned: 0, or 1 for a failure; after
    //! a signal other than SIGINT and SIGTERM (SIGHUP, SIGXCPU, …) 128 + its number, as a shell
    //! reports a program that signal ended — the stop was the same orderly one.
    static int exitCode(int loopCode);

private:
    //! `out` = `value` when there is one.
    template<typename Out, typename Value>
    static bool assign(const std::optional<Value> &value, Out &out)
    {
        if (value)
            out = Out(*value);
        return value.has_value();
    }
    bool installSignalHandlers() const; //!< quitOnSignals(); false after the sentence
    std::optional<quint64> seedValue() const;
    //! `parse(text, &error)` (HandInput::parse, FaultSpec::parse) into `out`, else the error.
    template<typename Value>
    bool parseInto(const QString &text, std::optional<Value> (*parse)(const QString &, QString *),
                   Value &out) const
    {
        QString error;
        const std::optional<Value> parsed = parse(text, &error);
        if (!parsed) {
            printError(error);
            return false;
        }
        out = *parsed;
        return true;
    }
    QString optionValue(SharedOption option) const;
    bool optionIsSet(SharedOption option) const;

    QCoreApplication &m_app;
    const char *m_program;
    QCommandLineParser m_parser;
    QCommandLineOption m_help;
    QString m_link;
};

} // namespace hatpic
