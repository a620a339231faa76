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

using namespace Qt::StringLiterals;

namespace {

class InfoSubcommand final : public DeviceSubcommand
{
public:
    InfoSubcommand()
        : DeviceSubcommand({.name = u"info"_s,
                            .summary = u"Show the device's identity, protocol and limits."_s,
                            .synopsis = u"info --port PORT [--json]"_s,
                            .description =
                                u"Connects (detecting the protocol unless --protocol is given) and "
                                "prints what the\ndevice reported about itself."_s})
    {}

protected:
    void addCommandOptions(QCommandLineParser &parser) override
    {
        parser.addOption({u"json"_s, u"Print a JSON object."_s});
    }

    int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) override
    {
        const DeviceInfo info = runner.client().deviceInfo();
        const QString deviceId = u"0x" + QString::number(info.deviceId, 16).rightJustified(8, u'0');
        if (parser.isSet(u"json"_s)) {
            QJsonObject object;
            object.insert(u"port"_s, info.port);
            object.insert(u"protocol"_s, wireProtocolName(info.protocol));
            object.insert(u"protocol_version"_s, info.protocolVersion);
            object.insert(u"baud"_s, info.baud);
            object.insert(u"device_id"_s, deviceId);
            object.insert(u"firmware"_s, info.firmware);
            object.insert(u"max_stream_hz"_s, info.maxStreamHz);
            object.insert(u"tau_limit"_s, shortestFloatDecimal(info.tauLimit));
            object.insert(u"can_set_params"_s, info.canSetParams());
            object.insert(u"simulated"_s, info.simulated);
            if (info.axes > 1 || info.tilt) { // a board with several knobs (the IMU branch)
                object.insert(u"axes"_s, info.axes);
                object.insert(u"tilt"_s, info.tilt);
            }
            writeOut(QJsonDocument(object).toJson(QJsonDocument::Indented));
            return ExitSuccess;
        }
        const auto line = [](const QString &key, const QString &value) -> QString {
            return key.leftJustified(18) + value + u'\n';
        };
        QString text;
        text += line(u"port"_s, info.port);
        text += line(u"protocol"_s, wireProtocolName(info.protocol));
        text += line(u"protocol version"_s, QString::number(info.protocolVersion));
        text += line(u"baud"_s, QString::number(info.baud));
        text += line(u"device id"_s, deviceId);
        text += line(u"firmware"_s, info.firmware);
        text += line(u"max stream"_s, QString::number(info.maxStreamHz) + u" Hz");
        text += line(u"tau_limit"_s, compactNumberText(info.tauLimit) + u" N·m");
        text += line(u"parameters"_s,
                     info.canSetParams() ? u"read and write"_s : u"not carried (legacy)"_s);
        text += line(u"simulated"_s, info.simulated ? u"yes"_s : u"no"_s);
        if (info.axes > 1 || info.tilt) {
            text += line(u"knobs"_s, QString::number(info.axes));
            text += line(u"tilt"_s, info.tilt ? u"roll and pitch"_s : u"none"_s);
        }
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
