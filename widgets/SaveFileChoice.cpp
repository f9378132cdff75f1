#include "widgets/SaveFileChoice.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>

namespace palpate {

QString withSuffixConfirmed(QWidget* parent, const QString& chosen, const QString& suffix) {
    if (chosen.isEmpty() || !QFileInfo(chosen).suffix().isEmpty()) return chosen;  // the dialog asked
    const QString path = chosen + suffix;
    if (!QFileInfo::exists(path)) return path;
    const auto answer = QMessageBox::question(
        parent, QCoreApplication::translate("palpate::SaveFileChoice", "Replace the file?"),
        QCoreApplication::translate("palpate::SaveFileChoice", "%1 already exists. Replace it?")
            .arg(QDir::toNativeSeparators(path)),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
    return answer == QMessageBox::Yes ? path : QString();
}

}  // namespace palpate
