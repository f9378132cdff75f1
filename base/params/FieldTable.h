#pragma once
// One table per parameter struct: every field's key, file key, unit, valid range, panel text and
// how to reach it in the struct, said once. The validator, the file reader and writer, the
// Parameters panel and the undo check all read the table, so a new parameter is one row beside
// its struct (and its member). The default is the member's initialiser: the table reads it from
// a default-constructed struct instead of repeating it. See docs/conventions.md.

#include "base/params/Problem.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>

namespace palpate {

inline constexpr double kNoLimit = std::numeric_limits<double>::infinity();

enum class FieldType {
    Real,      ///< a double
    Whole,     ///< an int
    Choice,    ///< an enum, 0..n-1, written by name
    RealList,  ///< an array of doubles of which the first used(s) entries count
};

/// Whether an end of a field's range is a valid value itself.
enum class Bound { Closed, Open };

/// Everything said about one field but how to reach it (the builders below add that).
struct FieldSpec {
    const char* key;        ///< the member's name: what Problems name ("anchorStiffnessNPerMm")
    const char* jsonKey;    ///< the key in preset and exercise files ("anchor_stiffness_n_per_mm")
    const char* unit = "";  ///< shown after a value ("N/mm"); "" when it has none
    double lo = 0.0;        ///< valid values lie between lo and hi ...
    double hi = kNoLimit;
    Bound lower = Bound::Closed;  ///< ... with or without the ends
    Bound upper = Bound::Closed;
    const char* label = "";  ///< the panel's row label, English (the panel translates it)
    const char* name = "";   ///< the field in a sentence ("damping ratio"); "": the label without its colon
    const char* tip = "";    ///< the panel's tooltip, English
    int decimals = 0;        ///< the panel's decimals (Real, RealList): what a value keeps
    /// The significant digits the panel shows (never more than `decimals`): a calibrated 14.072222222
    /// mm/N reads 14.07 while it keeps its decimals; 0 shows every decimal.
    int shownDigits = 4;
    double step = 1.0;       ///< the panel's single step
    bool required = false;   ///< a file's section must hold this key
    std::span<const char* const> choices = {};       ///< Choice: each value's name in files
    std::span<const char* const> choiceLabels = {};  ///< Choice: each value's text in the panel
    const char* choiceNoun = "value";                ///< Choice: "unknown <noun> 'x'"
    const char* sizeKey = "";  ///< RealList: the jsonKey of the field that sets how many entries count
    /// RealList: how messages name entry i ("|m1|"); null: "<key>[i]".
    std::string (*itemName)(int index) = nullptr;
    /// The panel's typing range when it is not the valid range widened a decade (so that a wrong
    /// value is shown with its reason instead of being clamped away); NaN: that default.
    double entryLo = std::numeric_limits<double>::quiet_NaN();
    double entryHi = std::numeric_limits<double>::quiet_NaN();
    /// The model name (ModelRegistry) this field matters for alone; "": every model of its section.
    const char* onlyFor = "";
};

/// Marks a field text for Qt's lupdate (run with -tr-function-alias
/// QT_TRANSLATE_NOOP+=PALPATE_TRANSLATE_NOOP) without making the engine depend on Qt. Every field
/// table's texts are in the context kFieldTextContext (lupdate needs the literal at each use).
#define PALPATE_TRANSLATE_NOOP(context, text) text
/// The same for a text with a plural (%n), which lupdate reads as QT_TRANSLATE_N_NOOP.
#define PALPATE_TRANSLATE_N_NOOP(context, text) text

/// The translation context of the field tables' labels, names, tips and choices: the engine's own,
/// not a widget's. A panel translates them with QCoreApplication::translate(kFieldTextContext, ...).
inline constexpr const char* kFieldTextContext = "palpate::Parameters";

/// The typing range of a field in a panel: entryLo/entryHi, or the valid range reaching down to 0
/// and up ten times its top (1e6 for an open top).
inline double entryLowOf(const FieldSpec& s) { return std::isnan(s.entryLo) ? std::min(s.lo, 0.0) : s.entryLo; }
inline double entryHighOf(const FieldSpec& s) {
    if (!std::isnan(s.entryHi)) return s.entryHi;
    return s.hi == kNoLimit ? 1e6 : s.hi > 0.0 ? 10.0 * s.hi : s.hi;
}

template <class S>
struct FieldDef {
    FieldSpec spec;
    FieldType type;
    double (*get)(const S& s, int index);        ///< index: the RealList entry; ignored otherwise
    void (*set)(S& s, int index, double value);  ///< the caller keeps an int field's value in int range
    int (*used)(const S& s) = nullptr;           ///< RealList: entries in use
    int capacity = 1;                            ///< RealList: entries stored

    const char* key() const { return spec.key; }
    /// The value a default-constructed struct holds: the member's initialiser.
    double defaultValue(int index = 0) const { return get(S{}, index); }
    /// How many entries of `s` count: 1 for a scalar.
    int usedCount(const S& s) const { return used ? used(s) : 1; }
    /// "vertexMassKg", or "|m2|" / "coefficients[1]" for a list entry.
    std::string nameOf(int index) const {
        if (type != FieldType::RealList) return spec.key;
        return spec.itemName ? spec.itemName(index) : std::string(spec.key) + "[" + std::to_string(index) + "]";
    }
};

template <class S>
using FieldTable = std::span<const FieldDef<S>>;

namespace fielddetail {
template <class M>
struct MemberOf;
template <class S, class T>
struct MemberOf<T S::*> {
    using Owner = S;
    using Type = T;
};
template <auto Member>
using OwnerOf = typename MemberOf<decltype(Member)>::Owner;
template <auto Member>
using TypeOf = typename MemberOf<decltype(Member)>::Type;
}  // namespace fielddetail

/// A scalar member: double (Real), int (Whole) or an enum (Choice, spec.choices names its values).
template <auto Member>
constexpr FieldDef<fielddetail::OwnerOf<Member>> field(const FieldSpec& spec) {
    using S = fielddetail::OwnerOf<Member>;
    using T = fielddetail::TypeOf<Member>;
    constexpr FieldType type = std::is_enum_v<T>           ? FieldType::Choice
                               : std::is_same_v<T, double> ? FieldType::Real
                                                           : FieldType::Whole;
    static_assert(std::is_enum_v<T> || std::is_same_v<T, double> || std::is_same_v<T, int>,
                  "a field is a double, an int or an enum");
    FieldSpec s = spec;
    if constexpr (std::is_enum_v<T>) {
        s.lo = 0.0;
        s.hi = double(spec.choices.size()) - 1.0;
    }
    return FieldDef<S>{s, type, [](const S& v, int) { return double(v.*Member); },
                       [](S& v, int, double x) {
                           if constexpr (std::is_enum_v<T>) v.*Member = T(int(x));
                           else v.*Member = static_cast<T>(x);
                       }};
}

/// An array member of doubles whose first `Used(s)` entries count.
template <auto Member, auto Used>
constexpr FieldDef<fielddetail::OwnerOf<Member>> listField(const FieldSpec& spec) {
    using S = fielddetail::OwnerOf<Member>;
    using A = fielddetail::TypeOf<Member>;
    return FieldDef<S>{spec,
                       FieldType::RealList,
                       [](const S& v, int i) {
                           constexpr int capacity = int(std::tuple_size_v<A>);
                           return i >= 0 && i < capacity ? (v.*Member)[std::size_t(i)] : 0.0;
                       },
                       [](S& v, int i, double x) {
                           constexpr int capacity = int(std::tuple_size_v<A>);
                           if (i >= 0 && i < capacity) (v.*Member)[std::size_t(i)] = x;
                       },
                       [](const S& v) {
                           constexpr int capacity = int(std::tuple_size_v<A>);
                           const int n = int(Used(v));
                           return n < 0 ? 0 : n > capacity ? capacity : n;
                       },
                       int(std::tuple_size_v<A>)};
}

/// A field whose setter does more than store (e.g. a degree that resets its coefficients).
template <class S>
constexpr FieldDef<S> customField(const FieldSpec& spec, FieldType type, double (*get)(const S&, int),
                                  void (*set)(S&, int, double)) {
    return FieldDef<S>{spec, type, get, set};
}

/// The number as messages print it ("0.001", "1e+06").
inline std::string formatNumber(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

/// "must be a positive finite number", "must be 0 or more", "is out of range 1..20" or
/// "is out of range (0, 1]": the rule of `spec`'s range in words.
inline std::string rangeRule(const FieldSpec& spec) {
    const bool loOpen = spec.lower == Bound::Open, hiOpen = spec.upper == Bound::Open;
    if (spec.lo == 0.0 && spec.hi == kNoLimit) return loOpen ? "must be a positive finite number" : "must be 0 or more";
    if (!loOpen && !hiOpen) return "is out of range " + formatNumber(spec.lo) + ".." + formatNumber(spec.hi);
    return std::string("is out of range ") + (loOpen ? "(" : "[") + formatNumber(spec.lo) + ", " +
           formatNumber(spec.hi) + (hiOpen ? ")" : "]");
}

/// Whether `v` lies in `spec`'s range (finite, and whole for a Whole or Choice field).
template <class S>
bool inRange(const FieldDef<S>& f, double v) {
    const FieldSpec& s = f.spec;
    if (!std::isfinite(v)) return false;
    if ((f.type == FieldType::Whole || f.type == FieldType::Choice) && std::floor(v) != v) return false;
    const bool aboveLo = s.lower == Bound::Open ? v > s.lo : v >= s.lo;
    const bool belowHi = s.upper == Bound::Open ? v < s.hi : v <= s.hi;
    return aboveLo && belowHi;
}

/// "<name> = <v> <unit> <rule>" for every value outside its field's range, in table order.
template <class S>
void checkFields(FieldTable<S> table, const S& s, Problems& out) {
    for (const FieldDef<S>& f : table) {
        const bool list = f.type == FieldType::RealList;
        for (int i = 0; i < f.usedCount(s); ++i) {
            const double v = f.get(s, i);
            if (inRange(f, v)) continue;
            const std::string unit = *f.spec.unit ? std::string(" ") + f.spec.unit : std::string();
            out.push_back({f.spec.key, list ? i : -1, -1,
                           f.nameOf(i) + " = " + formatNumber(v) + unit + " " + rangeRule(f.spec)});
        }
    }
}

/// The row of `key`, or null.
template <class S>
const FieldDef<S>* findField(FieldTable<S> table, const std::string& key) {
    for (const FieldDef<S>& f : table)
        if (key == f.spec.key) return &f;
    return nullptr;
}

/// Whether every field, every stored entry of a list included, holds the same value (exact).
template <class S>
bool sameFields(FieldTable<S> table, const S& a, const S& b) {
    for (const FieldDef<S>& f : table)
        for (int i = 0; i < f.capacity; ++i)
            if (!(f.get(a, i) == f.get(b, i))) return false;
    return true;
}

}  // namespace palpate
