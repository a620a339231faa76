// Finds out which protocol the device on a freshly opened link speaks (protocol.md § 4):
// listen for legacy frames, then send HELLO (with a seq whose frame holds no 'i', so a legacy
// device is never upset) and wait for HELLO_REPLY; or, with the protocol forced, go straight
// to one of the two.
#pragma once

#include "protocol/legacy.h"
#include "protocol/v2codec.h"
#include "session/sessiontypes.h"

#include <QDeadlineTimer>
#include <QObject>
#include <QTimer>

#include <optional>

namespace hatpic {

class ByteLink;
class CommandQueue;
class LinkStatistics;

class ProtocolDetector : public QObject
{
    Q_OBJECT
public:
    static constexpr int kListenMs = 500;         //!< listen for legacy frames [ms]
    static constexpr int kHelloWaitMs = 500;      //!< wait for HELLO_REPLY [ms]
    static constexpr int kHelloSends = 4;         //!< HELLOs sent within the wait
    static constexpr int kLegacyFramesNeeded = 2; //!< legacy frames that decide "legacy"

    //! `queue` carries the HELLO of a forced v2 (with its resends) and the shared seq.
    ProtocolDetector(CommandQueue &queue, LinkStatistics &statistics, QObject *parent = nullptr);

    //! Starts on an open `link`; reports through the signals below.
    void start(ByteLink *link, const ConnectOptions &options);
    //! Stops without a verdict; the decoder's drop counts go to the statistics.
    void stop();
    bool active() const { return m_phase != Phase::Idle; }
    void feed(const QByteArray &bytes);

    //! The v2 decoder's counts (HELLO phase), for LinkStats while detecting.
    const v2::DecoderStats &decoderStats() const { return m_v2.stats(); }
    //! Hands over the v2 decoder (it may hold the start of the next frame).
    v2::FrameDecoder takeDecoder();
    //! The legacy frames it listened to were the IMU branch's (with the tilt).
    bool heardImuBranch() const { return m_legacy.stats().tiltFrames > 0; }

Q_SIGNALS:
    //! What detection is doing, for the Detecting state's detail.
    void progress(const hatpic::StateDetail &detail);
    void foundLegacy();
    //! `rest`: the frames that came after the reply in the same read.
    void foundV2(const hatpic::v2::HelloReply &reply, const QList<hatpic::v2::Frame> &rest);
    void failed(const hatpic::StateDetail &detail);

private:
    enum class Phase { Idle, Listening, Hello };

    void onTimeout();
    void listen();
    void onListenTimeout();
    void sendHello();
    void onHelloTimeout();
    void onHelloUnanswered();
    void fail(const StateDetail &detail);
    StateDetail detail(StateDetail::Why why) const;
    bool detectsAtTwoRates() const;

    CommandQueue &m_queue;
    LinkStatistics &m_statistics;
    ByteLink *m_link = nullptr;
    ConnectOptions m_options;
    Phase m_phase = Phase::Idle;
    QTimer m_timer;
    legacy::Decoder m_legacy;
    int m_legacyFrames = 0;
    std::optional<quint8> m_helloSeq; //!< auto detection's HELLO (forced v2 uses the queue)
    int m_helloSends = 0;
    QDeadlineTimer m_giveUp; //!< when detection stops trying again (detectForMs)
    v2::FrameDecoder m_v2{v2::Direction::FromDevice};
};

//! A detail of `kind` naming the port and its rate (the link's, else the one it opens at).
StateDetail stateDetail(StateDetail::Why why, const ConnectOptions &options, const ByteLink *link);
//! The baud rate a link to `options` opens at.
qint32 requestedBaud(const ConnectOptions &options);

} // namespace hatpic
