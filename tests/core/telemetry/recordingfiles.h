// What the recording file tests share (tst_recordingwriter, tst_recordingreader): the metadata
// and samples they write and the header of an older recording (a file read whole: testfiles.h).
#pragma once

#include "telemetry/recordingwriter.h"
#include "testfiles.h"

#include <QByteArray>
#include <QDateTime>
#include <QFile>
#include <QString>

namespace hatpic::test {

inline RecordingMetadata metadata()
{
    RecordingMetadata m;
    m.start = QDateTime(QDate(2024, 5, 17), QTime(9, 30, 15, 250), Qt::UTC);
    m.device.protocol = WireProtocol::V2;
    m.device.port = QStringLiteral("/dev/ttyUSB0");
    m.device.baud = 921600;
    m.device.protocolVersion = 2;
    m.device.maxStreamHz = 1000;
    m.device.deviceId = 0x53494D31;
    m.device.tauLimit = 0.44;
    m.device.firmware = QStringLiteral("fw \"1.0\"");
    m.params.K_max = 0.6;
    m.host.v_max = 2;
    m.host.mode = ReferenceMode::Rotation;
    m.source = QStringLiteral("tst_recorder");
    return m;
}

inline Sample sample(double t)
{
    Sample s;
    s.t_s = t;
    s.theta = double(0.05f);
    s.omega = 0.5;
    s.tau = double(-0.01f);
    s.tau_rec = double(-0.02f);
    s.tau_ext = 0;
    s.tau_total = double(-0.02f);
    s.v_ref = 0.025;
    s.p_ref = 1.0 / 3.0;
    s.flags = 0x0102;
    return s;
}

//! The header of a recording made before tau_fx, tau_pc and pc_reserve existed: the hand-written
//! files of these tests use it, so they also check that such recordings still read (without a
//! word about those).
inline const QByteArray kHeader =
    "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,event\n";

} // namespace hatpic::test
