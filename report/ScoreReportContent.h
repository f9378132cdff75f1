#pragma once
// What the printable score report shows (ScoreReportPdf.h), gathered from a recorded session
// (ScoreReportFromRecording.h): who, which exercise, when, on which device, the score and its
// breakdown, each press target's definition, the force over time and which force window applied
// when. The GUI's export and `palpate-cli score --pdf` fill it the same way (docs/scoring.md).

#include "engine/exercise/Exercise.h"
#include "engine/exercise/ScoreReport.h"

#include <glm/vec3.hpp>

#include <QDateTime>
#include <QString>

#include <vector>

namespace palpate {

/// One sample of the force plot: recording time (s from the first recorded tick) and |F| (N).
struct ForceSample {
    double timeS = 0.0;
    double forceN = 0.0;
};

/// A force window over the stretch of the session it applied to: a press target's own window
/// while that target was the current one, or a trace's band over the traced time.
struct ForceWindowSpan {
    double startS = 0.0, endS = 0.0;  ///< recording time, as ForceSample::timeS
    double forceMinN = 0.0, forceMaxN = 0.0;
    int targetIndex = -1;             ///< the press target (0-based); -1: the trace's band
};

struct ScoreReportContent {
    QString traineeName;        ///< may be empty (not known)
    QString exerciseName;
    QString device;             ///< the recorded device's name and URI
    QDateTime sessionStart;     ///< invalid when the recording does not say
    ScoreReport report;
    std::vector<PressTarget> targets;  ///< the press targets as graded (empty for other types)
    std::vector<LumpDef> lumps;        ///< detect lumps: the lumps as graded (the table's depth, size, contrast)
    /// Palpation: the mesh at rest (engine order, as the heat map's peakForceN), for its picture.
    std::vector<glm::vec3> surfaceMm, normals;
    std::vector<ForceSample> force;    ///< empty: the plot is left out
    std::vector<ForceWindowSpan> windows;
};

}  // namespace palpate
