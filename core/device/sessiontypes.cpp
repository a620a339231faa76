#include "sessiontypes.h"

#include "device/sample.h"

#include <numeric>

namespace hatpic {

QString sessionStateName(SessionState state)
{
    switch (state) {
    case SessionState::Disconnected:
        return QStringLiteral("disconnected");
    case SessionState::Opening:
        return QStringLiteral("opening");
    case SessionState::Detecting:
        return QStringLiteral("detecting");
    case SessionState::Connected:
        return QStringLiteral("connected");
    case SessionState::Lost:
        return QStringLiteral("lost");
    }
    return QStringLiteral("unknown");
}

quint64 LinkStats::totalDecoderDrops() const
{
    return std::accumulate(decoderDrops.begin(), decoderDrops.end(), quint64(0));
}

void registerSessionMetaTypes()
{
    qRegisterMetaType<hatpic::Sample>();
    qRegisterMetaType<hatpic::SampleBatch>();
    qRegisterMetaType<hatpic::HandInput>();
    qRegisterMetaType<hatpic::ConnectOptions>();
    qRegisterMetaType<hatpic::SessionState>();
    qRegisterMetaType<hatpic::DeviceInfo>();
    qRegisterMetaType<hatpic::CommandResult>();
    qRegisterMetaType<hatpic::LinkStats>();
    qRegisterMetaType<hatpic::RecordingStatus>();
    qRegisterMetaType<hatpic::DeviceParams>();
    qRegisterMetaType<hatpic::HostParams>();
}

} // namespace hatpic
