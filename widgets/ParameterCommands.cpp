#include "widgets/ParameterCommands.h"

#include <utility>

namespace palpate {

ParameterEditCommand::ParameterEditCommand(const TissuePreset& before, const TissuePreset& after, const QString& text,
                                           int mergeKey, bool alreadyShown, PresetSink sink, QUndoCommand* parent)
    : QUndoCommand(text, parent),
      mBefore(before),
      mAfter(after),
      mMergeKey(mergeKey),
      mSkipNextRedo(alreadyShown),
      mSink(std::move(sink)) {}

void ParameterEditCommand::undo() {
    mSealed = true;
    mSink(mBefore);
}

void ParameterEditCommand::redo() {
    if (mSkipNextRedo) {
        mSkipNextRedo = false;
        return;
    }
    mSink(mAfter);
}

int ParameterEditCommand::id() const { return mMergeKey < 0 ? -1 : kIdBase + mMergeKey; }

bool ParameterEditCommand::mergeWith(const QUndoCommand* other) {
    if (mSealed || other->id() != id()) return false;
    const auto* edit = static_cast<const ParameterEditCommand*>(other);
    mAfter = edit->mAfter;
    setObsolete(samePreset(mBefore, mAfter));
    return true;
}

}  // namespace palpate
