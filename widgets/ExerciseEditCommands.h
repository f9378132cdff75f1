#pragma once
// Undo commands of the exercise editor. A command holds the whole exercise before and after the
// edit (an exercise is a few kilobytes even with many targets), so undo and redo restore every
// field, table and marker at once, and adding, removing, moving or placing by click is one step
// like any field edit. The commands know nothing about widgets: they hand the exercise to a
// callback that shows it.

#include "engine/exercise/Exercise.h"

#include <QUndoCommand>

#include <functional>

namespace palpate {

/// True when the two exercises are the same document: the same JSON (exerciseToJson) and the same
/// sourcePath (where their relative paths resolve from).
bool sameExercise(const Exercise& a, const Exercise& b);

/// Shows an exercise in the editor without pushing another command.
using ExerciseSink = std::function<void(const Exercise&)>;

class ExerciseEditCommand final : public QUndoCommand {
public:
    /// No merging: each command is its own step (adds, removes, moves, clicks, choices).
    static constexpr int kNoMerge = -1;

    /// `mergeKey` >= 0: consecutive commands with the same key (typing into one field) merge into
    /// one step; kNoMerge: never. The push's first redo() calls the sink too: the editor only sets
    /// the widgets whose value differs, so the field being typed in keeps its cursor.
    ExerciseEditCommand(const Exercise& before, const Exercise& after, const QString& text, int mergeKey,
                        ExerciseSink sink, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    /// Takes the newer edit's `after`; an edit that returns to `before` makes the step obsolete
    /// (QUndoStack drops it). A command that was undone once no longer absorbs new edits.
    bool mergeWith(const QUndoCommand* other) override;

    const Exercise& before() const { return mBefore; }
    const Exercise& after() const { return mAfter; }

private:
    /// Qt's command ids must not collide with other commands on a shared stack (the parameters
    /// panel uses 0x50410000).
    static constexpr int kIdBase = 0x45580000;  // "EX"

    Exercise mBefore;
    Exercise mAfter;
    int mMergeKey;
    bool mSealed = false;
    ExerciseSink mSink;
};

}  // namespace palpate
