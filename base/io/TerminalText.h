#pragma once
// Text from a file or a database shown on a terminal (docs/results-store.md, "What is protected"):
// a name is data, never a command to the terminal. Control characters (C0, DEL and the C1 range,
// which start escape sequences that set the title, clear the screen or rewrite lines) are shown as
// \xNN (C1: \u00NN); everything else, UTF-8 included, passes as it is. JSON output needs none of
// this: its encoder escapes control characters already.

#include <string>
#include <string_view>

namespace palpate {

std::string terminalSafe(std::string_view text);

}  // namespace palpate
