// A hatpicctl subcommand, and the dispatcher that picks one from the command line.
#pragma once

#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

class QCommandLineParser;

namespace hatpic::cli {

//! What `hatpicctl --help` and `hatpicctl NAME --help` say of a subcommand.
struct SubcommandText
{
    QString name;                   //!< "curve"
    QString summary;                //!< one line for `hatpicctl --help`
    QString synopsis;               //!< "curve --profile FILE [--from RAD] …"
    QString description;            //!< paragraphs under the synopsis in `NAME --help`
    bool acceptsPositional = false; //!< free arguments besides options (validate's FILE)
};

class Subcommand
{
public:
    explicit Subcommand(SubcommandText text) : m_text(std::move(text)) {}
    virtual ~Subcommand() = default;

    const SubcommandText &text() const { return m_text; }
    //! Registers the subcommand's options (the dispatcher adds --help itself).
    virtual void addOptions(QCommandLineParser &parser) { Q_UNUSED(parser); }
    //! Runs with parsed arguments; returns an ExitCode. Failures print one sentence first.
    virtual int run(const QCommandLineParser &parser) = 0;

private:
    SubcommandText m_text;
};

//! Every subcommand, in the order `hatpicctl --help` lists them.
std::vector<std::unique_ptr<Subcommand>> allSubcommands();

//! Parses `arguments` (as QCoreApplication::arguments(), program first), runs the chosen
//! subcommand and returns the process exit code.
int dispatch(const QStringList &arguments);

} // namespace hatpic::cli
