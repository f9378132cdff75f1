#include "results/SettingsFileGuard.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <sys/stat.h>

namespace palpate {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::MainWindow)
};

QString& lastProblem() {
    static QString problem;
    return problem;
}

QString kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return Tr::tr("a folder");
    if (S_ISFIFO(mode)) return Tr::tr("a FIFO");
    if (S_ISCHR(mode) || S_ISBLK(mode)) return Tr::tr("a device");
    if (S_ISSOCK(mode)) return Tr::tr("a socket");
    return Tr::tr("not a regular file");
}

}  // namespace

QString settingsFileProblem() { return lastProblem(); }

QString guardSettingsFile() {
    lastProblem().clear();
    // Where QSettings keeps them (FirstRun.h): the path is built here, because constructing a
    // QSettings reads the file, and reading a FIFO never returns.
    const QString folder = QCoreApplication::organizationName().isEmpty() ? QCoreApplication::organizationDomain()
                                                                          : QCoreApplication::organizationName();
    const QString path = QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation) + QLatin1Char('/') +
                         folder + QLatin1Char('/') + QCoreApplication::applicationName() + QStringLiteral(".conf");
    const QByteArray native = QFile::encodeName(path);
    struct stat link {};
    if (::lstat(native.constData(), &link) != 0) return {};  // none yet: QSettings makes a regular file
    struct stat target {};
    const bool resolves = ::stat(native.constData(), &target) == 0;
    if (resolves && S_ISREG(target.st_mode)) return {};
    static QTemporaryDir temporary;  // this run's preferences, removed at exit
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, temporary.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, temporary.path());
    const QString what = !resolves               ? Tr::tr("a link to nothing")
                         : S_ISLNK(link.st_mode) ? Tr::tr("a link to %1").arg(kindOf(target.st_mode))
                                                 : kindOf(target.st_mode);
    lastProblem() = Tr::tr(
                        "%1 is %2, not a regular file: the preferences are neither read from it nor saved over it; "
                        "this run keeps them until it ends. Move it away to keep preferences again.")
                        .arg(QDir::toNativeSeparators(path), what);
    return lastProblem();
}

}  // namespace palpate
