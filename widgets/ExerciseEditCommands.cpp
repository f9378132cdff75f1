#include "widgets/ExerciseEditCommands.h"

#include "engine/exercise/ExerciseFile.h"

#include <utility>

namespace palpate {

bool sameExercise(const Exercise& a, const Exercise& b) {
    // The JSON holds every saved value exactly (doubles round-trip); sourcePath is not saved.
    return a.sourcePath == b.sourcePath && exerciseToJson(a, -1) == exerciseToJson(b, -1);
}

ExerciseEditCommand::ExerciseEditCommand(const Exercise& before, const Exercise& after, const QString& text,
                                         int mergeKey, ExerciseSink sink, QUndoCommand* parent)
    : QUndoCommand(text, parent), mBefore(before), mAfter(after), mMergeKey(mergeKey), mSink(std::move(sink)) {}

void ExerciseEditCommand::undo() {
    mSealed = true;
    mSink(mBefore);
}

void ExerciseEditCommand::redo() { mSink(mAfter); }

int ExerciseEditCommand::id() const { return mMergeKey < 0 ? -1 : kIdBase + mMergeKey; }

bool ExerciseEditCommand::mergeWith(const QUndoCommand* other) {
    if (mSealed || other->id() != id()) return false;
    const auto* edit = static_cast<const ExerciseEditCommand*>(other);
    mAfter = edit->mAfter;
    setObsolete(sameExercise(mBefore, mAfter));
    return true;
}

}  // namespace palpate
