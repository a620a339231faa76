// A hatpicctl subcommand, and the dispatcher that picks one from the command line.
#pragma once

#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

class QCommandLineParser;

namespace hatpic::cli {

class Subcommand
{
public:
    virtual ~Subcommand() = default;

    virtual QString name() const = 0;     //!< "curve"
    virtual QString summary() const = 0;  //!< one line for `hatpicctl --help`
    virtual QString synopsis() const = 0; //!< "curve --profile FILE [--from RAD] …"
    //! Paragraphs shown by `hatpicctl NAME --help` under the synopsis.
    virtual QString description() const = 0;
    //! Registers the subcommand's options (the dispatcher adds --help itself).
    virtual void addOptions(QCommandLineParser &parser) = 0;
    //! Whether free arguments (besides options) are accepted; validate takes a FILE.
    virtual bool acceptsPositional() const { return false; }
    //! Runs with parsed arguments; returns an ExitCode. Failures print one sentence first.
    virtual int run(const QCommandLineParser &parser) = 0;
};

//! Every subcommand, in the order `hatpicctl --help` lists them.
std::vector<std::unique_ptr<Subcommand>> allSubcommands();

//! Parses `arguments` (as QCoreApplication::arguments(), program first), runs the chosen
//! subcommand and returns the process exit code.
int dispatch(const QStringList &arguments);

} // namespace hatpic::cli
