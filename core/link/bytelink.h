// A byte pipe to a joystick: a serial port or the in-process simulator.
//
// Lives on the session thread. Bytes arrive through bytesReceived() in whatever chunks the
// transport delivers; write() takes one whole frame per call and hands it on in one piece.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

namespace hatpic {

class ByteLink : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    ~ByteLink() override;

    //! Opens the transport; false with errorString() when it cannot.
    virtual bool open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    //! Queues one whole frame for the device (a single write on a serial port).
    virtual void write(const QByteArray &bytes) = 0;
    virtual QString errorString() const = 0;
    //! Effective baud rate of the link [bit/s].
    virtual qint32 baud() const = 0;
    //! Changes the baud rate of an open link; links without a rate (the simulator) ignore it.
    virtual bool setBaud(qint32 baud)
    {
        Q_UNUSED(baud);
        return true;
    }

Q_SIGNALS:
    void bytesReceived(const QByteArray &bytes);
    //! The transport broke or vanished (unplugged, simulator killed); the link is closed.
    void failed(const QString &reason);
};

} // namespace hatpic
