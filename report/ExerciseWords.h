#pragma once
// An exercise's name and description as the user reads them: the translation its file carries for
// the language the window is shown in, else its own words (docs/scoring.md, "Translations").

#include "engine/exercise/Exercise.h"

#include <QString>

#include <string>

namespace palpate {

/// The language the program's texts are shown in ("en", "de", "ms"): the one whose translation is
/// installed, so it always matches the rest of the window.
std::string shownLanguage();
/// The exercise's name in that language.
QString shownExerciseName(const Exercise& exercise);
/// The exercise's description in that language.
QString shownExerciseDescription(const Exercise& exercise);

}  // namespace palpate
