#pragma once
// Preferences (Edit > Preferences…): language, the unit forces are shown in, the haptic rate, the
// device used at start and the data folder. Stored in QSettings under these keys:
//
//   language           ""(the system's) | "en" | "de" | "ms"   applies at the next start
//   units/force        "N" | "gf"                              where forces are shown (formatForce)
//   haptic/rateHz      0 (the tissue preset's own) | 250..4000 at start, and on OK
//   device/defaultUri  "" (built-in: mouse:) | a device URI    the interactive window's device at start
//   dataFolder         "" (QStandardPaths::AppDataLocation)    recordings/ and results.sqlite, at start and on OK
//   results/serverUrl  "" (none) | postgresql://host/database  the class's server results are copied to (docs/results-store.md)
//   firstRunDone       bool                                    the welcome page is not shown at start
//   guidance/fadeGauge bool (true)                             the force gauge fades as a trainee improves
//   guidance/fadeSessions 1..50 (5)                            good sessions from a full gauge to none
//   guidance/goodScore 0..100 (80)                             a session this good fades it (docs/scoring.md)
//
// --device, --preset and the recorder's own Folder… choice win over these.

#include "results/DataFolder.h"

#include <QDialog>
#include <QList>
#include <QString>
#include <QStringList>

class QCheckBox;
class QDoubleSpinBox;
class QSpinBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace palpate {

struct Preferences {
    static constexpr const char* kLanguageKey = "language";
    static constexpr const char* kForceUnitKey = "units/force";
    static constexpr const char* kHapticRateKey = "haptic/rateHz";
    static constexpr const char* kDeviceUriKey = "device/defaultUri";
    static constexpr const char* kDataFolderKey = palpate::kDataFolderKey;  // results/DataFolder.h
    static constexpr const char* kFirstRunDoneKey = "firstRunDone";
    static constexpr const char* kFadeGaugeKey = "guidance/fadeGauge";
    static constexpr const char* kFadeSessionsKey = "guidance/fadeSessions";
    static constexpr const char* kGoodScoreKey = "guidance/goodScore";
    static constexpr const char* kResultsServerKey = "results/serverUrl";

    QString language;                       ///< "" = follow the system locale
    QString forceUnit = QStringLiteral("N");  ///< "N" or "gf" (gram-force: 1 gf = 9.80665 mN)
    int hapticRateHz = 0;                   ///< 0 = the tissue preset's rate
    QString deviceUri;                      ///< "" = the built-in default (the mouse)
    QString dataFolder;                     ///< "" = defaultDataFolder()
    QString resultsServer;                  ///< "" = none; a postgresql:// URL without a password
    bool fadeGauge = true;                  ///< fading guidance (GuidanceFadeDef)
    int fadeSessions = 5;
    double goodScore = 80.0;

    static Preferences load();
    void save() const;
    /// dataFolder, else defaultDataFolder().
    QString effectiveDataFolder() const;
    /// QStandardPaths::AppDataLocation.
    static QString defaultDataFolder();
    /// The language to load: `language`, else the system locale's ("de", "ms"; "en" for any other).
    QString effectiveLanguage() const;
    /// The haptic rates offered (Hz); 0 is "the preset's".
    static const QList<int>& hapticRates();
    /// The languages offered: codes, "" first (the system's).
    static const QStringList& languages();

    bool operator==(const Preferences&) const = default;
};

/// A force in the unit the preferences name, with the unit: "1.25 N" or "127.5 gf".
QString formatForce(double newtons, const QString& unit, int decimals = 2);
/// The same in the stored unit (QSettings "units/force", read once, updated by Preferences::save()).
/// For the status bar: mForceLabel->setText(tr("force %1").arg(formatForce(double(glm::length(o.forceN)))));
QString formatForce(double newtons, int decimals = 2);

class PreferencesDialog final : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(QWidget* parent = nullptr);

    /// Shows `preferences` in the fields.
    void setPreferences(const Preferences& preferences);
    /// What the fields say now (validated: an unknown device URI is kept as typed).
    Preferences preferences() const;
    /// "" when the fields can be saved, else why not (shown in the dialog; OK is disabled).
    QString problem() const { return mProblem; }

    QComboBox* languageBox() const { return mLanguage; }
    QComboBox* forceUnitBox() const { return mForceUnit; }
    QComboBox* hapticRateBox() const { return mHapticRate; }
    QComboBox* deviceBox() const { return mDevice; }
    QLineEdit* dataFolderEdit() const { return mDataFolder; }
    QCheckBox* fadeGaugeBox() const { return mFadeGauge; }

public slots:
    /// Saves to QSettings and closes (OK).
    void accept() override;

private:
    void restoreDefaults();
    void browseDataFolder();
    void validate();

    QComboBox* mLanguage = nullptr;
    QComboBox* mForceUnit = nullptr;
    QComboBox* mHapticRate = nullptr;
    QComboBox* mDevice = nullptr;
    QLineEdit* mDataFolder = nullptr;
    QLineEdit* mResultsServer = nullptr;
    QCheckBox* mFadeGauge = nullptr;
    QSpinBox* mFadeSessions = nullptr;
    QDoubleSpinBox* mGoodScore = nullptr;
    QLabel* mProblemLabel = nullptr;
    QPushButton* mOkButton = nullptr;
    QString mProblem;
};

}  // namespace palpate
