#include "widgets/MeshSizeText.h"

#include <cmath>

namespace palpate {

QString formatLengthMm(double mm) {
    // Three significant digits, judged after rounding (99.97 is "100", not "100.0").
    for (int decimals = 0; decimals < 3; ++decimals) {
        const QString text = QString::number(mm, 'f', decimals);
        if (std::abs(text.toDouble()) >= std::pow(10.0, 2 - decimals)) return text;
    }
    return QString::number(mm, 'f', 3);
}

QString meshSizeText(const glm::dvec3& sizeMm) {
    return QStringLiteral("%1 × %2 × %3 mm")
        .arg(formatLengthMm(sizeMm.x), formatLengthMm(sizeMm.y), formatLengthMm(sizeMm.z));
}

}  // namespace palpate
