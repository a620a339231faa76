// hatpicctl info: who answered on the port.
#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"
#include "devicesubcommand.h"
#include "paramtext.h"
#include "subcommands.h"
#include "telemetry/numbertext.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>

namespace hatpic::cli {

namespace {

class InfoSubcommand final : public DeviceSubcommand
{
public:
    QString name() const override { return QStringLiteral("info"); }
    QString summary() const override
    {
        return QStringLiteral("Show the device's identity, protocol and limits.");
    }
    QString synopsis() const override { return QStringLiteral("info --port PORT [--json]"); }
    QString description() const override
    {
        return QStringLiteral("Connects (detecting the protocol unless --protocol is given) and "
                              "prints what the\ndevice reported about itself.\n\n") +
               portHelp();
    }

protected:
    void addCommandOptions(QCommandLineParser &parser) override
    {
        parser.addOption(QCommandLineOption(QStringList{QStringLiteral("json")},
                                            QStringLiteral("Print a JSON object.")));
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        const DeviceInfo info = runner.client().deviceInfo();
        const QString deviceId = u"0x" + QString::number(info.deviceId, 16).rightJustified(8, u'0');
        if (parser.isSet(QStringLiteral("json"))) {
            QJsonObject object;
            object.insert(QStringLiteral("port"), info.port);
            object.insert(QStringLiteral("protocol"), wireProtocolName(info.protocol));
            object.insert(QStringLiteral("protocol_version"), info.protocolVersion);
            object.insert(QStringLiteral("baud"), info.baud);
            object.insert(QStringLiteral("device_id"), deviceId);
            object.insert(QStringLiteral("firmware"), info.firmware);
            object.insert(QStringLiteral("max_stream_hz"), info.maxStreamHz);
            object.insert(QStringLiteral("tau_limit"), shortestFloatDecimal(info.tauLimit));
            object.insert(QStringLiteral("can_set_params"), info.canSetParams());
            object.insert(QStringLiteral("simulated"), info.simulated);
            writeOut(QJsonDocument(object).toJson(QJsonDocument::Indented));
            return ExitSuccess;
        }
        const auto line = [](const QString &key, const QString &value) -> QString {
            return key.leftJustified(18) + value + u'\n';
        };
        QString text;
        text += line(QStringLiteral("port"), info.port);
        text += line(QStringLiteral("protocol"), wireProtocolName(info.protocol));
        text += line(QStringLiteral("protocol version"), QString::number(info.protocolVersion));
        text += line(QStringLiteral("baud"), QString::number(info.baud));
        text += line(QStringLiteral("device id"), deviceId);
        text += line(QStringLiteral("firmware"), info.firmware);
        text += line(QStringLiteral("max stream"), QString::number(info.maxStreamHz) + u" Hz");
        text += line(QStringLiteral("tau_limit"), compactNumberText(info.tauLimit) + u" N·m");
        text += line(QStringLiteral("parameters"), info.canSetParams()
                                                       ? QStringLiteral("read and write")
                                                       : QStringLiteral("not carried (legacy)"));
        text += line(QStringLiteral("simulated"),
                     info.simulated ? QStringLiteral("yes") : QStringLiteral("no"));
        writeOut(text);
        return ExitSuccess;
    }
};

} // namespace

std::unique_ptr<Subcommand> makeInfoSubcommand()
{
    return std::make_unique<InfoSubcommand>();
}

} // namespace hatpic::cli
