#include "widgets/FeelPanel.h"

#include "report/FeelChart.h"
#include "engine/bench/FeelCsv.h"

#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace palpate {

FeelPanel::FeelPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("feelPanel"));
    mChart = new FeelChart(this);
    mChart->setMinimumSize(360, 260);
    mChart->setFrameShape(QFrame::NoFrame);
    mChart->setLegendShown(false);  // the legend under the chart wraps; the chart's own takes the plot's width
    mLegendLabel = new QLabel(this);
    mLegendLabel->setObjectName(QStringLiteral("feelLegendLabel"));
    mLegendLabel->setWordWrap(true);
    mLegendLabel->setTextFormat(Qt::RichText);
    mLegendLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mLegendLabel->setVisible(false);
    connect(mChart, &FeelChart::rebuilt, this, [this] {
        mLegendLabel->setText(mChart->legendHtml());
        mLegendLabel->setVisible(mChart->pointCount() > 0);
    });

    mAxisLabel = new QLabel(this);
    mAxisCombo = new QComboBox(this);
    mAxisCombo->setObjectName(QStringLiteral("feelAxisCombo"));
    mAxisLabel->setBuddy(mAxisCombo);
    mAxisCombo->addItem(QString(), int(FeelChart::XAxis::RatioToPrevious));
    mAxisCombo->addItem(QString(), int(FeelChart::XAxis::TickMicroseconds));
    connect(mAxisCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index >= 0) mChart->setXAxis(FeelChart::XAxis(mAxisCombo->itemData(index).toInt()));
    });
    mOpenButton = new QPushButton(this);
    mOpenButton->setObjectName(QStringLiteral("openFeelCsvButton"));
    connect(mOpenButton, &QPushButton::clicked, this, &FeelPanel::openCsvDialog);
    mStatusLabel = new QLabel(this);
    mStatusLabel->setObjectName(QStringLiteral("feelStatusLabel"));
    mStatusLabel->setWordWrap(true);
    mStatusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* row = new QHBoxLayout;
    row->addWidget(mOpenButton);
    row->addStretch(1);
    row->addWidget(mAxisLabel);
    row->addWidget(mAxisCombo);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(mChart, 1);
    layout->addWidget(mLegendLabel);
    layout->addLayout(row);
    layout->addWidget(mStatusLabel);
    retranslateUi();
}

const std::vector<FeelRow>& FeelPanel::rows() const { return mChart->rows(); }

void FeelPanel::retranslateUi() {
    mChart->setEmptyHint(tr("No feel bench loaded: palpate-cli bench feel --csv FILE, then Open feel CSV"));
    mOpenButton->setText(tr("&Open feel CSV…"));
    mOpenButton->setToolTip(
        tr("Show a feel bench saved as CSV (palpate-cli bench feel --csv): every model's largest "
           "force step while sliding at constant depth, against its tick cost."));
    mAxisLabel->setText(tr("Tick &cost:"));
    mAxisCombo->setItemText(0, tr("× previous"));
    mAxisCombo->setItemText(1, tr("µs"));
    mAxisCombo->setToolTip(
        tr("The tick cost as a fraction of the paper's previous method's, measured in the same run "
           "on the same mesh, or in microseconds on the machine that ran the bench."));
    if (!mShownPath.isEmpty()) setStatus(summaryText());
}

void FeelPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void FeelPanel::loadDefaultCsvOnce() {
    if (mDefaultTried) return;
    mDefaultTried = true;
    if (!mDefaultCsv.isEmpty() && rows().empty() && QFileInfo::exists(mDefaultCsv)) loadCsv(mDefaultCsv);
}

QString FeelPanel::summaryText() const {
    return tr("Loaded %1: %2 of %3 points above the goal (step ≤ %4 % of the mean force).")
        .arg(QDir::toNativeSeparators(mShownPath))
        .arg(mChart->pointsAboveGoal())
        .arg(mChart->pointCount())
        .arg(QLocale().toString(kFeelStepGoalPct, 'g', 3));
}

bool FeelPanel::loadCsv(const QString& path, QString* error) {
    auto fail = [&](const QString& message) {
        setStatus(message, true);
        if (error) *error = message;
        return false;
    };
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(tr("%1: cannot be read (%2)").arg(QDir::toNativeSeparators(path), file.errorString()));
    std::string problem;
    std::vector<FeelRow> parsed = parseFeelCsv(file.readAll().toStdString(), &problem);
    if (!problem.empty())
        return fail(QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), QString::fromStdString(problem)));
    if (parsed.empty()) return fail(tr("%1: no rows (only the header)").arg(QDir::toNativeSeparators(path)));
    mChart->setRows(std::move(parsed));
    mShownPath = path;
    mLastDirectory = QFileInfo(path).absolutePath();
    setStatus(summaryText());
    if (error) error->clear();
    return true;
}

void FeelPanel::openCsvDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open feel CSV"), mLastDirectory,
                                                      tr("Feel bench CSV (*.csv);;All files (*)"));
    if (!path.isEmpty()) loadCsv(path);
}

void FeelPanel::setStatus(const QString& text, bool problem) {
    mStatusLabel->setText(text);
    mStatusLabel->setStyleSheet(problem ? QStringLiteral("color: #c62828;") : QString());
}

QString FeelPanel::statusText() const { return mStatusLabel->text(); }

}  // namespace palpate
