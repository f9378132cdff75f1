#pragma once
// One text cell of a CSV file the product writes (docs/results-store.md, "What is protected"):
// quoted when it holds a comma, a quote or a line break, and neutralised when a spreadsheet would
// take it for a formula (OWASP's CSV injection rule: a cell beginning with =, +, -, @, a tab or a
// carriage return gets a leading apostrophe), so that a trainee's or exercise's name such as
// =HYPERLINK(...) opens as the text it is. For text cells only: numbers are written as numbers.

#include <string>
#include <string_view>

namespace palpate {

std::string csvTextField(std::string_view text);

}  // namespace palpate
