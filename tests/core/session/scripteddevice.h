// A v2 device played by a test on the master side of a real pseudo-terminal, with scripted
// answers: for sessions and for hatpicctl facing a device that sends nonsense.
#pragma once

#include "protocol/v2codec.h"

#include <QSocketNotifier>

#include <fcntl.h>
#include <functional>
#include <memory>
#include <pty.h>
#include <unistd.h>

namespace hatpic::test {

//! A v2 device played by the test: answers HELLO with `hello`, GET_PARAMS with `params`,
//! SET_STREAM and the rest with ACK OK, PING with PONG; telemetry only when told.
class ScriptedDevice
{
public:
    v2::HelloReply hello;
    DeviceParams params;
    //! Asked first for every frame from the host: true when it answered (or chose silence),
    //! false to leave the frame to the answers above.
    std::function<bool(const v2::Frame &)> answer;

    ScriptedDevice()
    {
        hello.maxStreamHz = 1000;
        hello.deviceId = 0x54455354;
        hello.tauLimit = 0.44f;
        hello.firmware.assign("scripted");
        char name[256] = {};
        int slave = -1;
        if (::openpty(&m_master, &slave, name, nullptr, nullptr) != 0)
            return;
        ::close(slave);
        ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
        // Not inherited by the programs a test starts: hangUp() must really close the device.
        ::fcntl(m_master, F_SETFD, FD_CLOEXEC);
        m_path = QString::fromLocal8Bit(name);
        m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
        QObject::connect(m_notifier.get(), &QSocketNotifier::activated, [this] { onReadable(); });
    }
    ~ScriptedDevice()
    {
        m_notifier.reset();
        if (m_master >= 0)
            ::close(m_master);
    }
    bool isValid() const { return m_master >= 0; }
    QString path() const { return m_path; }
    //! Bytes the device's receiver holds before the host sends anything (line noise).
    void preload(const QByteArray &junk) { m_decoder.feed(junk, m_frames); }
    void send(const v2::Message &message) { write(v2::encodeFrame(m_seq++, message)); }
    //! Bytes as they are (another protocol, line noise).
    void sendRaw(const QByteArray &bytes) { write(bytes); }
    void sendTelemetry(float theta, quint32 tUs)
    {
        v2::Telemetry t;
        t.t_us = tUs;
        t.theta = theta;
        write(v2::encodeFrame(m_telemetrySeq++, t));
    }
    int hellosAnswered() const { return m_hellos; }
    //! Closes the device's side: the host's port reads the end of the file (a vanished device).
    void hangUp() // also from inside answer(): the notifier goes later
    {
        if (m_notifier) {
            m_notifier->setEnabled(false);
            m_notifier.release()->deleteLater();
        }
        if (m_master >= 0)
            ::close(m_master);
        m_master = -1;
    }

private:
    void write(const QByteArray &bytes)
    {
        qsizetype done = 0;
        while (done < bytes.size()) {
            const ssize_t n = ::write(m_master, bytes.constData() + done, bytes.size() - done);
            if (n <= 0)
                return;
            done += n;
        }
    }
    void onReadable()
    {
        if (m_master < 0)
            return;
        char buf[4096];
        const ssize_t n = ::read(m_master, buf, sizeof buf);
        if (n <= 0)
            return;
        m_frames.clear();
        m_decoder.feed(QByteArrayView(buf, n), m_frames);
        for (const v2::Frame &f : std::as_const(m_frames)) {
            if (answer && answer(f))
                continue;
            if (std::holds_alternative<v2::Hello>(f.message)) {
                ++m_hellos;
                send(hello);
            } else if (std::holds_alternative<v2::GetParams>(f.message)) {
                send(v2::Params{params});
            } else if (const auto *ping = std::get_if<v2::Ping>(&f.message)) {
                send(v2::Pong{ping->token});
            } else if (!std::holds_alternative<v2::SetFeedback>(f.message)) {
                send(v2::Ack{f.seq, v2::AckStatus::Ok, v2::kNoField});
            }
        }
    }

    int m_master = -1;
    QString m_path;
    std::unique_ptr<QSocketNotifier> m_notifier;
    v2::FrameDecoder m_decoder{v2::Direction::FromHost};
    QList<v2::Frame> m_frames;
    quint8 m_seq = 0;
    quint8 m_telemetrySeq = 0;
    int m_hellos = 0;
};

} // namespace hatpic::test
