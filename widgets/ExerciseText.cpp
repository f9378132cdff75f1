#include "widgets/ExerciseText.h"

#include "engine/exercise/ExerciseKind.h"

#include <QCoreApplication>
#include <QObject>

namespace palpate {

QString forceRangeText(double minN, double maxN) {
    return QObject::tr("%1–%2 N").arg(minN, 0, 'g', 3).arg(maxN, 0, 'g', 3);
}

QString exerciseText(const ViewText& text) {
    if (text.empty()) return {};
    QString out = QCoreApplication::translate(kExerciseTextContext, text.text, nullptr, text.count);
    for (const ViewText::Arg& arg : text.args) {
        switch (arg.kind) {
            case ViewText::ArgKind::Whole: out = out.arg(qlonglong(arg.a)); break;
            case ViewText::ArgKind::Fixed: out = out.arg(arg.a, 0, 'f', arg.decimals); break;
            case ViewText::ArgKind::ForceRange: out = out.arg(forceRangeText(arg.a, arg.b)); break;
        }
    }
    return out;
}

}  // namespace palpate
