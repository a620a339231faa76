// hatpicctl ports: the serial ports this machine has, and "sim".
#include "common/exitcodes.h"
#include "console.h"
#include "subcommand.h"
#include "subcommands.h"

#include "sim/simportname.h"

#include <QCommandLineParser>
#include <QSerialPortInfo>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

class PortsSubcommand final : public Subcommand
{
public:
    PortsSubcommand()
        : Subcommand(
              {.name = u"ports"_s,
               .summary = u"List serial ports, and 'sim'."_s,
               .synopsis = u"ports"_s,
               .description =
                   u"Prints one port per line: the name to pass to --port, a tab, and what the\n"
                   "system says about it. 'sim' (the simulated joystick) is always listed first.\n"
                   "Pseudo-terminals (such as the one hatpic-sim opens) are not listed."_s})
    {}

    int run(const QCommandLineParser &) override
    {
        QString text =
            QString::fromUtf16(kSimPortName) + u"\tsimulated joystick inside hatpicctl\n"_s;
        for (const QSerialPortInfo &port : QSerialPortInfo::availablePorts()) {
            QStringList about;
            if (!port.description().isEmpty())
                about << port.description();
            if (!port.manufacturer().isEmpty())
                about << port.manufacturer();
            if (!port.serialNumber().isEmpty())
                about << u"serial " + port.serialNumber();
            text += port.systemLocation() + u'\t' + about.join(u", "_s) + u'\n';
        }
        writeOut(text);
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makePortsSubcommand()
{
    return std::make_unique<PortsSubcommand>();
}

} // namespace hatpic::cli
