// What a session connects through when it is not a serial port: the program makes it (the
// in-process simulator is sim/simulatedjoystick.h) and hands it to the session in its
// ConnectOptions; the session makes a fresh link from it each time it (re)opens. Without one
// the session opens the serial port ConnectOptions::port names.
#pragma once

#include <QtGlobal>

#include <memory>

class QObject;

namespace hatpic {

class ByteLink;

class LinkSource
{
public:
    virtual ~LinkSource();

    //! A new link, not yet open, asking for `baud` [bit/s] (a link without a rate ignores it),
    //! owned by `parent`. Called on the session's thread.
    virtual ByteLink *makeLink(qint32 baud, QObject *parent) = 0;
    //! True when the device behind it is a simulator, not hardware: the session says so in its
    //! device facts (DeviceInfo::simulated) and in its words.
    virtual bool simulated() const = 0;
};

using LinkSourcePtr = std::shared_ptr<LinkSource>;

} // namespace hatpic
