#pragma once
// Undo commands of the parameters panel. A command holds the whole preset before and after the
// edit (a TissuePreset is a few hundred bytes), so undo and redo restore every field at once and a
// loaded preset is one step like any edit. The commands know nothing about widgets: they hand the
// preset to a callback that shows it; samePreset (engine/scene/TissuePreset.h) is the undo check.

#include "engine/scene/TissuePreset.h"

#include <QUndoCommand>

#include <functional>

namespace palpate {

/// Shows a preset in the panel's fields without pushing another command.
using PresetSink = std::function<void(const TissuePreset&)>;

class ParameterEditCommand final : public QUndoCommand {
public:
    /// No merging: each command is its own step (loads, discrete choices).
    static constexpr int kNoMerge = -1;

    /// `mergeKey` >= 0: consecutive commands with the same key (edits of one field) merge into
    /// one step; kNoMerge: never. `alreadyShown`: the fields show `after` already (the user edited
    /// them), so the push's first redo() does not set them again under the user's cursor.
    ParameterEditCommand(const TissuePreset& before, const TissuePreset& after, const QString& text, int mergeKey,
                         bool alreadyShown, PresetSink sink, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    /// Takes the newer edit's `after`; an edit that returns to `before` makes the step obsolete
    /// (QUndoStack drops it). A command that was undone once no longer absorbs new edits.
    bool mergeWith(const QUndoCommand* other) override;

    const TissuePreset& before() const { return mBefore; }
    const TissuePreset& after() const { return mAfter; }

private:
    /// Qt's command ids must not collide with other commands on a shared stack.
    static constexpr int kIdBase = 0x50410000;  // "PA"

    TissuePreset mBefore;
    TissuePreset mAfter;
    int mMergeKey;
    bool mSkipNextRedo;
    bool mSealed = false;
    PresetSink mSink;
};

}  // namespace palpate
