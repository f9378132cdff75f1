#pragma once
// What the exercise editor edits of a kind (docs/conventions.md, "Adding an exercise type"): the points the
// kind places on the surface, one row each in the editor's table with the item's own numbers as
// columns, and the numbers of the kind's section as a form below it. The editor builds its page
// from this and asks nothing else about the kind; the keys are the file's, so a problem naming a
// key marks its cell or field. Texts are English, translated in kExerciseTextContext.

#include "engine/exercise/Exercise.h"

#include <cstddef>
#include <span>

namespace palpate {

/// A number the editor edits.
struct EditedNumber {
    /// An item's: its key inside the item ("force_min_n"); a section's: the whole key
    /// ("trace.force_min_n").
    const char* key;
    const char* label;  ///< a column header ("Fmin") or a form row ("Band from:")
    const char* tip;
    const char* unit;  ///< "N", "mm", "s" or "" (a factor)
    double lo, hi;     ///< the widget's range (the validator says what is valid)
    int decimals;
    double step;
    double (*get)(const Exercise& exercise, std::size_t item);
    void (*set)(Exercise& exercise, std::size_t item, double value);
};

/// The points a kind places on the surface.
struct PlacedItems {
    /// Item i's problems name "<listKey>[i]" ("press_targets.targets[2].force_min_n"); a single
    /// item's name listKey itself ("find_lump.inclusion.radius_mm").
    const char* listKey;
    /// "Target %1": an item as the editor names it (undo steps, tooltips), numbered from 1.
    const char* itemName;
    /// What a click adds ("While on, each click on the tissue appends a target there...").
    const char* addTip;
    /// Exactly one item (find the lump's inclusion): it is moved by clicking, never added or removed.
    bool single = false;
    /// The order matters (the trainee follows it): the editor offers Move up and down.
    bool ordered = true;
    std::size_t (*count)(const Exercise& exercise);
    const SurfacePoint& (*point)(const Exercise& exercise, std::size_t item);
    void (*setPoint)(Exercise& exercise, std::size_t item, const SurfacePoint& at);
    /// Appends an item at `at` with the last item's numbers (items of one exercise are usually
    /// alike), or the defaults for the first.
    void (*append)(Exercise& exercise, const SurfacePoint& at);
    void (*erase)(Exercise& exercise, std::size_t item);
    void (*swap)(Exercise& exercise, std::size_t a, std::size_t b);
    /// The item's numbers, one column each after its number and vertex.
    std::span<const EditedNumber> numbers;
    /// When the first item is placed, the force window the tissue reaches there with the mouse
    /// (docs/scoring.md, "Reachable targets") goes here (a target's window, the trace's band while
    /// it is the default); null: the kind asks no force.
    void (*takeReachableWindow)(Exercise& exercise, double minN, double maxN);
};

/// What the editor edits of a kind.
struct ExerciseEditing {
    PlacedItems items;
    /// The section's own numbers (the item argument is unused), in form order.
    std::span<const EditedNumber> numbers;
};

}  // namespace palpate
