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

std::uint8_t messageType(const Message &message)
{
    return std::visit(
        [](const auto &m) -> std::uint8_t {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, Refused>)
                return m.type;
            else
                return static_cast<std::uint8_t>(T::kType);
        },
        message);
}

} // namespace hatpic::v2
