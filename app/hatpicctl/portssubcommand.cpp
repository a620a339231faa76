// hatpicctl ports: the serial ports this machine has, and "sim".
#include "common/exitcodes.h"
#include "console.h"
#include "subcommand.h"
#include "subcommands.h"

#include "sim/simportname.h"

#include <QCommandLineParser>
#include <QSerialPortInfo>

namespace hatpic::cli {

namespace {

class PortsSubcommand final : public Subcommand
{
public:
    QString name() const override { return QStringLiteral("ports"); }
    QString summary() const override { return QStringLiteral("List serial ports, and 'sim'."); }
    QString synopsis() const override { return QStringLiteral("ports"); }
    QString description() const override
    {
        return QStringLiteral(
            "Prints one port per line: the name to pass to --port, a tab, and what the\n"
            "system says about it. 'sim' (the simulated joystick) is always listed first.\n"
            "Pseudo-terminals (such as the one hatpic-sim opens) are not listed.");
    }
    void addOptions(QCommandLineParser &parser) override { Q_UNUSED(parser); }

    int run(const QCommandLineParser &parser) override
    {
        Q_UNUSED(parser);
        QString text = QString::fromUtf16(kSimPortName) +
                       QStringLiteral("\tsimulated joystick inside hatpicctl\n");
        for (const QSerialPortInfo &port : QSerialPortInfo::availablePorts()) {
            QStringList about;
            if (!port.description().isEmpty())
                about << port.description();
            if (!port.manufacturer().isEmpty())
                about << port.manufacturer();
            if (!port.serialNumber().isEmpty())
                about << u"serial " + port.serialNumber();
            text += port.systemLocation() + u'\t' + about.join(QStringLiteral(", ")) + u'\n';
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
