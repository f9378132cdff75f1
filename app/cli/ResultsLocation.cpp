// Built with the GUI only: the data folder is Qt's (QStandardPaths).
#ifdef PALPATE_HAVE_CHARTS
#include "app/cli/ResultsLocation.h"

#include <QCoreApplication>
#include <QDir>
#include <QStandardPaths>

namespace palpate::cli {

std::string defaultDatabasePath() {
    // The GUI's names (app/gui/FirstRun.cpp setApplicationNames): the same data folder.
    QCoreApplication::setApplicationName(QStringLiteral("palpate"));
    QCoreApplication::setOrganizationName(QString());
    QCoreApplication::setOrganizationDomain(QStringLiteral("palpate"));
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("results.sqlite"))
        .toStdString();
}

}  // namespace palpate::cli

#endif  // PALPATE_HAVE_CHARTS
