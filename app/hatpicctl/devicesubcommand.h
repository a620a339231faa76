// Base of the subcommands that talk to a device: shared options, connect, then the command.
#pragma once

#include "deviceoptions.h"
#include "subcommand.h"

namespace hatpic::cli {

class DeviceRunner;

class DeviceSubcommand : public Subcommand
{
public:
    //! Whether the subcommand reaches one knob of several (--knob N: get, set, zero, vibrate).
    enum class Knobs { None, One };

    //! The description gets the paragraph on --port every device subcommand ends with.
    explicit DeviceSubcommand(SubcommandText text, Knobs knobs = Knobs::None);

    void addOptions(QCommandLineParser &parser) final;
    int run(const QCommandLineParser &parser) final;

protected:
    //! The options specific to the subcommand.
    virtual void addCommandOptions(QCommandLineParser &parser) { Q_UNUSED(parser); }
    //! Checks the subcommand's own options before any port is opened (bad usage → 4); may
    //! adjust the connection (e.g. the stream rate).
    virtual int prepare(const QCommandLineParser &parser, DeviceOptions &options);
    //! Runs once the device is connected.
    virtual int runConnected(DeviceRunner &runner, const QCommandLineParser &parser) = 0;

    //! --json, "Print a profile (JSON).": get, set and zero.
    static void addJsonOption(QCommandLineParser &parser);
    //! The knob --knob named (Knobs::One; 0 for knob 1, also when absent), read before
    //! prepare(). The device's own count is checked once it answered.
    Knob knob() const { return m_knob; }
    //! " of knob N" for knob 2 and on, else nothing: the sentences of a command for one knob.
    QString ofKnob() const;

private:
    //! Reads --knob into m_knob; bad usage (4, with one sentence) when it is not a knob's number.
    int readKnob(const QCommandLineParser &parser);

    Knobs m_knobs;
    Knob m_knob = 0;
};

} // namespace hatpic::cli
