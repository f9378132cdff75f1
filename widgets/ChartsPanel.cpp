#include "widgets/ChartsPanel.h"

#include "results/HandOff.h"

#include "widgets/SaveFileChoice.h"
#include "engine/accuracy/SweepCsv.h"
#include "report/SpeedAccuracyChart.h"
#include "widgets/FeelPanel.h"
#include "widgets/StiffeningPanel.h"
#include "engine/accuracy/OrganSweep.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSaveFile>
#include <QTabWidget>
#include <QThread>
#include <QVBoxLayout>

#include <exception>

namespace palpate {

namespace {

constexpr int kProgressSteps = 1000;

/// FILE.json next to FILE.csv: the sweep's JSON (palpate-cli sweep --json), which names the tissue.
QString sidecarJson(const QString& csvPath) {
    const QFileInfo info(csvPath);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".json"));
}

std::optional<ToolContact> readSidecarContact(const QString& csvPath) {
    QFile file(sidecarJson(csvPath));
    if (!file.open(QIODevice::ReadOnly)) return std::nullopt;
    const QJsonObject j = QJsonDocument::fromJson(file.readAll()).object();
    const auto e = j.value(QStringLiteral("youngs_modulus_kpa")), nu = j.value(QStringLiteral("poisson_ratio")),
               a = j.value(QStringLiteral("tool_radius_mm"));
    if (!e.isDouble() || !nu.isDouble() || !a.isDouble()) return std::nullopt;
    ToolContact contact;
    contact.material = {e.toDouble() * 1e-3, nu.toDouble()};
    contact.toolRadiusMm = a.toDouble();
    if (!validateToolContact(contact).empty()) return std::nullopt;
    return contact;
}

}  // namespace

QString ChartsPanel::pointsText(int count) { return count == 1 ? tr("1 point") : tr("%1 points").arg(count); }

ChartsPanel::ChartsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("chartsPanel"));
    mChart = new SpeedAccuracyChart(this);
    mChart->setMinimumSize(360, 280);
    mChart->setFrameShape(QFrame::NoFrame);
    // The legend under the chart, wrapping: the chart's own legend would take the plot's width.
    mChart->setLegendShown(false);
    mLegendLabel = new QLabel(this);
    mLegendLabel->setObjectName(QStringLiteral("chartLegendLabel"));
    mLegendLabel->setWordWrap(true);
    mLegendLabel->setTextFormat(Qt::RichText);
    mLegendLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    connect(mChart, &SpeedAccuracyChart::rebuilt, this, [this] {
        mLegendLabel->setText(mChart->legendHtml());
        mLegendLabel->setVisible(!mChart->points().empty());
    });
    mLegendLabel->setVisible(false);

    mRunButton = new QPushButton(this);
    mRunButton->setObjectName(QStringLiteral("runSweepButton"));
    connect(mRunButton, &QPushButton::clicked, this, &ChartsPanel::runSweep);
    mQuickCheck = new QCheckBox(this);
    mQuickCheck->setObjectName(QStringLiteral("quickSweepCheck"));
    mQuickCheck->setChecked(true);
    mReferenceCombo = new QComboBox(this);
    mReferenceCombo->setObjectName(QStringLiteral("sweepReferenceCombo"));
    mReferenceCombo->addItem(QString(), QStringLiteral("punch"));
    mReferenceCombo->addItem(QString(), QStringLiteral("fem"));
    mCancelButton = new QPushButton(this);
    mCancelButton->setObjectName(QStringLiteral("cancelSweepButton"));
    connect(mCancelButton, &QPushButton::clicked, this, &ChartsPanel::cancelSweep);
    mOpenButton = new QPushButton(this);
    mOpenButton->setObjectName(QStringLiteral("openSweepCsvButton"));
    connect(mOpenButton, &QPushButton::clicked, this, &ChartsPanel::openCsvDialog);
    mSaveButton = new QPushButton(this);
    mSaveButton->setObjectName(QStringLiteral("saveSweepCsvButton"));
    connect(mSaveButton, &QPushButton::clicked, this, &ChartsPanel::saveCsvDialog);
    mShapeLabel = new QLabel(this);
    mShapeCombo = new QComboBox(this);
    mShapeCombo->setObjectName(QStringLiteral("sweepShapeCombo"));
    mShapeCombo->setSizeAdjustPolicy(QComboBox::AdjustToContents);  // "Stomach, curved site" after "Sphere"
    mShapeLabel->setBuddy(mShapeCombo);
    connect(mShapeCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index < 0) return;
        const QStringList data = mShapeCombo->itemData(index).toStringList();
        mChart->setShape(GeneratedShape(data.value(0).toInt()));
        mChart->setSite(data.value(1).toStdString());
    });

    mProgress = new QProgressBar(this);
    mProgress->setObjectName(QStringLiteral("sweepProgress"));
    mProgress->setRange(0, kProgressSteps);
    mProgress->setValue(0);
    mStatusLabel = new QLabel(this);
    mStatusLabel->setObjectName(QStringLiteral("sweepStatusLabel"));
    mStatusLabel->setWordWrap(true);
    mStatusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mCurrentLabel = new QLabel(this);
    mCurrentLabel->setObjectName(QStringLiteral("currentConfigurationLabel"));
    mCurrentLabel->setWordWrap(true);

    auto* runRow = new QHBoxLayout;
    runRow->addWidget(mRunButton);
    runRow->addWidget(mQuickCheck);
    runRow->addWidget(mReferenceCombo);
    runRow->addWidget(mCancelButton);
    runRow->addStretch(1);
    runRow->addWidget(mShapeLabel);
    runRow->addWidget(mShapeCombo);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(mOpenButton);
    fileRow->addWidget(mSaveButton);
    fileRow->addStretch(1);

    // The sweep's chart and the feel chart on two tabs: a dock is narrow and short, and stacked the
    // two charts (each with its legend and buttons) had less than their minimum height.
    auto* sweep = new QWidget(this);
    sweep->setObjectName(QStringLiteral("sweepSection"));
    auto* sweepLayout = new QVBoxLayout(sweep);
    sweepLayout->addWidget(mChart, 1);
    sweepLayout->addWidget(mLegendLabel);
    sweepLayout->addWidget(mCurrentLabel);
    sweepLayout->addLayout(runRow);
    sweepLayout->addWidget(mProgress);
    sweepLayout->addWidget(mStatusLabel);
    sweepLayout->addLayout(fileRow);
    mFeelPanel = new FeelPanel(this);
    mTabs = new QTabWidget(this);
    mTabs->setObjectName(QStringLiteral("chartsTabs"));
    mTabs->setDocumentMode(true);
    mTabs->addTab(sweep, QString());
    mTabs->addTab(mFeelPanel, QString());
    mStiffeningPanel = new StiffeningPanel(this);
    mStiffeningPanel->setObjectName(QStringLiteral("stiffeningSection"));
    mTabs->addTab(mStiffeningPanel, QString());
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(mTabs);

    retranslateUi();
    updateShapeCombo();
    updateButtons();
}

ChartsPanel::~ChartsPanel() {
    if (mThread) {
        mCancel.store(true);
        mThread->wait();
        handOffAcquire();  // the sweep's last act was its hand-off (results/HandOff.h)
        delete mThread;
    }
}

const std::vector<SweepPoint>& ChartsPanel::points() const { return mChart->points(); }

void ChartsPanel::retranslateUi() {
    mRunButton->setText(tr("&Run sweep"));
    mRunButton->setToolTip(tr("Measure every model's tick cost and its displacement error against the flat punch "
                              "(slopes calibrated for the tissue and tool in use). Runs in the background; the full "
                              "sweep (both shapes, four sizes, 1 to 8 rings and the paper's methods) takes seconds."));
    mQuickCheck->setText(tr("&Quick"));
    mQuickCheck->setToolTip(tr("Sphere only, at 1442 and 3970 vertices, up to 4 rings: about a second (against the "
                               "organ's FEM: the stomach at 1442 vertices, about half a minute)."));
    mReferenceCombo->setItemText(0, tr("vs. punch"));
    mReferenceCombo->setItemText(1, tr("vs. organ FEM"));
    mReferenceCombo->setToolTip(tr("What Run sweep scores against: the flat punch on a half-space, or the FEM of the filled "
                                   "stomach (linear and hyperelastic) at its thin, thick and curved sites."));
    mCancelButton->setText(tr("&Cancel"));
    mCancelButton->setToolTip(tr("Stop after the model being measured; the points measured so far are shown."));
    mOpenButton->setText(tr("&Open CSV…"));
    mOpenButton->setToolTip(tr("Show a sweep saved as CSV (palpate-cli sweep --csv, or Save CSV here)."));
    mSaveButton->setText(tr("S&ave CSV…"));
    mSaveButton->setToolTip(tr("Write the points shown as CSV (and the tissue as JSON next to it)."));
    mShapeLabel->setText(tr("Sha&pe:"));
    mShapeCombo->setToolTip(tr("The shape whose points are drawn (each shape has its own Pareto front)."));
    mChart->setEmptyHint(tr("No sweep loaded: press Run sweep"));
    mProgress->setFormat(tr("%p %"));
    mTabs->setTabText(0, tr("&Speed vs. accuracy"));
    mTabs->setTabToolTip(0, tr("Every model's tick cost against its displacement error (the sweep)."));
    mTabs->setTabText(1, tr("&Feel"));
    mTabs->setTabToolTip(1, tr("Every model's largest force step while sliding at constant depth, against its tick cost "
                               "(palpate-cli bench feel)."));
    mTabs->setTabText(2, tr("S&tiffening"));
    mTabs->setTabToolTip(2, tr("The tissue's force against depth: the hyperelastic reference beside the linear model and "
                               "the model with stiffening knots."));
    for (int i = 0; i < mShapeCombo->count(); ++i) {
        const QStringList data = mShapeCombo->itemData(i).toStringList();
        mShapeCombo->setItemText(i, shapeItemText(GeneratedShape(data.value(0).toInt()), data.value(1).toStdString()));
    }
    updateHighlight();
}

void ChartsPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void ChartsPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    // In a dock, "shown" includes a tab behind another: wait until the dock says it can be seen.
    if (auto* dock = qobject_cast<QDockWidget*>(parentWidget())) {
        if (!mWatchingDock) {
            mWatchingDock = true;
            connect(dock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
                if (visible) loadDefaultCsvOnce();
            });
        }
        return;
    }
    loadDefaultCsvOnce();
}

void ChartsPanel::loadDefaultCsvOnce() {
    if (mDefaultTried) return;
    mDefaultTried = true;
    mFeelPanel->loadDefaultCsvOnce();
    if (!mDefaultCsv.isEmpty() && points().empty() && !isRunning() && QFileInfo::exists(mDefaultCsv)) loadCsv(mDefaultCsv);
}

void ChartsPanel::setCurrentConfiguration(const TissuePreset& applied, const ToolContact& contact, std::size_t meshVertices) {
    mApplied = applied;
    mContact = contact;
    mMeshVertices = meshVertices;
    mStiffeningPanel->setTissue(contact, applied.model.slopeRing);
    updateHighlight();
}

void ChartsPanel::updateHighlight() {
    // Slope-ring methods are charted per ring count; every other model is one series by its name.
    const std::string series = mApplied.model.kind == ModelKind::SlopeRing
                                   ? sweepSeriesName(mApplied.model.slopeRingMethod, mApplied.model.slopeRing.ringCount)
                                   : presetModelName(mApplied);
    // A stored sweep of another tissue says nothing of this one: nothing of it is "in use".
    const bool otherTissue = mShownContact && !points().empty() && !sameToolContact(*mShownContact, mContact);
    mChart->setHighlight(otherTissue ? std::string() : series, otherTissue ? 0 : mMeshVertices);
    const QString name = series.empty() ? tr("%1 with %2 rings")
                                              .arg(QString::fromLatin1(methodName(mApplied.model.slopeRingMethod).data(),
                                                                       qsizetype(methodName(mApplied.model.slopeRingMethod).size())))
                                              .arg(mApplied.model.slopeRing.ringCount)
                                        : QString::fromStdString(series);
    const QLocale l = locale();
    const auto kPa = [&l](const ToolContact& c) {
        return l.toString(c.material.youngsModulusNPerMm2 * 1000.0, 'g', 3);
    };
    QString text;
    if (mMeshVertices == 0)
        text = tr("In use: %1 (no mesh loaded)").arg(name);
    else if (otherTissue)
        text = tr("In use: %1 on %2 vertices, tissue E = %3 kPa, ν = %4. The chart shows a stored sweep of another "
                  "tissue (E = %5 kPa, ν = %6), not this one: press Run sweep to measure it.")
                   .arg(name)
                   .arg(mMeshVertices)
                   .arg(kPa(mContact), l.toString(mContact.material.poissonRatio, 'g', 3), kPa(*mShownContact),
                        l.toString(mShownContact->material.poissonRatio, 'g', 3));
    else if (mChart->highlightMarkCount() > 0)
        text = tr("In use: %1 on %2 vertices; ringed in magenta: the sweep's point of that model and size (on "
                  "its generated shape, not necessarily this mesh)")
                   .arg(name)
                   .arg(mMeshVertices);
    else if (points().empty())
        text = tr("In use: %1 on %2 vertices").arg(name).arg(mMeshVertices);
    else
        text = tr("In use: %1 on %2 vertices (not measured in this sweep)").arg(name).arg(mMeshVertices);
    mCurrentLabel->setText(text);
}

SweepDef ChartsPanel::sweepDefinition() const {
    SweepDef def;
    def.contact = mContact;
    def.base = mApplied.model.slopeRing;
    if (mQuickCheck->isChecked()) {
        def.shapes = {GeneratedShape::Sphere};
        def.sizes = {1442, 3970};
        def.maxRings = 4;
        def.timingRepeats = 1;
        def.minMeasureMs = 2.0;
    }
    return def;
}

void ChartsPanel::runSweep() {
    if (mReferenceCombo->currentData().toString() == QLatin1String("fem")) {
        OrganSweepDef organ;
        organ.sweep = sweepDefinition();
        if (mQuickCheck->isChecked()) organ.sizes = {1442};
        startOrganSweep(organ);
    } else {
        startSweep(sweepDefinition());
    }
}

bool ChartsPanel::startSweep(const SweepDef& requested) {
    return startWorker(requested, [](const SweepDef& def) { return palpate::runSweep(def); });
}

bool ChartsPanel::startOrganSweep(const OrganSweepDef& requested) {
    return startWorker(requested.sweep, [requested](const SweepDef& def) {
        OrganSweepDef organ = requested;
        organ.sweep = def;  // with the panel's progress and cancel
        return runOrganSweep(organ).sweep;
    });
}

bool ChartsPanel::startWorker(const SweepDef& requested, std::function<SweepResult(const SweepDef&)> run) {
    if (mThread) return false;
    mCancel.store(false);
    mRunningDef = requested;
    SweepDef def = requested;
    def.cancel = &mCancel;
    // Called on the worker thread: the text goes to the panel's thread as a queued call.
    def.progress = [this](double fraction, const std::string& line) {
        handOffTo(this, [this, fraction, text = QString::fromStdString(line)] { onProgress(fraction, text); });
    };
    mThread = QThread::create([this, def, run = std::move(run)] {
        SweepResult result;
        QString error;
        try {
            result = run(def);
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        handOffTo(this, [this, result = std::move(result), error] { onFinished(result, error); });
    });
    mThread->setObjectName(QStringLiteral("sweep"));
    mRunClock.start();
    mProgress->setValue(0);
    setStatus(tr("Sweep started: building the first mesh…"));
    mThread->start(QThread::LowPriority);  // the haptic thread and the GUI come first
    updateButtons();
    return true;
}

void ChartsPanel::cancelSweep() {
    if (!mThread) return;
    mCancel.store(true);
    setStatus(tr("Cancelling: the model being measured finishes first…"));
    mCancelButton->setEnabled(false);
}

void ChartsPanel::onProgress(double fraction, const QString& line) {
    if (!mThread) return;
    mProgress->setValue(int(fraction * kProgressSteps + 0.5));
    if (!mCancel.load()) setStatus(line);
}

void ChartsPanel::onFinished(const SweepResult& result, const QString& error) {
    if (mThread) {
        mThread->wait();  // it posted this as its last act
        delete mThread;
        mThread = nullptr;
    }
    const double seconds = double(mRunClock.elapsed()) / 1000.0;
    if (!error.isEmpty()) {
        setStatus(tr("Sweep failed: %1").arg(error), true);
        updateButtons();
        emit sweepFailed(error);
        return;
    }
    const int count = int(result.points.size());
    if (count > 0) {
        mShownFromRun = true;
        showPoints(result.points, mRunningDef.contact);
    }
    mProgress->setValue(result.cancelled ? mProgress->value() : kProgressSteps);
    if (result.cancelled)
        setStatus(count > 0 ? tr("Cancelled after %1 (%2 s); the chart shows them.")
                                  .arg(pointsText(count), QLocale().toString(seconds, 'f', 1))
                            : tr("Cancelled before the first point; the chart is unchanged."));
    else
        setStatus(tr("Sweep done: %1 in %2 s.").arg(pointsText(count), QLocale().toString(seconds, 'f', 1)));
    updateButtons();
    emit sweepFinished(result.cancelled, count);
}

void ChartsPanel::showPoints(std::vector<SweepPoint> points, const std::optional<ToolContact>& contact) {
    mShownContact = contact;
    mChart->setToolContact(contact);
    mChart->setPoints(std::move(points));
    updateShapeCombo();
    updateHighlight();
    updateButtons();
}

QString ChartsPanel::shapeItemText(GeneratedShape shape, const std::string& site) {
    if (site.empty()) return SpeedAccuracyChart::shapeTitle(shape);
    //: The shape and the site of the organ sweep: "Stomach, thin site"
    return tr("%1, %2 site").arg(SpeedAccuracyChart::shapeTitle(shape), QString::fromStdString(site));
}

void ChartsPanel::updateShapeCombo() {
    const QSignalBlocker block(mShapeCombo);
    mShapeCombo->clear();
    // One entry per shape, and per site of the organ sweep (each has its own front).
    for (GeneratedShape shape : mChart->shapesPresent())
        for (const std::string& site : mChart->sitesPresent(shape))
            mShapeCombo->addItem(shapeItemText(shape, site), QStringList{QString::number(int(shape)), QString::fromStdString(site)});
    const int shown = mShapeCombo->findData(
        QStringList{QString::number(int(mChart->shownShape())), QString::fromStdString(mChart->shownSite())});
    mShapeCombo->setCurrentIndex(shown);
    mShapeCombo->setEnabled(mShapeCombo->count() > 1);
}

void ChartsPanel::updateButtons() {
    const bool running = isRunning();
    mRunButton->setEnabled(!running);
    mQuickCheck->setEnabled(!running);
    mReferenceCombo->setEnabled(!running);
    mCancelButton->setEnabled(running && !mCancel.load());
    mOpenButton->setEnabled(!running);
    mSaveButton->setEnabled(!running && !points().empty());
    mProgress->setVisible(running || mProgress->value() > 0);
}

void ChartsPanel::setStatus(const QString& text, bool problem) {
    mStatusLabel->setText(text);
    mStatusLabel->setStyleSheet(problem ? QStringLiteral("color: #c62828;") : QString());
}

QString ChartsPanel::statusText() const { return mStatusLabel->text(); }

bool ChartsPanel::loadCsv(const QString& path, QString* error) {
    auto fail = [&](const QString& message) {
        setStatus(message, true);
        if (error) *error = message;
        return false;
    };
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(tr("%1: cannot be read (%2)").arg(QDir::toNativeSeparators(path), file.errorString()));
    std::string problem;
    std::vector<SweepPoint> parsed = parseSweepCsv(file.readAll().toStdString(), &problem);
    if (!problem.empty()) return fail(QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), QString::fromStdString(problem)));
    if (parsed.empty()) return fail(tr("%1: no points (only the header)").arg(QDir::toNativeSeparators(path)));
    const int count = int(parsed.size());
    mShownFromRun = false;
    mProgress->setValue(0);
    showPoints(std::move(parsed), readSidecarContact(path));
    mLastDirectory = QFileInfo(path).absolutePath();
    setStatus(tr("Loaded %1 (%2).").arg(QDir::toNativeSeparators(path), pointsText(count)));
    if (error) error->clear();
    return true;
}

bool ChartsPanel::saveCsv(const QString& path, QString* error) {
    auto fail = [&](const QString& message) {
        setStatus(message, true);
        if (error) *error = message;
        return false;
    };
    if (points().empty()) return fail(tr("%1: not saved, there are no points").arg(QDir::toNativeSeparators(path)));
    auto write = [](const QString& target, const std::string& text, QString& why) {
        QSaveFile out(target);  // atomic: a failed write leaves the old file
        if (!out.open(QIODevice::WriteOnly) || out.write(text.data(), qint64(text.size())) != qint64(text.size()) ||
            !out.commit()) {
            why = out.errorString();
            return false;
        }
        return true;
    };
    // The sweep's description goes beside the CSV (FILE.json): a file of that name that is not one
    // (a preset, an exercise) is not the user's to lose for a CSV they chose to replace.
    if (mShownContact && QFileInfo::exists(sidecarJson(path)) && !readSidecarContact(path))
        return fail(tr("%1: not saved, %2 exists and is not a sweep's description (it would be replaced); choose "
                       "another name")
                        .arg(QDir::toNativeSeparators(path), QDir::toNativeSeparators(sidecarJson(path))));
    QString why;
    if (!write(path, sweepToCsv(points()), why))
        return fail(tr("%1: cannot be written (%2)").arg(QDir::toNativeSeparators(path), why));
    if (mShownContact) {
        SweepDef def = mShownFromRun ? mRunningDef : SweepDef{};
        def.contact = *mShownContact;
        SweepResult result;
        result.points = points();
        if (!write(sidecarJson(path), sweepToJson(result, def), why))
            return fail(tr("%1: cannot be written (%2)").arg(QDir::toNativeSeparators(sidecarJson(path)), why));
    }
    mLastDirectory = QFileInfo(path).absolutePath();
    setStatus(tr("Saved %1.").arg(QDir::toNativeSeparators(path)));
    if (error) error->clear();
    return true;
}

void ChartsPanel::openCsvDialog() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open sweep CSV"), mLastDirectory, tr("Sweep CSV (*.csv);;All files (*)"));
    if (!path.isEmpty()) loadCsv(path);
}

void ChartsPanel::saveCsvDialog() {
    const QString start = QDir(mLastDirectory.isEmpty() ? QDir::currentPath() : mLastDirectory).filePath(QStringLiteral("sweep.csv"));
    QString path = QFileDialog::getSaveFileName(this, tr("Save sweep CSV"), start, tr("Sweep CSV (*.csv);;All files (*)"));
    path = withSuffixConfirmed(this, path, QStringLiteral(".csv"));
    if (path.isEmpty()) return;
    saveCsv(path);
}

}  // namespace palpate
