#pragma once
// What a window shows of an exercise, decided by its kind (ExerciseKind::draw, ::guidance) and
// shown by the widgets: the markers drawn over the tissue, and what the trainee is told while the
// session runs. Qt-free: texts are English templates with arguments, which the window translates
// (context kExerciseTextContext) and fills in its own number format and force unit.

#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <vector>

namespace palpate {

/// An English text with %1, %2, ... (and %n for `count`), marked for translation where it is
/// written (PALPATE_TRANSLATE_NOOP("palpate::Exercises", ...)).
struct ViewText {
    enum class ArgKind {
        Whole,       ///< `a` as a whole number
        Fixed,       ///< `a` with `decimals` decimals
        ForceRange,  ///< the force window [a, b], N, in the window's force unit
    };
    struct Arg {
        ArgKind kind = ArgKind::Whole;
        double a = 0.0, b = 0.0;
        int decimals = 0;
    };
    ViewText() = default;
    ViewText(const char* sourceText, int pluralCount = -1) : text(sourceText), count(pluralCount) {}

    const char* text = "";
    int count = -1;  ///< >= 0: the plural's %n
    std::vector<Arg> args;

    bool empty() const { return *text == '\0'; }
    ViewText& whole(double v) {
        args.push_back({ArgKind::Whole, v, 0.0, 0});
        return *this;
    }
    ViewText& fixed(double v, int decimals) {
        args.push_back({ArgKind::Fixed, v, 0.0, decimals});
        return *this;
    }
    ViewText& forceRange(double minN, double maxN) {
        args.push_back({ArgKind::ForceRange, minN, maxN, 0});
        return *this;
    }
};

/// What kind of thing a marker over the tissue is (each has its colour).
enum class SurfaceMarkerKind { Target, CurrentTarget, DoneTarget, PathPoint, Inclusion, Mark };

struct SurfaceMarker {
    SurfaceMarkerKind kind = SurfaceMarkerKind::Target;
    glm::vec3 positionMm{0.0f};
    glm::vec3 normal{0.0f};  ///< outward rest normal (zero: unknown)
    ViewText label;          ///< drawn beside it; may be empty
    double radiusMm = 0.0;   ///< > 0: a circle of this radius on the surface (tolerance, inclusion)
    bool selected = false;   ///< the one the instructor is editing
    /// > 0: a sphere of this radius inside the tissue (a lump), centred at bodyCentreMm, drawn
    /// through the surface (the instructor's see-through view).
    double bodyRadiusMm = 0.0;
    glm::vec3 bodyCentreMm{0.0f};
};

/// Who looks at the exercise: the instructor sees everything, the trainee not what is hidden.
enum class MarkerAudience { Instructor, Trainee };

/// The markers of an exercise, and the trace's polyline (empty: none).
struct ExerciseDrawing {
    std::vector<SurfaceMarker> markers;
    std::vector<glm::vec3> pathMm;
};

/// What the trainee is told while the session runs.
struct GuidanceView {
    double windowMinN = 0.0, windowMaxN = 0.0;  ///< the force gauge's window (equal: none)
    /// The force a press must reach to count as examined (the gauge marks it); 0: none.
    double examineAtN = 0.0;
    ViewText instruction;
    std::vector<ViewText> detail;  ///< shown joined with " · "
    double progress = 0.0;         ///< 0..1
    ViewText progressFormat;       ///< the progress bar's text (%p: its percentage)
    ViewText markTip;              ///< the Mark button's tooltip (empty: the window's own)
};

}  // namespace palpate
