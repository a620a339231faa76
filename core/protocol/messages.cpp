#include "messages.h"

#include <type_traits>

namespace hatpic::v2 {

std::string_view ackStatusWireName(AckStatus status)
{
    switch (status) {
    case AckStatus::Ok:
        return "OK";
    case AckStatus::BadLength:
        return "BAD_LENGTH";
    case AckStatus::OutOfRange:
        return "OUT_OF_RANGE";
    case AckStatus::UnknownType:
        return "UNKNOWN_TYPE";
    case AckStatus::StorageError:
        return "STORAGE_ERROR";
    case AckStatus::Unsupported:
        return "UNSUPPORTED";
    }
    return {};
}

namespace {

template<typename T> constexpr MessageType typeOf()
{
    if constexpr (std::is_same_v<T, Hello>)
        return MessageType::Hello;
    else if constexpr (std::is_same_v<T, GetParams>)
        return MessageType::GetParams;
    else if constexpr (std::is_same_v<T, SetParams>)
        return MessageType::SetParams;
    else if constexpr (std::is_same_v<T, SetStream>)
        return MessageType::SetStream;
    else if constexpr (std::is_same_v<T, SetFeedback>)
        return MessageType::SetFeedback;
    else if constexpr (std::is_same_v<T, SaveParams>)
        return MessageType::SaveParams;
    else if constexpr (std::is_same_v<T, Ping>)
        return MessageType::Ping;
    else if constexpr (std::is_same_v<T, Zero>)
        return MessageType::Zero;
    else if constexpr (std::is_same_v<T, SetEffects>)
        return MessageType::SetEffects;
    else if constexpr (std::is_same_v<T, GetEffects>)
        return MessageType::GetEffects;
    else if constexpr (std::is_same_v<T, Vibrate>)
        return MessageType::Vibrate;
    else if constexpr (std::is_same_v<T, Effects>)
        return MessageType::Effects;
    else if constexpr (std::is_same_v<T, HelloReply>)
        return MessageType::HelloReply;
    else if constexpr (std::is_same_v<T, Params>)
        return MessageType::Params;
    else if constexpr (std::is_same_v<T, Ack>)
        return MessageType::Ack;
    else if constexpr (std::is_same_v<T, Pong>)
        return MessageType::Pong;
    else if constexpr (std::is_same_v<T, Telemetry>)
        return MessageType::Telemetry;
    else {
        static_assert(std::is_same_v<T, Log>, "every message type needs a wire type");
        return MessageType::Log;
    }
}

} // namespace

std::uint8_t messageType(const Message &message)
{
    return std::visit(
        [](const auto &m) -> std::uint8_t {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, Refused>)
                return m.type;
            else
                return static_cast<std::uint8_t>(typeOf<T>());
        },
        message);
}

} // namespace hatpic::v2
