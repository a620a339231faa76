#include "framecodec.h"

#include "crc16.h"

#include <bit>
#include <cstring>
#include <type_traits>
#include <utility>
#include <variant>

namespace hatpic::v2 {

namespace {

//! Little-endian payload writer straight into the caller's frame buffer, called once per field
//! of a message's fields(); the caller has checked the room (PayloadSize).
class Writer
{
public:
    explicit Writer(std::uint8_t *at) : m_at(at) {}
    bool m_optionalsOpen = true; //!< no optional field absent so far

    template<typename F> void operator()(const F &field)
    {
        if constexpr (kIsOptionalField<F>) {
            // Sent only when every optional before it was: a receiver reads them in order.
            m_optionalsOpen = m_optionalsOpen && field.has_value();
            if (m_optionalsOpen)
                (*this)(*field);
        } else if constexpr (kIsRestField<F>) {
            text(field.text.view(), 0);
        } else if constexpr (kIsTextField<F>) {
            text(field.view(), F::capacity());
        } else if constexpr (std::is_same_v<F, Reserved>) {
            put(std::uint8_t(0));
        } else if constexpr (FieldStruct<F>) {
            F::fields(field, *this);
        } else if constexpr (FieldBlock<F>) {
            // Doubles travel as binary32: rounded to the nearest float, out-of-range values
            // become ±Inf and NaN stays NaN (the receiver's validation rejects both).
            for (int i = 0; i < F::kFieldCount; ++i)
                (*this)(static_cast<float>(field.field(i)));
        } else if constexpr (std::is_enum_v<F>) {
            put(static_cast<std::underlying_type_t<F>>(field));
        } else if constexpr (std::is_same_v<F, float>) {
            put(std::bit_cast<std::uint32_t>(field));
        } else {
            put(field);
        }
    }

private:
    void text(std::string_view t, std::size_t padTo)
    {
        std::memcpy(m_at, t.data(), t.size());
        m_at += t.size();
        if (t.size() < padTo) {
            std::memset(m_at, 0, padTo - t.size());
            m_at += padTo - t.size();
        }
    }
    template<typename U> void put(U v)
    {
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(m_at, &v, sizeof v);
            m_at += sizeof v;
        } else {
            for (std::size_t i = 0; i < sizeof v; ++i)
                *m_at++ = static_cast<std::uint8_t>(v >> (8 * i));
        }
    }

    std::uint8_t *m_at;
};

//! Little-endian payload reader, called once per field of a message's fields(); the caller has
//! checked the length against payloadBounds().
class Reader
{
public:
    explicit Reader(std::span<const std::uint8_t> bytes) : m_bytes(bytes) {}

    template<typename Field> void operator()(Field &&field)
    {
        using F = std::remove_cvref_t<Field>;
        if constexpr (kIsOptionalField<F>) {
            // A field newer senders append: read when its bytes are there; anything after it
            // is for newer receivers.
            using T = typename F::value_type;
            if (m_bytes.size() - m_pos >= fixedFieldBytes<T>()) {
                T value{};
                (*this)(value);
                field = value;
            }
        } else if constexpr (kIsRestField<F>) {
            field.text.assign(text(m_bytes.size() - m_pos));
        } else if constexpr (kIsTextField<F>) {
            const std::string_view t = text(F::capacity());
            field.assign(t.substr(0, t.find('\0')));
        } else if constexpr (std::is_same_v<F, Reserved>) {
            ++m_pos;
        } else if constexpr (FieldStruct<F>) {
            F::fields(field, *this);
        } else if constexpr (FieldBlock<F>) {
            for (int i = 0; i < F::kFieldCount; ++i) {
                float value = 0;
                (*this)(value);
                field.setField(i, static_cast<double>(value));
            }
        } else if constexpr (std::is_enum_v<F>) {
            field = static_cast<F>(get<std::underlying_type_t<F>>());
        } else if constexpr (std::is_same_v<F, float>) {
            field = std::bit_cast<float>(get<std::uint32_t>());
        } else {
            field = get<F>();
        }
    }

private:
    std::string_view text(std::size_t n)
    {
        const std::string_view t{reinterpret_cast<const char *>(m_bytes.data() + m_pos), n};
        m_pos += n;
        return t;
    }
    template<typename U> U get()
    {
        U v = 0;
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(&v, m_bytes.data() + m_pos, sizeof v);
        } else {
            for (std::size_t i = 0; i < sizeof v; ++i)
                v = static_cast<U>(v | (U(m_bytes[m_pos + i]) << (8 * i)));
        }
        m_pos += sizeof v;
        return v;
    }

    std::span<const std::uint8_t> m_bytes;
    std::size_t m_pos = 0;
};

//! Payload length of one message on the wire, summed over its fields(); not encodable when a
//! Rest text is empty (a LOG carries 1…240 bytes).
struct PayloadSize
{
    std::size_t bytes = 0;
    bool encodable = true;
    bool optionalsOpen = true;

    template<typename F> void operator()(const F &field)
    {
        if constexpr (kIsOptionalField<F>) {
            optionalsOpen = optionalsOpen && field.has_value(); // as Writer
            if (optionalsOpen)
                bytes += fixedFieldBytes<typename F::value_type>();
        } else if constexpr (kIsRestField<F>) {
            encodable = encodable && !field.text.empty();
            bytes += field.text.size();
        } else {
            bytes += fixedFieldBytes<F>();
        }
    }
};

//! Calls `T::fields(m, visit)`; a message without fields() has no payload.
template<typename T, typename Visit> void visitFields(T &m, Visit &visit)
{
    if constexpr (!std::is_empty_v<std::remove_const_t<T>>)
        std::remove_const_t<T>::fields(m, visit);
}

//! Calls `onType(std::type_identity<T>{})` when T is the message whose wire type is `type` and
//! whose sender `direction` names (0x80 set: from the device).
template<typename T, typename OnType>
bool callIfType(std::uint8_t type, Direction direction, OnType &onType)
{
    if constexpr (WireMessage<T>) {
        static_assert(payloadBounds<T>().valid && payloadBounds<T>().max <= kMaxPayload,
                      "an optional or Rest field must come last");
        constexpr auto code = static_cast<std::uint8_t>(T::kType);
        constexpr Direction sender = code & 0x80 ? Direction::FromDevice : Direction::FromHost;
        if (type == code && direction == sender) {
            onType(std::type_identity<T>{});
            return true;
        }
    }
    return false;
}

template<typename OnType, std::size_t... I>
bool withMessageType(std::uint8_t type, Direction direction, OnType &onType,
                     std::index_sequence<I...>)
{
    return (callIfType<std::variant_alternative_t<I, Message>>(type, direction, onType) || ...);
}

//! Calls `onType(std::type_identity<T>{})` for the message T in Message that `type` names from
//! `direction`'s sender; false when there is none.
template<typename OnType>
bool withMessageType(std::uint8_t type, Direction direction, OnType &&onType)
{
    return withMessageType(type, direction, onType,
                           std::make_index_sequence<std::variant_size_v<Message>>{});
}

//! Completes a frame whose packet body (`type | seq | payload`, `body` bytes) sits at out[1…]:
//! appends the CRC, stuffs the packet in place (it fits one COBS block) and the delimiter.
std::size_t finishFrame(std::span<std::uint8_t> out, std::size_t body)
{
    static_assert(kPacketOverhead + kMaxPayload <= kCobsBlockBytes);
    const std::uint16_t crc = crc16(out.subspan(1, body));
    out[1 + body] = static_cast<std::uint8_t>(crc);
    out[2 + body] = static_cast<std::uint8_t>(crc >> 8);
    const std::size_t n = cobsEncodeInPlace(out.first(body + 3));
    out[n] = 0;
    return n + 1;
}

template<typename T>
std::size_t encodeMessage(std::uint8_t seq, const T &m, std::span<std::uint8_t> out)
{
    if constexpr (!WireMessage<T>) {
        return 0; // Refused: what a receiver made of a frame, not a message to send
    } else {
        PayloadSize size;
        visitFields(m, size);
        if (!size.encodable)
            return 0;
        const std::size_t body = 2 + size.bytes;
        if (out.size() < body + 4) // code byte, body, CRC, delimiter
            return 0;
        out[1] = static_cast<std::uint8_t>(T::kType);
        out[2] = seq;
        Writer w(out.data() + 3);
        visitFields(m, w);
        return finishFrame(out, body);
    }
}

} // namespace

std::size_t encodePacket(std::uint8_t type, std::uint8_t seq, std::span<const std::uint8_t> payload,
                         std::span<std::uint8_t> out)
{
    if (payload.size() > kMaxRawPayload)
        return 0;
    const std::size_t body = 2 + payload.size();
    const std::size_t length = body + 2;
    if (out.size() < cobsMaxEncodedSize(length) + 1)
        return 0;
    if (length <= kCobsBlockBytes) {
        out[1] = type;
        out[2] = seq;
        std::copy(payload.begin(), payload.end(), out.begin() + 3);
        return finishFrame(out, body);
    }
    // Longer than any valid frame (tests build them): more than one COBS block.
    std::array<std::uint8_t, kPacketOverhead + kMaxRawPayload> packet;
    packet[0] = type;
    packet[1] = seq;
    std::copy(payload.begin(), payload.end(), packet.begin() + 2);
    const std::uint16_t crc = crc16({packet.data(), body});
    packet[body] = static_cast<std::uint8_t>(crc);
    packet[body + 1] = static_cast<std::uint8_t>(crc >> 8);
    const std::size_t n = cobsEncode({packet.data(), length}, out);
    out[n] = 0;
    return n + 1;
}

std::size_t encodeFrame(std::uint8_t seq, const Message &message, std::span<std::uint8_t> out)
{
    return std::visit([&](const auto &m) { return encodeMessage(seq, m, out); }, message);
}

std::string_view dropReasonText(DropReason reason)
{
    switch (reason) {
    case DropReason::Cobs:
        return "COBS error";
    case DropReason::Short:
        return "too short";
    case DropReason::Crc:
        return "CRC mismatch";
    case DropReason::UnknownType:
        return "unknown type";
    case DropReason::BadLength:
        return "bad length";
    case DropReason::Overflow:
        return "overflow";
    }
    return "unknown reason";
}

std::uint64_t DecoderStats::totalDropped() const
{
    std::uint64_t total = 0;
    for (const std::uint64_t n : drops)
        total += n;
    return total;
}

void WireDecoder::append(std::span<const std::uint8_t> part)
{
    if (m_overflowing)
        return;
    if (m_size + part.size() > kMaxFrameBytes) {
        // Too long for any frame: drop what we hold and skip to the next delimiter.
        overflow();
        m_size = 0;
        m_overflowing = true;
        return;
    }
    std::copy(part.begin(), part.end(), m_buffer.begin() + static_cast<std::ptrdiff_t>(m_size));
    m_size += part.size();
}

void WireDecoder::overflow()
{
    ++m_stats.drops[static_cast<std::size_t>(DropReason::Overflow)];
}

bool WireDecoder::decodeBody(std::span<const std::uint8_t> encoded, Frame &out)
{
    const auto drop = [this](DropReason reason) {
        ++m_stats.drops[static_cast<std::size_t>(reason)];
        return false;
    };
    // Into m_buffer: from the caller's bytes, or in place when the body is m_buffer (the
    // decoded packet is never longer than its encoding).
    const std::optional<std::size_t> decoded = cobsDecodeBody(encoded, m_buffer);
    if (!decoded)
        return drop(DropReason::Cobs);
    const std::size_t length = *decoded;
    if (length < kPacketOverhead)
        return drop(DropReason::Short);
    const std::span<const std::uint8_t> body{m_buffer.data(), length - 2};
    const auto received =
        static_cast<std::uint16_t>(m_buffer[length - 2] | (m_buffer[length - 1] << 8));
    if (crc16(body) != received)
        return drop(DropReason::Crc);
    const std::uint8_t type = body[0];
    out.seq = body[1];
    const std::span<const std::uint8_t> payload = body.subspan(2);
    bool lengthOk = false;
    const bool known = withMessageType(type, m_direction, [&]<typename T>(std::type_identity<T>) {
        constexpr PayloadBounds bounds = payloadBounds<T>();
        lengthOk = payload.size() >= bounds.min && payload.size() <= bounds.max;
        if (lengthOk) {
            Reader r(payload);
            visitFields(out.message.emplace<T>(), r);
        }
    });
    if (!known) {
        drop(DropReason::UnknownType);
        out.message = Refused{type, AckStatus::UnknownType};
        return true;
    }
    if (!lengthOk) {
        drop(DropReason::BadLength);
        out.message = Refused{type, AckStatus::BadLength};
        return true;
    }
    ++m_stats.frames;
    return true;
}

} // namespace hatpic::v2
