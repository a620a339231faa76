// The connection options, defined once for every program that takes them: --port, --baud,
// --protocol, --faults and --seed (hatpic-tuner, hatpicctl, hatpic-bridge; hatpic-sim's
// --baud, --protocol, --seed and --faults, and the other pty programs' --seed and --faults).
// One name, value name, help text, bound and sentence each; each sentence names the option
// and quotes the value ("--baud must be …, got 'fast'.").
#pragma once

#include "link/faultinjector.h"
#include "session/sessiontypes.h"
#include "sim/simulateddevice.h"

#include <QCommandLineOption>
#include <QString>

#include <optional>

class QCommandLineParser;

namespace hatpic {

enum class ConnectionOption { Port, Baud, Protocol, Faults, Seed };

//! The baud rates every program accepts, for a serial port as for an emulated link: 300, the
//! lowest rate USB serial adapters offer, to 4 000 000, Linux's highest named rate (B4000000).
inline constexpr qint32 kMinBaud = 300;
inline constexpr qint32 kMaxBaud = 4000000;

//! The option with its shared names, value name and help; `help` replaces the help where a
//! program means it its own way (hatpic-sim's --baud is the emulated link's rate).
QCommandLineOption connectionOption(ConnectionOption option, const QString &help = {});

//! What a baud value must be: "a whole number of baud from 300 to 4000000".
QString baudRule();
//! `text` as a baud rate within the bounds, else nullopt.
std::optional<qint32> baudValue(const QString &text);

// Each reads the option's text; on a bad value it sets `*error` to the option's sentence.
std::optional<qint32> parseBaud(const QString &text, QString *error);
//! auto, v2 or legacy (any case); without `allowAuto` only v2 or legacy (hatpic-sim, which is
//! one device).
std::optional<ProtocolChoice> parseProtocol(const QString &text, QString *error,
                                            bool allowAuto = true);
std::optional<FaultSpec> parseFaults(const QString &text, QString *error);
std::optional<quint64> parseSeed(const QString &text, QString *error);

//! For the port "sim", makes the program's link: an in-process SimulatedJoystick
//! (sim/simulatedjoystick.h) of `config`, speaking the protocol options.protocol chose, as
//! options.link. Any other port is left to the session, which opens it as a serial port.
void linkSimulator(ConnectOptions &options, const SimulatedDevice::Config &config = {});

//! Reads the options that `parser` has set into `options` (port, baud, protocol) and makes the
//! link of --port sim (linkSimulator() with --faults and --seed). Refuses --faults or --seed
//! without --port sim. False with `*error` set to one sentence. A missing --port is the
//! caller's to judge.
bool readConnectionOptions(const QCommandLineParser &parser, ConnectOptions &options,
                           QString *error);

} // namespace hatpic
