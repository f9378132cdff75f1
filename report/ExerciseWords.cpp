#include "report/ExerciseWords.h"

#include <QCoreApplication>

namespace palpate {

std::string shownLanguage() {
    // Each catalogue names its own language here, so no setting can disagree with the texts shown.
    return QCoreApplication::translate("palpate::Language", "en",
                                       "The code of the language of this translation: de, ms. Exercise files "
                                       "carry their name and description under it.")
        .toStdString();
}

QString shownExerciseName(const Exercise& exercise) {
    return QString::fromStdString(exerciseTextIn(exercise, shownLanguage()).name);
}

QString shownExerciseDescription(const Exercise& exercise) {
    return QString::fromStdString(exerciseTextIn(exercise, shownLanguage()).description);
}

}  // namespace palpate
