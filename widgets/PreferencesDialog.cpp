#include "widgets/PreferencesDialog.h"

#include "results/ServerConnectOptions.h"

#include "results/ResultsDatabase.h"

#include "device/open/DeviceUri.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QCheckBox>
#include <QSpinBox>
#include <QDoubleSpinBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QUrl>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <string>

#include <algorithm>

namespace palpate {

namespace {
constexpr double kNewtonsPerGramForce = 9.80665e-3;

/// The stored force unit, read once and kept up to date by save(): formatForce runs at the status
/// bar's rate and should not read QSettings each time.
QString& cachedForceUnit() {
    static QString unit = Preferences::load().forceUnit;
    return unit;
}
}  // namespace

Preferences Preferences::load() {
    QSettings settings;
    Preferences p;
    p.language = settings.value(kLanguageKey).toString();
    if (!languages().contains(p.language)) p.language.clear();
    p.forceUnit = settings.value(kForceUnitKey, QStringLiteral("N")).toString() == QLatin1String("gf")
                      ? QStringLiteral("gf")
                      : QStringLiteral("N");
    p.hapticRateHz = settings.value(kHapticRateKey, 0).toInt();
    if (!hapticRates().contains(p.hapticRateHz)) p.hapticRateHz = 0;
    p.deviceUri = settings.value(kDeviceUriKey).toString().trimmed();
    p.dataFolder = settings.value(kDataFolderKey).toString().trimmed();
    p.resultsServer = settings.value(kResultsServerKey).toString().trimmed();
    p.fadeGauge = settings.value(kFadeGaugeKey, true).toBool();
    p.fadeSessions = std::clamp(settings.value(kFadeSessionsKey, 5).toInt(), 1, 50);
    p.goodScore = std::clamp(settings.value(kGoodScoreKey, 80.0).toDouble(), 0.0, 100.0);
    return p;
}

void Preferences::save() const {
    QSettings settings;
    settings.setValue(kLanguageKey, language);
    settings.setValue(kForceUnitKey, forceUnit);
    settings.setValue(kHapticRateKey, hapticRateHz);
    settings.setValue(kDeviceUriKey, deviceUri);
    settings.setValue(kDataFolderKey, dataFolder);
    settings.setValue(kResultsServerKey, resultsServer);
    settings.setValue(kFadeGaugeKey, fadeGauge);
    settings.setValue(kFadeSessionsKey, fadeSessions);
    settings.setValue(kGoodScoreKey, goodScore);
    cachedForceUnit() = forceUnit;
}

QString Preferences::defaultDataFolder() { return palpate::defaultDataFolder(); }

QString Preferences::effectiveDataFolder() const { return dataFolder.isEmpty() ? defaultDataFolder() : dataFolder; }

QString Preferences::effectiveLanguage() const {
    if (!language.isEmpty()) return language;
    switch (QLocale::system().language()) {
    case QLocale::German: return QStringLiteral("de");
    case QLocale::Malay: return QStringLiteral("ms");
    default: return QStringLiteral("en");
    }
}

const QList<int>& Preferences::hapticRates() {
    static const QList<int> rates{0, 250, 500, 1000, 2000, 4000};
    return rates;
}

const QStringList& Preferences::languages() {
    static const QStringList codes{QString(), QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("ms")};
    return codes;
}

QString formatForce(double newtons, const QString& unit, int decimals) {
    if (unit == QLatin1String("gf"))
        return QCoreApplication::translate("palpate::Preferences", "%1 gf")
            .arg(QLocale().toString(newtons / kNewtonsPerGramForce, 'f', qMax(0, decimals - 1)));
    return QCoreApplication::translate("palpate::Preferences", "%1 N").arg(QLocale().toString(newtons, 'f', decimals));
}

QString formatForce(double newtons, int decimals) { return formatForce(newtons, cachedForceUnit(), decimals); }

PreferencesDialog::PreferencesDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));

    mLanguage = new QComboBox(this);
    mLanguage->setObjectName(QStringLiteral("languageBox"));
    // The languages are named in themselves, so that anyone can find theirs.
    mLanguage->addItem(tr("System default"), QString());
    mLanguage->addItem(QStringLiteral("English"), QStringLiteral("en"));
    mLanguage->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    mLanguage->addItem(QStringLiteral("Bahasa Melayu"), QStringLiteral("ms"));
    auto* languageNote = new QLabel(tr("A new language applies when Palpate is started again."), this);
    languageNote->setObjectName(QStringLiteral("languageNote"));
    languageNote->setWordWrap(true);

    mForceUnit = new QComboBox(this);
    mForceUnit->setObjectName(QStringLiteral("forceUnitBox"));
    mForceUnit->addItem(tr("newtons (N)"), QStringLiteral("N"));
    mForceUnit->addItem(tr("gram-force (gf, 1 gf = 9.81 mN)"), QStringLiteral("gf"));

    mHapticRate = new QComboBox(this);
    mHapticRate->setObjectName(QStringLiteral("hapticRateBox"));
    for (int rate : Preferences::hapticRates())
        mHapticRate->addItem(rate == 0 ? tr("As the tissue preset says") : tr("%1 Hz").arg(rate), rate);
    mHapticRate->setToolTip(tr("Ticks per second of the haptic loop. Higher rates feel stiffer tissue as stable, "
                               "and need a faster computer."));

    mDevice = new QComboBox(this);
    mDevice->setObjectName(QStringLiteral("deviceBox"));
    mDevice->setEditable(true);
    mDevice->addItem(tr("Built-in default (the mouse)"), QString());
    for (const DeviceSchemeInfo& scheme : listDeviceSchemes()) {
        DeviceUri parsed;
        std::string ignored;
        if (!(ignored = parseDeviceUri(scheme.uri, parsed)).empty()) continue;  // forms like sim:path:FILE: type them
        const QString uri = QString::fromStdString(scheme.uri);
        mDevice->addItem(uri, uri);
        mDevice->setItemData(mDevice->count() - 1, QString::fromStdString(scheme.description), Qt::ToolTipRole);
    }
    mDevice->setToolTip(tr("The device the window uses when it starts (--device overrides it)."));

    mDataFolder = new QLineEdit(this);
    mDataFolder->setObjectName(QStringLiteral("dataFolderEdit"));
    mDataFolder->setPlaceholderText(QDir::toNativeSeparators(Preferences::defaultDataFolder()));
    mDataFolder->setToolTip(tr("Recordings (in recordings/) and the trainees' results (results.sqlite) are kept here."));
    auto* browse = new QPushButton(tr("&Browse…"), this);
    browse->setObjectName(QStringLiteral("browseDataFolder"));
    connect(browse, &QPushButton::clicked, this, &PreferencesDialog::browseDataFolder);
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(mDataFolder, 1);
    folderRow->addWidget(browse);

    mResultsServer = new QLineEdit(this);
    mResultsServer->setObjectName(QStringLiteral("resultsServerEdit"));
    mResultsServer->setPlaceholderText(tr("none (results stay on this workstation)"));
    mResultsServer->setToolTip(tr("The class's PostgreSQL server, postgresql://user@host/database: every result is kept "
                                  "here first and copied there when it answers. The password goes in ~/.pgpass, never "
                                  "here (docs/results-store.md)."));
    connect(mResultsServer, &QLineEdit::textChanged, this, &PreferencesDialog::validate);

    auto* form = new QFormLayout;
    form->addRow(tr("&Language:"), mLanguage);
    form->addRow(QString(), languageNote);
    form->addRow(tr("&Forces shown in:"), mForceUnit);
    form->addRow(tr("&Haptic rate:"), mHapticRate);
    form->addRow(tr("&Device at start:"), mDevice);
    auto* folderLabel = new QLabel(tr("Data f&older:"), this);
    folderLabel->setBuddy(mDataFolder);
    form->addRow(folderLabel, folderRow);
    auto* serverLabel = new QLabel(tr("Class's &server:"), this);
    serverLabel->setBuddy(mResultsServer);
    form->addRow(serverLabel, mResultsServer);
    mFadeGauge = new QCheckBox(tr("F&ade the force gauge as the trainee improves"), this);
    mFadeGauge->setToolTip(tr("Continuous force feedback breeds dependence: each good session of an exercise fades "
                              "the gauge, each poor one brings it back"));
    mFadeSessions = new QSpinBox(this);
    mFadeSessions->setRange(1, 50);
    mFadeSessions->setSuffix(tr(" good sessions to fade out"));
    mGoodScore = new QDoubleSpinBox(this);
    mGoodScore->setRange(0.0, 100.0);
    mGoodScore->setDecimals(0);
    mGoodScore->setPrefix(tr("good at "));
    mGoodScore->setSuffix(tr(" / 100 or more"));
    auto* fadeRow = new QHBoxLayout;
    fadeRow->addWidget(mFadeSessions);
    fadeRow->addWidget(mGoodScore);
    form->addRow(tr("Guidance:"), mFadeGauge);
    form->addRow(QString(), fadeRow);
    connect(mFadeGauge, &QCheckBox::toggled, mFadeSessions, &QWidget::setEnabled);
    connect(mFadeGauge, &QCheckBox::toggled, mGoodScore, &QWidget::setEnabled);

    mProblemLabel = new QLabel(this);
    mProblemLabel->setObjectName(QStringLiteral("preferencesProblem"));
    mProblemLabel->setWordWrap(true);
    mProblemLabel->setStyleSheet(QStringLiteral("color: #b00020;"));
    mProblemLabel->hide();

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                         QDialogButtonBox::RestoreDefaults, this);
    mOkButton = buttons->button(QDialogButtonBox::Ok);
    connect(buttons, &QDialogButtonBox::accepted, this, &PreferencesDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &PreferencesDialog::reject);
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            &PreferencesDialog::restoreDefaults);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(mProblemLabel);
    layout->addStretch(1);
    layout->addWidget(buttons);

    connect(mDevice, &QComboBox::currentTextChanged, this, &PreferencesDialog::validate);
    connect(mDataFolder, &QLineEdit::textChanged, this, &PreferencesDialog::validate);
    setPreferences(Preferences::load());
    setMinimumWidth(520);
}

void PreferencesDialog::setPreferences(const Preferences& p) {
    mLanguage->setCurrentIndex(qMax(0, mLanguage->findData(p.language)));
    mForceUnit->setCurrentIndex(qMax(0, mForceUnit->findData(p.forceUnit)));
    mHapticRate->setCurrentIndex(qMax(0, mHapticRate->findData(p.hapticRateHz)));
    if (p.deviceUri.isEmpty()) mDevice->setCurrentIndex(0);
    else if (const int i = mDevice->findData(p.deviceUri); i >= 0) mDevice->setCurrentIndex(i);
    else mDevice->setEditText(p.deviceUri);
    mDataFolder->setText(QDir::toNativeSeparators(p.dataFolder));
    mResultsServer->setText(p.resultsServer);
    mFadeGauge->setChecked(p.fadeGauge);
    mFadeSessions->setValue(p.fadeSessions);
    mGoodScore->setValue(p.goodScore);
    mFadeSessions->setEnabled(p.fadeGauge);
    mGoodScore->setEnabled(p.fadeGauge);
    validate();
}

Preferences PreferencesDialog::preferences() const {
    Preferences p;
    p.language = mLanguage->currentData().toString();
    p.forceUnit = mForceUnit->currentData().toString();
    p.hapticRateHz = mHapticRate->currentData().toInt();
    const QString text = mDevice->currentText().trimmed();
    p.deviceUri = (mDevice->currentIndex() == 0 && text == mDevice->itemText(0)) ? QString() : text;
    p.dataFolder = QDir::fromNativeSeparators(mDataFolder->text().trimmed());
    p.resultsServer = mResultsServer->text().trimmed();
    p.fadeGauge = mFadeGauge->isChecked();
    p.fadeSessions = mFadeSessions->value();
    p.goodScore = mGoodScore->value();
    return p;
}

void PreferencesDialog::validate() {
    const Preferences p = preferences();
    mProblem.clear();
    if (!p.deviceUri.isEmpty()) {
        DeviceUri parsed;
        std::string error;
        if (!(error = parseDeviceUri(p.deviceUri.toStdString(), parsed)).empty())
            mProblem = tr("Device: %1").arg(QString::fromStdString(error));
    }
    if (mProblem.isEmpty() && !p.dataFolder.isEmpty() && QDir::isRelativePath(p.dataFolder))
        mProblem = tr("The data folder must be an absolute path.");
    if (mProblem.isEmpty() && !p.resultsServer.isEmpty()) {
        const QUrl url(p.resultsServer);
        if (!isServerLocation(p.resultsServer) || !url.isValid() || url.host().isEmpty() || url.path().size() < 2)
            mProblem = tr("Class's server: postgresql://[user@]host[:port]/database");
        else if (!url.password().isEmpty())
            mProblem = tr("Class's server: no password here; put it in ~/.pgpass (docs/results-store.md).");
        // The query's options as the store will read them: a password in any form, an option
        // the URL may not set, a timeout out of range.
        else if (QString why; !serverConnectOptions(url, why)) mProblem = tr("Class's server: %1").arg(why);
    }
    mProblemLabel->setText(mProblem);
    mProblemLabel->setVisible(!mProblem.isEmpty());
    if (mOkButton) mOkButton->setEnabled(mProblem.isEmpty());
}

void PreferencesDialog::restoreDefaults() { setPreferences(Preferences{}); }

void PreferencesDialog::browseDataFolder() {
    const QString start = preferences().effectiveDataFolder();
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Data Folder"), start);
    if (!folder.isEmpty()) mDataFolder->setText(QDir::toNativeSeparators(folder));
}

void PreferencesDialog::accept() {
    validate();
    if (!mProblem.isEmpty()) return;
    preferences().save();
    QDialog::accept();
}

}  // namespace palpate
