#pragma once
// Replacing an existing file needs the user's explicit choice (docs/reliability.md). QFileDialog asks
// about the name as typed; a suffix the panel adds afterwards ("tissue" -> "tissue.json") names
// another file, which is asked about here.

#include <QString>

class QWidget;

namespace palpate {

/// `chosen` (a save dialog's answer) with `suffix` (".json") added when it has none. When that adds
/// the suffix and the file exists, the user is asked whether to replace it: "" when they decline.
QString withSuffixConfirmed(QWidget* parent, const QString& chosen, const QString& suffix);

}  // namespace palpate
