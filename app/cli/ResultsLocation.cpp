// Built with the GUI only: the data folder is Qt's (QStandardPaths).
#ifdef PALPATE_HAVE_CHARTS
#include "app/cli/ResultsLocation.h"

#include "results/DataFolder.h"
#include "results/SettingsFileGuard.h"

#include <QCoreApplication>

#include <iostream>

namespace palpate::cli {

std::string defaultDatabasePath() {
    // The GUI's names (app/gui/FirstRun.cpp setApplicationNames): the same data folder.
    QCoreApplication::setApplicationName(QStringLiteral("palpate"));
    QCoreApplication::setOrganizationName(QString());
    QCoreApplication::setOrganizationDomain(QStringLiteral("palpate"));
    // The window's store: the data folder of its preferences (results/DataFolder.h).
    const QString store = defaultResultsStore();
    // A preferences file that is not a regular file is not read (a FIFO would hang): say so once.
    static bool told = false;
    if (const QString problem = settingsFileProblem(); !problem.isEmpty() && !told) {
        std::cerr << "palpate-cli: " << problem.toStdString() << "\n";
        told = true;
    }
    return store.toStdString();
}

}  // namespace palpate::cli

#endif  // PALPATE_HAVE_CHARTS
