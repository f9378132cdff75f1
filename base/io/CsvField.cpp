#include "base/io/CsvField.h"

namespace palpate {

std::string csvTextField(std::string_view text) {
    std::string cell;
    const bool formula = !text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos;
    if (formula) cell += '\'';
    cell += text;
    if (!formula && cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
    std::string quoted = "\"";
    for (const char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace palpate
