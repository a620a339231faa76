// Helpers of tst_firmwarehost: the programs as child processes and a v2 client on a real pty.
#pragma once

#include "protocol/v2codec.h"
#include "ptyprogram.h"

#include <QProcess>
#include <QSerialPort>

#include <cmath>
#include <numbers>

namespace hatpic::test {

//! A protocol v2 host on the fw-host's pty: a QSerialPort and a frame decoder.
class V2Client
{
public:
    explicit V2Client(const QString &path)
    {
        m_port.setPortName(path);
        m_port.setBaudRate(921600);
        QObject::connect(&m_port, &QSerialPort::readyRead, &m_port,
                         [this] { m_decoder.feed(m_port.readAll(), frames); });
    }
    bool open() { return m_port.open(QIODevice::ReadWrite); }
    QString errorString() const { return m_port.errorString(); }
    //! Sends a command with a fresh seq; returns that seq.
    quint8 send(const v2::Message &message)
    {
        const quint8 seq = m_seq++;
        m_port.write(v2::encodeFrame(seq, message));
        return seq;
    }
    //! The ACK of command `seq`, if it came.
    std::optional<v2::Ack> ack(quint8 seq) const
    {
        for (const v2::Frame &f : frames) {
            if (const auto *a = std::get_if<v2::Ack>(&f.message); a && a->ackedSeq == seq)
                return *a;
        }
        return std::nullopt;
    }
    template<typename T> QList<T> all() const
    {
        QList<T> out;
        for (const v2::Frame &f : frames) {
            if (const auto *m = std::get_if<T>(&f.message))
                out.append(*m);
        }
        return out;
    }

    QList<v2::Frame> frames;

private:
    QSerialPort m_port;
    v2::FrameDecoder m_decoder{v2::Direction::FromDevice};
    quint8 m_seq = 1; // seq 0 would be a HELLO's
};

constexpr double kTick = 2.0 * std::numbers::pi / 4096; //!< one servo tick [rad]

} // namespace hatpic::test
