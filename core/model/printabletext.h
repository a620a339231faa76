// The one rule for foreign text on its way to a terminal or a widget. Plain C++ (no Qt), so
// every layer uses the same function: a device's lines and name (session, protocol), a file's
// keys and values (profile), an option's value (echoedText(), params.h).
#pragma once

#include <string>
#include <string_view>

namespace hatpic {

//! UTF-8 `text` with every control character (C0 including ESC, BEL, CR and LF; DEL; C1) shown
//! as a "\x1b"-style escape, so it can never clear a screen, set a window title or fake a
//! line; the rest kept as it is. echoedText() (params.h) quotes through it.
std::string printableText(std::string_view text);

} // namespace hatpic
