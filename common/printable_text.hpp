#pragma once
// Text quoted from user files in messages, made safe for a terminal and kept on one line.
#include <string>
#include <string_view>

namespace common {

/// `text` with control bytes, DEL and bytes that are not valid UTF-8 escaped as \xNN (tab, newline and
/// carriage return as \t \n \r, backslash kept), so that a message never sends raw binary to the
/// terminal nor spans lines.
std::string printable(std::string_view text);

}  // namespace common
