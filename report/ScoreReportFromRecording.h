#pragma once
// The score report's content from a recorded exercise session: the recording is replayed and
// scored (ReplayScorer, the same scorer the live session uses), and the replay says which force
// window applied at each tick. The GUI's "export score report" and `palpate-cli score --pdf` both
// come through here, so they print the same report (docs/scoring.md).

#include "report/ScoreReportContent.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"

#include <QString>

#include <cstddef>
#include <vector>

namespace palpate {

/// Every tick's |F| (s from the first recorded tick), thinned to at most `maxPoints` by buckets
/// that keep their largest force (peaks are what a plot must not lose); empty without a header.
std::vector<ForceSample> recordedForceSeries(const RecordingReader& reader, std::size_t maxPoints = 4000);

/// The trainee the recording's note names ("trainee: NAME", as the GUI's sessions write it), or "".
QString recordedTraineeName(const RecordingHeader& header);

/// Replays and scores `recordingPath` by `exercise` (null: the exercise the recording carries) and
/// fills `content`. `traineeName` empty: the one the note names. False with `error` (naming the
/// file) when the recording cannot be scored.
bool scoreReportFromRecording(const QString& recordingPath, const Exercise* exercise, const QString& traineeName,
                              const ReplayScorerDef& options, ScoreReportContent& content, QString* error);

}  // namespace palpate
