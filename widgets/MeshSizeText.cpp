#include "widgets/MeshSizeText.h"

#include <cmath>

namespace palpate {

QString formatLengthMm(double mm) {
    const double magnitude = std::abs(mm);
    const int decimals = magnitude >= 100.0 ? 0 : magnitude >= 10.0 ? 1 : magnitude >= 1.0 ? 2 : 3;
    return QString::number(mm, 'f', decimals);
}

QString meshSizeText(const glm::dvec3& sizeMm) {
    return QStringLiteral("%1 × %2 × %3 mm")
        .arg(formatLengthMm(sizeMm.x), formatLengthMm(sizeMm.y), formatLengthMm(sizeMm.z));
}

}  // namespace palpate
