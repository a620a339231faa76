#include "printabletext.h"

namespace hatpic {

std::string printableText(std::string_view text)
{
    static constexpr char kHex[] = "0123456789abcdef";
    const auto escape = [](std::string &out, unsigned char code) {
        out += "\\x";
        out += kHex[code >> 4];
        out += kHex[code & 0xF];
    };
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c == 0x7F) {
            escape(out, c);
        } else if (c == 0xC2 && i + 1 < text.size() &&
                   static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                   static_cast<unsigned char>(text[i + 1]) < 0xA0) {
            escape(out, static_cast<unsigned char>(text[++i])); // C1: U+0080 … U+009F
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

} // namespace hatpic
