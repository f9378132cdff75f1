#pragma once
// A text an exercise's kind chose (engine/exercise/ExerciseView.h), in the user's language: its
// template translated in the kinds' context, its numbers filled in.

#include "engine/exercise/ExerciseView.h"

#include <QString>

namespace palpate {

QString exerciseText(const ViewText& text);
/// "0.5–1.5 N": a force window as the trainee reads it.
QString forceRangeText(double minN, double maxN);

}  // namespace palpate
