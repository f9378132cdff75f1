#pragma once
// A problem with a parameter set, said once and carried as data: the field it belongs to (so a
// panel can mark that field, a file reader can name that key) and the sentence a person reads.
// Validators return Problems; nothing parses the sentence. See docs/conventions.md.

#include <string>
#include <vector>

namespace palpate {

struct Problem {
    /// The field's key as its table names it ("anchorStiffnessNPerMm"); empty for the set as a whole.
    std::string field;
    /// The entry of a list field ("slopeMagnitudeMmPerN" entry 0 is |m1|); -1 for a scalar.
    int index = -1;
    /// A second entry of the same list the problem is about (two slopes out of order); -1 if none.
    int relatedIndex = -1;
    /// "anchorStiffnessNPerMm = -1 N/mm must be a positive finite number"
    std::string message;
};

using Problems = std::vector<Problem>;

/// One problem of `field` (the validators that stop at the first problem they find).
inline Problems oneProblem(std::string field, std::string message) {
    return {Problem{std::move(field), -1, -1, std::move(message)}};
}

/// The messages alone, in order (for a log line or a list shown as it is).
inline std::vector<std::string> messagesOf(const Problems& problems) {
    std::vector<std::string> out;
    out.reserve(problems.size());
    for (const Problem& p : problems) out.push_back(p.message);
    return out;
}

/// All messages joined by "; " (for an exception or a one-line error).
inline std::string joinedMessages(const Problems& problems) {
    std::string out;
    for (const Problem& p : problems) out += (out.empty() ? "" : "; ") + p.message;
    return out;
}

/// Whether any problem belongs to `field` (and entry `index`, when given).
inline bool hasProblem(const Problems& problems, const std::string& field, int index = -1) {
    for (const Problem& p : problems)
        if (p.field == field && (index < 0 || p.index == index || p.relatedIndex == index)) return true;
    return false;
}

}  // namespace palpate
