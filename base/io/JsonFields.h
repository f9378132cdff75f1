#pragma once
// A parameter struct's section of a JSON file, read and written through its field table
// (base/params/FieldTable.h): the keys a section may hold, their types, whole numbers, choice
// names and list lengths come from the table; ranges from the struct's validator, reported at the
// key of the field each problem names. Include from .cpp files only (it brings nlohmann/json).

#include "base/io/JsonReader.h"
#include "base/params/FieldTable.h"

#include <string>
#include <vector>

namespace palpate {

/// The file keys of a table, in its order.
template <class S>
std::vector<std::string> jsonKeysOf(FieldTable<S> table) {
    std::vector<std::string> keys;
    for (const FieldDef<S>& f : table) keys.emplace_back(f.spec.jsonKey);
    return keys;
}

/// "section.json_key" (with "[i]" for a list entry) of the field a problem names; "section" when
/// the problem is the set's as a whole.
template <class S>
std::string jsonPathOf(FieldTable<S> table, const std::string& section, const Problem& problem) {
    const FieldDef<S>* f = findField(table, problem.field);
    if (!f) return section;
    std::string path = JsonReader::join(section, f->spec.jsonKey);
    if (problem.index >= 0) path += "[" + std::to_string(problem.index) + "]";
    return path;
}

/// Reads the keys of `section` that the table names into `s` (absent keys keep s's values), in
/// table order, so a list's length is checked against a count read before it. Type errors are
/// recorded by key; ranges are the validator's (reportProblems).
template <class S>
void readFields(JsonReader& r, const Json& object, const std::string& section, FieldTable<S> table, S& s) {
    if (!r.object(object, section, jsonKeysOf(table))) return;
    for (const FieldDef<S>& f : table) {
        const char* key = f.spec.jsonKey;
        const std::string path = JsonReader::join(section, key);
        if (!object.contains(key)) {
            if (f.spec.required) r.error(path, "missing");
            continue;
        }
        const Json& v = object.at(key);
        switch (f.type) {
            case FieldType::Real:
                if (!v.is_number()) r.error(path, "must be a number");
                else f.set(s, -1, v.get<double>());
                break;
            case FieldType::Whole: {
                // Checked against the range here, not by the validator: a count sizes what follows
                // (a list's length), which must not be judged by a count out of range.
                if (!v.is_number()) {
                    r.error(path, "must be a number");
                } else if (const double x = v.get<double>(); std::floor(x) != x) {
                    r.error(path, "must be a whole number");
                } else if (!inRange(f, x)) {
                    r.error(path, formatNumber(x) + " " + rangeRule(f.spec));
                } else {
                    f.set(s, -1, x);
                }
                break;
            }
            case FieldType::Choice: {
                std::string name;
                if (!r.text(object, section, key, name)) break;
                int index = -1;
                for (std::size_t i = 0; i < f.spec.choices.size(); ++i)
                    if (name == f.spec.choices[i]) index = int(i);
                if (index >= 0) {
                    f.set(s, -1, index);
                    break;
                }
                std::string names;
                for (std::size_t i = 0; i < f.spec.choices.size(); ++i)
                    names += std::string(i == 0                           ? ""
                                         : i + 1 == f.spec.choices.size() ? " or "
                                                                          : ", ") +
                             f.spec.choices[i];
                r.error(path, "unknown " + std::string(f.spec.choiceNoun) + " '" + name + "' (use " + names + ")");
                break;
            }
            case FieldType::RealList: {
                if (!v.is_array()) {
                    r.error(path, "must be an array of numbers");
                    break;
                }
                const std::size_t used = std::size_t(f.usedCount(s));
                if (v.size() != used) {
                    std::string why = std::to_string(used);
                    for (const FieldDef<S>& g : table)
                        if (std::string(f.spec.sizeKey) == g.spec.jsonKey)
                            why = std::string(g.spec.jsonKey) + " " + formatNumber(g.get(s, -1)) + " needs " + why;
                    r.error(path, "has " + std::to_string(v.size()) + " values; " + why);
                }
                for (std::size_t i = 0; i < v.size() && i < std::size_t(f.capacity); ++i) {
                    if (!v[i].is_number()) r.error(path + "[" + std::to_string(i) + "]", "must be a number");
                    else f.set(s, int(i), v[i].get<double>());
                }
                break;
            }
        }
    }
}

/// Each problem of a validator at the key of the field it names.
template <class S>
void reportProblems(JsonReader& r, FieldTable<S> table, const std::string& section, const Problems& problems) {
    for (const Problem& p : problems) r.error(jsonPathOf(table, section, p), p.message);
}

/// The section as JSON, in table order: numbers, whole numbers as integers, choices by name, lists
/// with their used entries.
template <class S>
Json fieldsToJson(FieldTable<S> table, const S& s) {
    Json j = Json::object();
    for (const FieldDef<S>& f : table) {
        switch (f.type) {
            case FieldType::Real: j[f.spec.jsonKey] = f.get(s, -1); break;
            case FieldType::Whole: j[f.spec.jsonKey] = int(f.get(s, -1)); break;
            case FieldType::Choice: {
                const int i = int(f.get(s, -1));
                j[f.spec.jsonKey] = i >= 0 && std::size_t(i) < f.spec.choices.size() ? f.spec.choices[std::size_t(i)]
                                                                                     : "?";
                break;
            }
            case FieldType::RealList: {
                Json a = Json::array();
                for (int i = 0; i < f.usedCount(s); ++i) a.push_back(f.get(s, i));
                j[f.spec.jsonKey] = a;
                break;
            }
        }
    }
    return j;
}

}  // namespace palpate
