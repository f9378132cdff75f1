#include "report/ScoreReportFromRecording.h"

#include "report/ExerciseWords.h"
#include "engine/exercise/ExerciseKind.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace palpate {

namespace {

/// The force window a tick was judged against, by tick: runs of ticks with the same window.
struct TickSpan {
    std::uint64_t firstTick = 0, lastTick = 0;
    double forceMinN = 0.0, forceMaxN = 0.0;
    int targetIndex = -1;
};

/// Replays the whole recording, noting before each scored tick the window the scorer judges it by
/// (the guidance's current window: a press target's own, or the trace's band).
std::vector<TickSpan> replayWindows(ReplayScorer& scorer, ExerciseType type) {
    std::vector<TickSpan> spans;
    if (exerciseKind(type).palpation()) {  // no force window to shade
        scorer.advanceAll();
        return spans;
    }
    while (!scorer.scorer().over()) {
        const ScoreGuidance before = scorer.scorer().guidance();
        if (scorer.advanceTo(scorer.currentTick() + 1) == 0) break;
        const int target = before.targetIndex;         // -1: no target (a trace's band)
        if (before.targetCount > 0 && target < 0) continue;  // every target done
        if (!(before.forceMaxN > before.forceMinN)) continue;
        const std::uint64_t tick = scorer.currentTick();
        if (!spans.empty() && spans.back().targetIndex == target && spans.back().forceMinN == before.forceMinN &&
            spans.back().forceMaxN == before.forceMaxN)
            spans.back().lastTick = tick;
        else
            spans.push_back({tick, tick, before.forceMinN, before.forceMaxN, target});
    }
    scorer.advanceAll();  // what is left after the end is counted, not scored
    return spans;
}

}  // namespace

std::vector<ForceSample> recordedForceSeries(const RecordingReader& reader, std::size_t maxPoints) {
    std::vector<ForceSample> all;
    if (!reader.headerOk()) return all;
    double firstS = -1.0;
    reader.forEachTick([&](const RecordedTick& t) {
        if (firstS < 0.0) firstS = t.nowS;
        all.push_back({t.nowS - firstS, double(glm::length(t.forceN))});
        return true;
    });
    if (maxPoints < 2 || all.size() <= maxPoints) return all;
    std::vector<ForceSample> thin;
    const std::size_t bucket = (all.size() + maxPoints - 1) / maxPoints;
    for (std::size_t i = 0; i < all.size(); i += bucket) {
        ForceSample best = all[i];
        for (std::size_t j = i; j < std::min(all.size(), i + bucket); ++j)
            if (all[j].forceN > best.forceN) best = all[j];
        thin.push_back(best);
    }
    return thin;
}

QString recordedTraineeName(const RecordingHeader& header) {
    const QString prefix = QStringLiteral("trainee: ");
    for (const QString& line : QString::fromStdString(header.note).split(QLatin1Char('\n')))
        if (line.startsWith(prefix)) return line.mid(prefix.size()).trimmed();
    return {};
}

bool scoreReportFromRecording(const QString& recordingPath, const Exercise* exercise, const QString& traineeName,
                              const ReplayScorerDef& options, ScoreReportContent& content, QString* error) {
    const RecordingReader reader = RecordingReader::open(recordingPath.toStdString());
    std::string problem;
    auto scorer = ReplayScorer::open(reader, exercise, problem, options);
    if (!scorer) {
        if (error) *error = QString::fromStdString(problem);
        return false;
    }
    const Exercise& graded = scorer->exercise();
    const std::vector<TickSpan> spans = replayWindows(*scorer, graded.type);

    content = {};
    content.report = scorer->report();
    content.exerciseName = shownExerciseName(graded);  // the report is read in the window's language
    content.traineeName = traineeName.isEmpty() ? recordedTraineeName(reader.header()) : traineeName;
    const RecordedDevice& device = reader.header().device;
    content.device = device.spec.name.empty() || device.spec.name == device.uri
                         ? QString::fromStdString(device.uri)
                         : QStringLiteral("%1 (%2)").arg(QString::fromStdString(device.spec.name),
                                                         QString::fromStdString(device.uri));
    if (reader.header().startUnixUs > 0)
        content.sessionStart = QDateTime::fromMSecsSinceEpoch(reader.header().startUnixUs / 1000);
    content.targets = graded.pressTargets.targets;  // empty but for press targets
    content.lumps = graded.detectLumps.lumps;       // empty but for detect lumps
    if (content.report.palpation) {
        content.surfaceMm = scorer->scorer().geometry().restMm();
        content.normals = scorer->scorer().geometry().normals();
    }
    content.force = recordedForceSeries(reader);

    // Ticks to the plot's time (s from the first recorded tick), as the force series counts it.
    std::vector<std::pair<std::uint64_t, double>> tickTimes;
    double firstS = -1.0;
    reader.forEachTick([&](const RecordedTick& t) {
        if (firstS < 0.0) firstS = t.nowS;
        tickTimes.emplace_back(t.tick, t.nowS - firstS);
        return true;
    });
    auto timeOf = [&](std::uint64_t tick) {
        auto it = std::lower_bound(tickTimes.begin(), tickTimes.end(), tick,
                                   [](const auto& a, std::uint64_t t) { return a.first < t; });
        if (it == tickTimes.end()) return tickTimes.empty() ? 0.0 : tickTimes.back().second;
        return it->second;
    };
    for (const TickSpan& s : spans)
        content.windows.push_back({timeOf(s.firstTick), timeOf(s.lastTick), s.forceMinN, s.forceMaxN, s.targetIndex});
    return true;
}

}  // namespace palpate
