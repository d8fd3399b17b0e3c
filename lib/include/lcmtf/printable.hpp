#pragma once

#include <string>
#include <string_view>

namespace lcmtf {

/// Text from the network made safe for a terminal: bytes outside printable ASCII become \xNN
/// and a backslash becomes \\, so a hostile name cannot move the cursor or hide itself.
std::string printable(std::string_view text);
/// The same, line by line: the newlines of a report are kept.
std::string printableLines(std::string_view text);
/// A program's message, which may quote a file or the network, made safe for a terminal
/// without changing text that already is: each byte of a control character other than the
/// newline (C0, DEL, and C1 in its two UTF-8 bytes) and of malformed UTF-8 becomes \xNN, while
/// backslashes and well-formed UTF-8 stay, so parts already passed through printable() read the
/// same.
std::string terminalSafe(std::string_view text);
/// `text` as a quoted Graphviz DOT string shown as it is: a newline becomes a line break, and
/// control characters and malformed UTF-8 (Graphviz's renderers fail on it) become '?'.
std::string dotQuoted(std::string_view text);
/// `text` as a YAML scalar that reads back as the same name: single-quoted, or double-quoted
/// with escapes when it holds line breaks, control characters or other characters YAML cannot
/// show (a malformed UTF-8 byte becomes \xNN, the one thing that cannot read back the same).
std::string yamlQuoted(std::string_view text);

}  // namespace lcmtf
