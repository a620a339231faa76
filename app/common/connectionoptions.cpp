#include "common/connectionoptions.h"

#include "model/params.h"
#include "sim/simulatedjoystick.h"

#include <QCommandLineParser>

namespace hatpic {

namespace {

struct Spec
{
    ConnectionOption option;
    const char *shortName; //!< nullptr: none
    const char *name;
    const char *valueName;
    const char *help;
};

constexpr Spec kOptions[] = {
    {ConnectionOption::Port, "p", "port", "PORT",
     "Serial device (e.g. /dev/ttyUSB0, a pty) or 'sim' for the built-in simulated joystick."},
    {ConnectionOption::Baud, "b", "baud", "N",
     "Baud rate, 300 to 4000000 (default: 921600 for v2, 115200 for legacy; auto listens at "
     "115200, then asks at 921600)."},
    {ConnectionOption::Protocol, nullptr, "protocol", "NAME",
     "auto (detect), v2 or legacy (default: auto)."},
    {ConnectionOption::Faults, nullptr, "faults", "SPEC",
     "With --port sim: faults the simulated link injects, e.g. drop=0.01,cut=30s:2s "
     "(docs/simulator.md)."},
    {ConnectionOption::Seed, nullptr, "seed", "N",
     "With --port sim: seed of the faults and the load noise (default: 1)."},
};

const Spec &spec(ConnectionOption option)
{
    for (const Spec &s : kOptions) {
        if (s.option == option)
            return s;
    }
    Q_UNREACHABLE();
}

QString name(ConnectionOption option)
{
    return QLatin1String(spec(option).name);
}

// Text the user gave, as a message quotes it (echoedText(): a long value is cut).
QString echoed(const QString &text)
{
    return QString::fromStdString(echoedText(text.toStdString()));
}

// "--NAME must be RULE, got 'TEXT'."
QString mustBe(ConnectionOption option, const QString &rule, const QString &text)
{
    return u"--" + name(option) + u" must be " + rule + u", got '" + echoed(text) + u"'.";
}

} // namespace

QCommandLineOption connectionOption(ConnectionOption option, const QString &help)
{
    const Spec &s = spec(option);
    QStringList names;
    if (s.shortName)
        names << QLatin1String(s.shortName);
    names << QLatin1String(s.name);
    return QCommandLineOption(names, help.isEmpty() ? QString::fromUtf8(s.help) : help,
                              QLatin1String(s.valueName));
}

QString baudRule()
{
    return u"a whole number of baud from " + QString::number(kMinBaud) + u" to " +
           QString::number(kMaxBaud);
}

std::optional<qint32> baudValue(const QString &text)
{
    bool ok = false;
    const qint32 baud = text.trimmed().toInt(&ok);
    if (!ok || baud < kMinBaud || baud > kMaxBaud)
        return std::nullopt;
    return baud;
}

std::optional<qint32> parseBaud(const QString &text, QString *error)
{
    const std::optional<qint32> baud = baudValue(text);
    if (!baud)
        *error = mustBe(ConnectionOption::Baud, baudRule(), text);
    return baud;
}

std::optional<ProtocolChoice> parseProtocol(const QString &text, QString *error, bool allowAuto)
{
    const QString lower = text.trimmed().toLower();
    if (allowAuto && lower == u"auto")
        return ProtocolChoice::Auto;
    if (lower == u"v2")
        return ProtocolChoice::V2;
    if (lower == u"legacy")
        return ProtocolChoice::Legacy;
    *error = mustBe(
        ConnectionOption::Protocol,
        allowAuto ? QStringLiteral("auto, v2 or legacy") : QStringLiteral("v2 or legacy"), text);
    return std::nullopt;
}

std::optional<FaultSpec> parseFaults(const QString &text, QString *error)
{
    QString problem;
    std::optional<FaultSpec> faults = FaultSpec::parse(text, &problem);
    if (!faults)
        *error = u"--faults: " + problem;
    return faults;
}

std::optional<quint64> parseSeed(const QString &text, QString *error)
{
    bool ok = false;
    const quint64 seed = text.trimmed().toULongLong(&ok);
    if (!ok) {
        *error =
            mustBe(ConnectionOption::Seed, QStringLiteral("a non-negative whole number"), text);
        return std::nullopt;
    }
    return seed;
}

void linkSimulator(ConnectOptions &options, const SimulatedDevice::Config &config)
{
    if (options.port != QStringView(kSimPortName))
        return;
    auto joystick = std::make_shared<SimulatedJoystick>(config);
    joystick->answerIn(options.protocol);
    options.link = std::move(joystick);
}

bool readConnectionOptions(const QCommandLineParser &parser, ConnectOptions &options,
                           QString *error)
{
    const auto isSet = [&](ConnectionOption o) { return parser.isSet(name(o)); };
    const auto value = [&](ConnectionOption o) { return parser.value(name(o)); };
    options.port = value(ConnectionOption::Port);
    if (isSet(ConnectionOption::Baud)) {
        const auto baud = parseBaud(value(ConnectionOption::Baud), error);
        if (!baud)
            return false;
        options.baud = *baud;
    }
    if (isSet(ConnectionOption::Protocol)) {
        const auto protocol = parseProtocol(value(ConnectionOption::Protocol), error);
        if (!protocol)
            return false;
        options.protocol = *protocol;
    }
    SimulatedDevice::Config sim;
    if (isSet(ConnectionOption::Faults)) {
        const auto faults = parseFaults(value(ConnectionOption::Faults), error);
        if (!faults)
            return false;
        sim.faults = *faults;
    }
    if (isSet(ConnectionOption::Seed)) {
        const auto seed = parseSeed(value(ConnectionOption::Seed), error);
        if (!seed)
            return false;
        sim.seed = *seed;
    }
    if ((isSet(ConnectionOption::Faults) || isSet(ConnectionOption::Seed)) &&
        options.port != QStringView(kSimPortName)) {
        *error = QStringLiteral("--faults and --seed act on the built-in simulated joystick: use "
                                "them with --port sim (hatpic-sim has its own).");
        return false;
    }
    linkSimulator(options, sim);
    return true;
}

} // namespace hatpic
