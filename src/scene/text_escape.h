#pragma once
// Text that came from the user's files or arguments (names, keys, table lines, titles, paths)
// printed safely: terminal escape sequences, control characters and bytes that are not UTF-8
// never reach the terminal raw. Every place that echoes input text goes through these.
#include <string>
#include <string_view>

namespace cablefilm {

// Printable ASCII and well-formed UTF-8 as they are; a backslash as "\\"; \n, \r, \t as such;
// any other control character (C0, DEL, C1), a byte that is not part of well-formed UTF-8, and
// the Unicode bidirectional controls (which reorder what a terminal shows) as \xHH or \u{HHHH}.
std::string EscapeText(std::string_view text);

// EscapeText in double quotes, a double quote inside as \": "name".
std::string QuoteText(std::string_view text);

}  // namespace cablefilm
