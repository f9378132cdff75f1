#include "widgets/MeshSizeText.h"

#include <QLocale>

#include <cmath>

namespace palpate {

QString formatLengthMm(double mm) {
    // In the user's decimal sign, without grouping ("1500 mm", not "1,500 mm").
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    // Three significant digits, judged after rounding (99.97 is "100", not "100.0").
    for (int decimals = 0; decimals < 3; ++decimals)
        if (std::abs(QString::number(mm, 'f', decimals).toDouble()) >= std::pow(10.0, 2 - decimals))
            return locale.toString(mm, 'f', decimals);
    return locale.toString(mm, 'f', 3);
}

QString meshSizeText(const glm::dvec3& sizeMm) {
    return QStringLiteral("%1 × %2 × %3 mm")
        .arg(formatLengthMm(sizeMm.x), formatLengthMm(sizeMm.y), formatLengthMm(sizeMm.z));
}

}  // namespace palpate
