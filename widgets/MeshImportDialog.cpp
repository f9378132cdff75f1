#include "widgets/MeshImportDialog.h"

#include "results/HandOff.h"

#include "widgets/MeshSizeText.h"
#include "widgets/SaveFileChoice.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDeadlineTimer>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTextBrowser>
#include <QShowEvent>
#include <QThread>
#include <QVBoxLayout>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>

namespace palpate {

namespace {

// The units the combo box names, in its order; the last entry is "Scale…" (a factor).
constexpr const char* kNamedUnits[] = {"mm", "cm", "m", "in"};
constexpr int kScaleIndex = 4;

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Errors red, the faults that are only reported amber: the colours the window's warnings use.
const char* const kErrorColour = "#c62828";
const char* const kWarningColour = "#a86400";

QString htmlList(const std::vector<std::string>& lines, const char* colour) {
    QString html;
    for (const std::string& line : lines)
        html += QStringLiteral("<li style=\"color:%1\">%2</li>").arg(QLatin1String(colour), qs(line).toHtmlEscaped());
    return html;
}

QString plainList(const std::vector<std::string>& lines) {
    QString text;
    for (const std::string& line : lines) text += QStringLiteral("<li>%1</li>").arg(qs(line).toHtmlEscaped());
    return text;
}

}  // namespace

struct MeshImportDialog::Job {
    std::string path;
    MeshImportDef def;
    std::atomic<bool> cancel{false};
    MeshImportResult result;
    // The worker's own: the last progress it posted (to post only what changes).
    int postedPercent = -1;
    std::string postedStage;
};

MeshImportDialog::MeshImportDialog(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Import Mesh"));
    setObjectName(QStringLiteral("meshImportDialog"));
    buildUi();
    mDebounce.setSingleShot(true);
    mDebounce.setInterval(kDebounceMs);
    connect(&mDebounce, &QTimer::timeout, this, &MeshImportDialog::startPreview);
    showIdle(tr("Choose a mesh file to preview."));
}

MeshImportDialog::~MeshImportDialog() {
    if (mJob) mJob->cancel = true;
    joinWorker();
}

void MeshImportDialog::buildUi() {
    auto* layout = new QVBoxLayout(this);

    layout->addLayout(buildOptionsForm());

    auto* progressRow = new QHBoxLayout;
    mProgress = new QProgressBar(this);
    mProgress->setObjectName(QStringLiteral("importProgress"));
    mProgress->setRange(0, 100);
    mStage = new QLabel(this);
    mStage->setObjectName(QStringLiteral("importStage"));
    mCancel = new QPushButton(tr("Cancel Preview"), this);
    mCancel->setObjectName(QStringLiteral("importCancel"));
    progressRow->addWidget(mProgress, 1);
    progressRow->addWidget(mStage);
    progressRow->addWidget(mCancel);
    layout->addLayout(progressRow);

    layout->addWidget(buildPreview(), 1);

    auto* buttons = new QDialogButtonBox(this);
    mImport = buttons->addButton(tr("Import…"), QDialogButtonBox::AcceptRole);
    mImport->setObjectName(QStringLiteral("importButton"));
    mImport->setToolTip(tr("Write the previewed mesh (in mm) to a new file and open it"));
    buttons->addButton(QDialogButtonBox::Close);
    layout->addWidget(buttons);

    connectOptions();
    connect(mCancel, &QPushButton::clicked, this, &MeshImportDialog::cancelPreview);
    connect(mImport, &QPushButton::clicked, this, &MeshImportDialog::chooseOutput);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // Closed, the dialog stays (the window keeps it): a preview running on stops, not to take the
    // haptic loop's cores for nothing.
    connect(this, &QDialog::finished, this, &MeshImportDialog::cancelPreview);
    mKeep->setEnabled(false);  // the repair's and the remeshing's own options wait for them
    mFillHoles->setEnabled(false);
    mEdge->setEnabled(false);
    updateEnabled();
}

QFormLayout* MeshImportDialog::buildOptionsForm() {
    auto* form = new QFormLayout;
    auto* inputRow = new QHBoxLayout;
    mInput = new QLineEdit(this);
    mInput->setObjectName(QStringLiteral("importInput"));
    mInput->setPlaceholderText(tr("A mesh from another tool (OBJ, OFF, PLY, STL, OM)"));
    auto* browse = new QPushButton(tr("Browse…"), this);
    browse->setObjectName(QStringLiteral("importBrowse"));
    inputRow->addWidget(mInput, 1);
    inputRow->addWidget(browse);
    form->addRow(tr("File:"), inputRow);

    auto* unitRow = new QHBoxLayout;
    mUnitCombo = new QComboBox(this);
    mUnitCombo->setObjectName(QStringLiteral("importUnit"));
    mUnitCombo->addItems({tr("mm"), tr("cm"), tr("m"), tr("in"), tr("Scale…")});
    mScale = new QDoubleSpinBox(this);
    mScale->setObjectName(QStringLiteral("importScale"));
    mScale->setDecimals(6);
    mScale->setRange(kMinMmPerUnit, kMaxMmPerUnit);
    mScale->setValue(1.0);
    mScale->setSuffix(tr(" mm per file unit"));
    mScale->setEnabled(false);
    mReason = new QLabel(this);
    mReason->setObjectName(QStringLiteral("importUnitReason"));
    mReason->setWordWrap(true);
    unitRow->addWidget(mUnitCombo);
    unitRow->addWidget(mScale);
    unitRow->addWidget(mReason, 1);
    form->addRow(tr("Unit of the file:"), unitRow);

    auto* repairRow = new QHBoxLayout;
    mRepair = new QCheckBox(tr("Repair faults"), this);
    mRepair->setObjectName(QStringLiteral("importRepair"));
    mRepair->setToolTip(
        tr("Orient the faces consistently, split non-manifold edges and vertices, remove degenerate "
           "triangles and duplicate vertices (CGAL). Without it a mesh with faults is refused."));
    mKeep = new QComboBox(this);
    mKeep->setObjectName(QStringLiteral("importKeep"));
    mKeep->addItems({tr("Keep the largest piece"), tr("Keep all pieces")});
    mFillHoles = new QCheckBox(tr("Fill holes"), this);
    mFillHoles->setObjectName(QStringLiteral("importFillHoles"));
    mFillHoles->setChecked(MeshImportDef{}.fillHoles);
    repairRow->addWidget(mRepair);
    repairRow->addWidget(mKeep);
    repairRow->addWidget(mFillHoles);
    repairRow->addStretch(1);
    form->addRow(tr("Repair:"), repairRow);

    auto* remeshRow = new QHBoxLayout;
    mRemesh = new QCheckBox(tr("Remesh to even triangles, edge"), this);
    mRemesh->setObjectName(QStringLiteral("importRemesh"));
    mRemesh->setToolTip(tr("Isotropic remeshing: even triangles make the slope model's rings round"));
    mEdge = new QDoubleSpinBox(this);
    mEdge->setObjectName(QStringLiteral("importEdge"));
    mEdge->setDecimals(2);
    mEdge->setRange(kMinRemeshEdgeMm, 1000.0);
    mEdge->setSingleStep(0.1);
    mEdge->setValue(1.0);
    mEdge->setSuffix(tr(" mm"));
    remeshRow->addWidget(mRemesh);
    remeshRow->addWidget(mEdge);
    remeshRow->addStretch(1);
    form->addRow(tr("Remesh:"), remeshRow);
    connect(browse, &QPushButton::clicked, this, &MeshImportDialog::browse);
    return form;
}

QGroupBox* MeshImportDialog::buildPreview() {
    auto* preview = new QGroupBox(tr("Preview"), this);
    auto* previewLayout = new QVBoxLayout(preview);
    mSize = new QLabel(preview);
    mSize->setObjectName(QStringLiteral("importSize"));
    mSize->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont big = mSize->font();
    big.setBold(true);
    mSize->setFont(big);
    mCounts = new QLabel(preview);
    mCounts->setObjectName(QStringLiteral("importCounts"));
    mCounts->setWordWrap(true);
    auto* details = new QHBoxLayout;
    mReport = new QTextBrowser(preview);
    mReport->setObjectName(QStringLiteral("importReport"));
    mReport->setMinimumHeight(120);
    mRoundness = new QTableWidget(preview);
    mRoundness->setObjectName(QStringLiteral("importRoundness"));
    mRoundness->setColumnCount(2);
    mRoundness->setHorizontalHeaderLabels({tr("Before"), tr("After")});
    mRoundness->setEditTriggers(QAbstractItemView::NoEditTriggers);
    mRoundness->setSelectionMode(QAbstractItemView::NoSelection);
    mRoundness->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    mRoundness->setToolTip(
        tr("Ring roundness: the spread of the distances to ring k's vertices (coefficient of "
           "variation; 0 is a circle, a regular mesh gives about 0.1 at ring 2), and the spread "
           "of the edge lengths"));
    mRoundness->setMinimumWidth(220);
    mRoundness->setMaximumWidth(300);
    auto* roundnessBox = new QVBoxLayout;
    roundnessBox->addWidget(new QLabel(tr("Ring roundness (CV)"), preview));
    roundnessBox->addWidget(mRoundness, 1);
    details->addWidget(mReport, 1);
    details->addLayout(roundnessBox);
    previewLayout->addWidget(mSize);
    previewLayout->addWidget(mCounts);
    previewLayout->addLayout(details, 1);
    return preview;
}

void MeshImportDialog::connectOptions() {
    connect(mInput, &QLineEdit::textEdited, this, [this] {
        // Another file: its own size decides the unit again.
        mSuggestion.reset();
        mUnitChosen = false;
        mEdgeEdited = false;
        mSettingUp = true;
        setUnit(kMillimetres);
        mSettingUp = false;
        optionsChanged();
    });
    connect(mUnitCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        mScale->setEnabled(index == kScaleIndex);
        if (index >= 0 && index < kScaleIndex) {
            std::string ignored;
            const bool wasSettingUp = mSettingUp;
            mSettingUp = true;
            mScale->setValue(parseMeshUnit(kNamedUnits[index], ignored).value_or(kMillimetres).mmPerUnit);
            mSettingUp = wasSettingUp;
        }
        if (!mSettingUp) mUnitChosen = true;
        optionsChanged();
    });
    connect(mScale, &QDoubleSpinBox::valueChanged, this, [this] {
        if (mUnitCombo->currentIndex() == kScaleIndex) optionsChanged();
    });
    for (QCheckBox* box : {mRepair, mFillHoles, mRemesh})
        connect(box, &QCheckBox::toggled, this, &MeshImportDialog::optionsChanged);
    connect(mKeep, &QComboBox::currentIndexChanged, this, &MeshImportDialog::optionsChanged);
    connect(mEdge, &QDoubleSpinBox::valueChanged, this, [this] {
        if (!mSettingUp) mEdgeEdited = true;
        if (mRemesh->isChecked()) optionsChanged();
    });
}

void MeshImportDialog::setInputPath(const QString& path) {
    mSettingUp = true;
    mInput->setText(QDir::toNativeSeparators(path));
    setUnit(kMillimetres);
    mSettingUp = false;
    mSuggestion.reset();
    mUnitChosen = false;
    mEdgeEdited = false;
    mDebounce.stop();
    startPreview();
}

QString MeshImportDialog::inputPath() const { return QDir::fromNativeSeparators(mInput->text().trimmed()); }

void MeshImportDialog::setUnit(const MeshUnit& unit) {
    int index = kScaleIndex;
    for (int i = 0; i < kScaleIndex; ++i)
        if (unit.name == kNamedUnits[i]) index = i;
    const bool wasSettingUp = mSettingUp;
    mSettingUp = true;
    mScale->setValue(unit.mmPerUnit);  // a named unit's factor shown too: Scale… starts from it
    mUnitCombo->setCurrentIndex(index);
    mScale->setEnabled(index == kScaleIndex);
    mSettingUp = wasSettingUp;
    if (!mSettingUp) {
        mUnitChosen = true;
        optionsChanged();
    }
}

MeshUnit MeshImportDialog::unit() const {
    const int index = mUnitCombo->currentIndex();
    const std::string text = index >= 0 && index < kScaleIndex
                                 ? std::string(kNamedUnits[index])
                                 : QString::number(mScale->value(), 'g', 17).toStdString();
    std::string error;
    return parseMeshUnit(text, error).value_or(kMillimetres);  // the spin box's range is parseMeshUnit's
}

MeshImportDef MeshImportDialog::options() const {
    MeshImportDef def;
    def.unit = unit();
    def.repair = mRepair->isChecked();
    def.keep = mKeep->currentIndex() == 1 ? KeepComponents::All : KeepComponents::Largest;
    def.fillHoles = mFillHoles->isChecked();
    def.remeshEdgeMm = mRemesh->isChecked() ? mEdge->value() : 0.0;
    return def;
}

bool MeshImportDialog::previewBusy() const { return mJob != nullptr || mDebounce.isActive() || mRerun; }

bool MeshImportDialog::waitForPreview(int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    while (previewBusy()) {
        if (deadline.hasExpired()) return false;
        QApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(5);
    }
    return true;
}

QString MeshImportDialog::sizeText() const { return mSize->text(); }
QString MeshImportDialog::reasonText() const { return mReason->text(); }
bool MeshImportDialog::importEnabled() const { return mImport->isEnabled(); }

QString MeshImportDialog::previewText() const {
    QStringList rows;
    for (int r = 0; r < mRoundness->rowCount(); ++r) {
        QStringList cells{mRoundness->verticalHeaderItem(r) ? mRoundness->verticalHeaderItem(r)->text() : QString()};
        for (int c = 0; c < mRoundness->columnCount(); ++c)
            cells << (mRoundness->item(r, c) ? mRoundness->item(r, c)->text() : QString());
        rows << cells.join(QLatin1Char('\t'));
    }
    return QStringList{mSize->text(), mCounts->text(), mReport->toPlainText(), rows.join(QLatin1Char('\n'))}.join(
        QLatin1Char('\n'));
}

void MeshImportDialog::browse() {
    const QString start = inputPath().isEmpty() ? QString() : QFileInfo(inputPath()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Mesh"), start,
                                                      tr("Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)"));
    if (!path.isEmpty()) setInputPath(path);
}

QString MeshImportDialog::defaultOutputPath() const {
    const QFileInfo in(inputPath());
    if (inputPath().isEmpty()) return {};
    return in.absoluteDir().filePath(in.completeBaseName() + QStringLiteral("-imported.off"));
}

void MeshImportDialog::chooseOutput() {
    QString path = QFileDialog::getSaveFileName(this, tr("Import Mesh As"), defaultOutputPath(),
                                                tr("Meshes (*.off *.obj *.ply *.stl *.om)"));
    if (path.isEmpty()) return;
    path = withSuffixConfirmed(this, path, QStringLiteral(".off"));
    if (path.isEmpty()) return;
    if (const QString error = importTo(path); !error.isEmpty()) QMessageBox::warning(this, tr("Cannot import"), error);
}

QString MeshImportDialog::importTo(const QString& outputPath) {
    if (outputPath.isEmpty()) return tr("Choose a file for the imported mesh.");
    if (previewBusy()) return tr("The preview is not finished yet: wait for it, then import.");
    if (!mResult || !mResult->mesh) {
        const QString why = mResult && !mResult->errors.empty() ? qs(mResult->errors.front()) : tr("nothing previewed");
        return tr("There is no mesh to import: %1").arg(why);
    }
    // An input is never overwritten by an output (docs/reliability.md): the result over its own
    // source would lose the original, and with it every later re-import with other options.
    const QFileInfo out(outputPath), in(qs(mResult->source));
    const bool same = out.absoluteFilePath() == in.absoluteFilePath() ||
                      (out.exists() && in.exists() && out.canonicalFilePath() == in.canonicalFilePath());
    if (same)
        return tr("%1: is the mesh being imported; choose another file for the result")
            .arg(QDir::toNativeSeparators(outputPath));
    if (const std::string error = mResult->mesh->save(outputPath.toStdString()); !error.empty()) return qs(error);
    emit imported(outputPath);
    accept();
    return {};
}

void MeshImportDialog::optionsChanged() {
    if (mSettingUp) return;
    mKeep->setEnabled(mRepair->isChecked());
    mFillHoles->setEnabled(mRepair->isChecked());
    mEdge->setEnabled(mRemesh->isChecked());
    mDebounce.start();
    updateEnabled();
}

void MeshImportDialog::startPreview() {
    mDebounce.stop();
    if (mJob) {  // the running one is for other options: stop it, then run again
        mJob->cancel = true;
        mRerun = true;
        updateEnabled();
        return;
    }
    mRerun = false;
    const QString path = inputPath();
    if (path.isEmpty()) {
        mResult.reset();
        showIdle(tr("Choose a mesh file to preview."));
        updateEnabled();
        return;
    }
    joinWorker();
    auto job = std::make_shared<Job>();
    job->path = path.toStdString();
    job->def = options();
    mJob = job;
    mProgress->setValue(0);
    mStage->setText(tr("reading"));
    // The worker gets the job by value: once the dialog has joined it, nothing of the dialog is touched.
    // Results and progress reach the dialog as queued calls; those still queued when the dialog
    // is destroyed are discarded with it (the destructor joins the worker first).
    mWorker = std::thread([this, job] {
        ImportProgress progress = [this, job](double fraction, const std::string& stage) {
            const int percent = int(fraction * 100.0 + 0.5);
            if (percent != job->postedPercent || stage != job->postedStage) {
                job->postedPercent = percent;
                job->postedStage = stage;
                const QString stageText = qs(stage);
                handOffTo(this, [this, job, fraction, stageText] {
                    if (job == mJob && !job->cancel) showProgress(fraction, stageText);
                });
            }
            return !job->cancel.load();
        };
        try {  // no event loop catches it on this thread: it would end the process
            job->result = importMesh(job->path, job->def, progress);
        } catch (const std::exception& e) {
            job->result = MeshImportResult{};
            job->result.source = job->path;
            job->result.errors.push_back(job->path + ": " + e.what());
        }
        handOffTo(this, [this, job] { previewFinished(job); });
    });
    updateEnabled();
}

void MeshImportDialog::cancelPreview() {
    mDebounce.stop();
    mRerun = false;
    updateEnabled();
    if (!mJob) return;
    // The import stops at its next progress call; a remeshing pass can take a while to get there.
    mJob->cancel = true;
    mCancel->setEnabled(false);
    mStage->setText(tr("cancelling…"));
}

void MeshImportDialog::joinWorker() {
    if (mWorker.joinable()) mWorker.join();
}

void MeshImportDialog::previewFinished(std::shared_ptr<Job> job) {
    if (job != mJob) return;
    joinWorker();  // it posted this as its last act
    mJob.reset();
    if (mRerun) {  // stale: the options changed meanwhile
        startPreview();
        return;
    }
    const bool cancelled = job->cancel.load();
    mLastCancelled = cancelled;
    mResult = std::make_unique<MeshImportResult>(std::move(job->result));
    mProgress->setValue(cancelled ? 0 : 100);
    mStage->setText(cancelled ? tr("cancelled") : tr("done"));
    // The first preview of a file, read as mm: when that size is implausible, read it in the unit
    // that makes it plausible (docs/meshes.md, "Units"), and say why beside the unit.
    if (!cancelled && !mUnitChosen && mResult->suggestion) {
        mSuggestion = mResult->suggestion;
        mSettingUp = true;
        setUnit(mSuggestion->unit);
        mSettingUp = false;
        mUnitChosen = true;
        showResult();
        startPreview();
        return;
    }
    mUnitChosen = true;  // from here on the unit is the one shown (a new file resets it)
    // The remeshing edge follows the mesh's size until the user sets one.
    if (!cancelled && !mEdgeEdited && mResult->sizeMm != glm::dvec3(0.0)) {
        const double suggested = suggestedRemeshEdgeMm(mResult->sizeMm);
        if (std::abs(suggested - mEdge->value()) > 1e-9) {
            mSettingUp = true;
            mEdge->setValue(suggested);
            mSettingUp = false;
            if (mRemesh->isChecked()) {  // that preview ran with another edge
                showResult();
                startPreview();
                return;
            }
        }
    }
    showResult();
    updateEnabled();
}

void MeshImportDialog::showEvent(QShowEvent* event) {
    QDialog::showEvent(event);
    if (mLastCancelled && !previewBusy() && !inputPath().isEmpty()) startPreview();
}

void MeshImportDialog::showProgress(double fraction, const QString& stage) {
    mProgress->setValue(int(fraction * 100.0 + 0.5));
    mStage->setText(stage);
}

void MeshImportDialog::showIdle(const QString& message) {
    mSize->setText(message);
    mStage->clear();
    mProgress->setValue(0);
    mCounts->clear();
    mReport->clear();
    mReason->clear();
    mRoundness->setRowCount(0);
}

void MeshImportDialog::showResult() {
    const MeshImportResult& r = *mResult;
    // The size line: what the unit chosen makes of the file.
    QString size = meshSizeText(r.sizeMm);
    if (!r.unit.isMillimetres()) size = tr("%1 · file in %2").arg(size, qs(r.unit.text()));
    mSize->setText(r.sizeMm == glm::dvec3(0.0) && !r.ok() ? tr("Not read") : size);

    const std::optional<UnitSuggestion>& suggestion = r.suggestion ? r.suggestion : mSuggestion;
    if (suggestion) {
        const bool taken = suggestion->unit == r.unit;
        mReason->setText((taken ? tr("Suggested %1: %2") : tr("Try %1: %2"))
                             .arg(qs(suggestion->unit.text()), qs(suggestion->reason)));
        mReason->setStyleSheet(taken ? QString() : QStringLiteral("color:%1").arg(QLatin1String(kWarningColour)));
    } else {
        mReason->clear();
    }

    QString counts = tr("Source: %1 vertices, %2 polygons").arg(r.sourceVertices).arg(r.sourcePolygons);
    if (r.mesh)
        counts += tr(" · result: %1 vertices, %2 triangles").arg(r.mesh->vertexCount()).arg(r.mesh->triangleCount());
    mCounts->setText(counts);

    QString html;
    const auto section = [&html](const QString& title, const QString& items) {
        if (!items.isEmpty()) html += QStringLiteral("<p><b>%1</b></p><ul>%2</ul>").arg(title.toHtmlEscaped(), items);
    };
    section(tr("Errors"), htmlList(r.errors, kErrorColour));
    section(tr("Problems found"),
            htmlList(r.faults.errorTexts(), kErrorColour) + htmlList(r.faults.warningTexts(), kWarningColour));
    section(tr("Warnings"), htmlList(r.warnings, kWarningColour));
    section(tr("Changes made"), plainList(r.changes));
    section(tr("Tolerated while reading"), plainList(r.notes));
    if (html.isEmpty()) html = tr("<p>No problems found.</p>");
    mReport->setHtml(html);

    const int rings = std::max(r.roundnessBefore ? r.roundnessBefore->ringCount : 0,
                               r.roundnessAfter ? r.roundnessAfter->ringCount : 0);
    mRoundness->setRowCount(rings > 0 ? rings + 1 : 0);
    const auto cell = [this](int row, int column, const std::optional<RingRoundness>& roundness, double value) {
        auto* item = new QTableWidgetItem(roundness ? QString::number(value, 'f', 3) : QStringLiteral("—"));
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        mRoundness->setItem(row, column, item);
    };
    for (int k = 1; k <= rings; ++k) {
        mRoundness->setVerticalHeaderItem(k - 1, new QTableWidgetItem(tr("Ring %1").arg(k)));
        cell(k - 1, 0, r.roundnessBefore, r.roundnessBefore ? r.roundnessBefore->ringDistanceCv[k] : 0.0);
        cell(k - 1, 1, r.roundnessAfter, r.roundnessAfter ? r.roundnessAfter->ringDistanceCv[k] : 0.0);
    }
    if (rings > 0) {
        mRoundness->setVerticalHeaderItem(rings, new QTableWidgetItem(tr("Edge length")));
        cell(rings, 0, r.roundnessBefore, r.roundnessBefore ? r.roundnessBefore->edgeLengthCv : 0.0);
        cell(rings, 1, r.roundnessAfter, r.roundnessAfter ? r.roundnessAfter->edgeLengthCv : 0.0);
    }
}

void MeshImportDialog::updateEnabled() {
    const bool busy = previewBusy();
    mCancel->setEnabled((mJob != nullptr && !mJob->cancel) || mDebounce.isActive());
    mImport->setEnabled(!busy && mResult && mResult->mesh);
    if (busy && !mJob) mStage->setText(tr("waiting"));
}

}  // namespace palpate
