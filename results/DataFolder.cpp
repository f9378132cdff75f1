#include "results/DataFolder.h"

#include "results/SettingsFileGuard.h"

#include <QDir>
#include <QSettings>
#include <QStandardPaths>

namespace palpate {

QString defaultDataFolder() { return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation); }

QString dataFolder() {
    guardSettingsFile();
    const QString chosen = QSettings().value(QLatin1String(kDataFolderKey)).toString().trimmed();
    return chosen.isEmpty() ? defaultDataFolder() : chosen;
}

QString resultsStorePath(const QString& folder) { return QDir(folder).filePath(QStringLiteral("results.sqlite")); }

QString defaultResultsStore() { return resultsStorePath(dataFolder()); }

}  // namespace palpate
