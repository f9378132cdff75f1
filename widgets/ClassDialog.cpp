#include "widgets/ClassDialog.h"

#include "results/HandOff.h"

#include "results/ResultsDatabase.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSaveFile>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>

namespace palpate {

ClassDialog::ClassDialog(const QString& localPath, const QString& serverUrl, const QString& examplesFolder, QWidget* parent)
    : QDialog(parent), mLocal(localPath), mServer(serverUrl), mExamples(examplesFolder) {
    setWindowTitle(tr("Class View"));
    mSource = new QComboBox(this);
    mSource->setObjectName(QStringLiteral("classSourceCombo"));
    mSource->addItem(tr("This workstation"), mLocal);
    if (!mServer.isEmpty()) {
        mSource->addItem(tr("The class's server (%1)").arg(mServer), mServer);
        mSource->setCurrentIndex(1);
    }
    mRefresh = new QPushButton(tr("&Refresh"), this);
    mRefresh->setObjectName(QStringLiteral("classRefreshButton"));
    mExport = new QPushButton(tr("&Export CSV…"), this);
    mExport->setObjectName(QStringLiteral("classExportButton"));
    mClassFilter = new QComboBox(this);
    mClassFilter->setObjectName(QStringLiteral("classFilterCombo"));
    mClassFilter->setToolTip(tr("Show one class (a class is the server's: a workstation's role belongs to one)"));
    mTable = new QTableWidget(0, 8, this);
    mTable->setObjectName(QStringLiteral("classTable"));
    mTable->setHorizontalHeaderLabels({tr("Class"), tr("Trainee"), tr("Exercise"), tr("Sessions"), tr("Latest"), tr("Best"),
                                       tr("Against the marks"), tr("Last session")});
    mTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    mTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    // The rows come by class, then trainee: the first sort (by class, stable) keeps that order.
    mTable->horizontalHeader()->setSortIndicator(0, Qt::AscendingOrder);
    mTable->setSortingEnabled(true);
    mTable->horizontalHeader()->setStretchLastSection(true);
    mTable->verticalHeader()->hide();
    mStatus = new QLabel(this);
    mStatus->setObjectName(QStringLiteral("classStatus"));
    mStatus->setWordWrap(true);
    auto* top = new QHBoxLayout;
    auto* sourceLabel = new QLabel(tr("&Results of:"), this);
    sourceLabel->setBuddy(mSource);
    top->addWidget(sourceLabel);
    top->addWidget(mSource, 1);
    auto* classLabel = new QLabel(tr("C&lass:"), this);
    classLabel->setBuddy(mClassFilter);
    top->addWidget(classLabel);
    top->addWidget(mClassFilter);
    top->addWidget(mRefresh);
    top->addWidget(mExport);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(mTable, 1);
    layout->addWidget(mStatus);
    layout->addWidget(buttons);
    connect(mRefresh, &QPushButton::clicked, this, &ClassDialog::refresh);
    connect(mSource, &QComboBox::currentIndexChanged, this, &ClassDialog::refresh);
    connect(mClassFilter, &QComboBox::currentIndexChanged, this, [this] {
        fill();
        showSummary();
    });
    connect(mExport, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export the Class View"), QStringLiteral("class.csv"),
                                                          tr("CSV (*.csv)"));
        if (path.isEmpty()) return;
        const QString problem = exportCsv(path);
        mStatus->setText(problem.isEmpty() ? tr("Exported %1 rows to %2.").arg(mShown.size()).arg(path) : problem);
    });
    resize(900, 480);
    refresh();
}

ClassDialog::~ClassDialog() {
    if (mThread) {
        mThread->wait();  // its queued call to this dialog is dropped with it
        delete mThread;
    }
}

bool ClassDialog::refresh() {
    if (mThread) return false;
    const QString location = mSource->currentData().toString(), examples = mExamples;
    const QString source = mSource->currentText();
    mThread = QThread::create([this, location, examples, source] {
        std::vector<ClassRow> rows;
        QString error, connection;
        {
            ResultsDatabase db;  // a connection of this thread's own
            if (db.open(location, &error)) {
                rows = classSummary(db.allResults(), defaultExerciseLookup(examples));
                connection = db.connectionDescription();
            }
        }
        const QString described = connection.isEmpty() ? source : tr("%1 as %2").arg(source, connection);
        handOffTo(this, [this, rows, error, described] { onLoaded(rows, error, described); });
    });
    mThread->setObjectName(QStringLiteral("class view"));
    mRefresh->setEnabled(false);
    mStatus->setText(tr("Reading %1…").arg(source));
    mThread->start(QThread::LowPriority);
    return true;
}

void ClassDialog::onLoaded(const std::vector<ClassRow>& rows, const QString& error, const QString& source) {
    if (mThread) {
        mThread->wait();
        delete mThread;
        mThread = nullptr;
    }
    mRefresh->setEnabled(true);
    if (!error.isEmpty()) {
        mStatus->setText(tr("Cannot read %1: %2").arg(source, error));
        emit loaded(false);
        return;
    }
    mRows = rows;
    mSourceText = source;
    // The classes these rows hold; the choice is kept when the new rows still have it.
    const QVariant chosen = mClassFilter->currentData();
    QStringList classes;
    for (const ClassRow& r : mRows)
        if (!classes.contains(r.className)) classes << r.className;
    {
        const QSignalBlocker quiet(mClassFilter);
        mClassFilter->clear();
        mClassFilter->addItem(tr("All"));
        for (const QString& c : classes) mClassFilter->addItem(c.isEmpty() ? tr("(none)") : c, c);
        const int keep = chosen.isValid() ? mClassFilter->findData(chosen) : -1;
        mClassFilter->setCurrentIndex(std::max(0, keep));
    }
    mClassFilter->setEnabled(classes.size() > 1);
    fill();
    showSummary();
    emit loaded(true);
}

void ClassDialog::showSummary() {
    int trainees = 0;
    QString last;
    for (const ClassRow& r : mShown)
        if (r.trainee != last) ++trainees, last = r.trainee;
    // No plural translation is loaded for English: the forms are spelled out.
    const QString who = trainees == 1 ? tr("1 trainee") : tr("%1 trainees").arg(trainees);
    const QString what = mShown.size() == 1 ? tr("1 row") : tr("%1 rows").arg(mShown.size());
    mStatus->setText(tr("%1: %2, %3. Exercises are matched by name across workstations.").arg(mSourceText, who, what));
}

void ClassDialog::setClassFilter(const QString& className) {
    const int index = mClassFilter->findData(className);
    if (index >= 0) mClassFilter->setCurrentIndex(index);
}

void ClassDialog::fill() {
    const QVariant only = mClassFilter->currentData();
    mShown.clear();
    for (const ClassRow& r : mRows)
        if (!only.isValid() || r.className == only.toString()) mShown.push_back(r);
    mTable->setSortingEnabled(false);
    mTable->setRowCount(int(mShown.size()));
    const QLocale locale;
    for (int i = 0; i < int(mShown.size()); ++i) {
        const ClassRow& r = mShown[std::size_t(i)];
        auto number = [](double v) {
            auto* item = new QTableWidgetItem;
            item->setData(Qt::DisplayRole, qRound(v * 10.0) / 10.0);
            return item;
        };
        mTable->setItem(i, 0, new QTableWidgetItem(r.className.isEmpty() ? tr("(none)") : r.className));
        mTable->setItem(i, 1, new QTableWidgetItem(r.trainee));
        mTable->setItem(i, 2, new QTableWidgetItem(r.exercise));
        auto* sessions = new QTableWidgetItem;
        sessions->setData(Qt::DisplayRole, r.sessions);
        mTable->setItem(i, 3, sessions);
        mTable->setItem(i, 4, number(r.latestScore));
        mTable->setItem(i, 5, number(r.bestScore));
        const QString verdict = r.verdict == QLatin1String("proficient") ? tr("proficient")
                                : r.verdict == QLatin1String("passed")   ? tr("passed (once)")
                                : r.verdict == QLatin1String("not yet")  ? tr("not yet")
                                                                         : tr("no marks");
        auto* v = new QTableWidgetItem(verdict);
        if (!r.standardNote.isEmpty()) v->setToolTip(r.standardNote);
        if (r.verdict == QLatin1String("proficient")) v->setBackground(QColor(0xc8, 0xe6, 0xc9));
        else if (r.verdict == QLatin1String("not yet")) v->setBackground(QColor(0xff, 0xe0, 0xb2));
        mTable->setItem(i, 6, v);
        mTable->setItem(i, 7, new QTableWidgetItem(locale.toString(r.latestUtc.toLocalTime(), QLocale::ShortFormat)));
    }
    mTable->setSortingEnabled(true);
    mTable->resizeColumnsToContents();
}

QString ClassDialog::statusText() const { return mStatus->text(); }

QString ClassDialog::exportCsv(const QString& path) const {
    if (path == mLocal) return tr("%1 is the results database: choose another file").arg(path);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return tr("%1: cannot be written (%2)").arg(path, file.errorString());
    file.write(classSummaryCsv(mShown).toUtf8());  // what the view shows
    if (!file.commit()) return tr("%1: cannot be written (%2)").arg(path, file.errorString());
    return {};
}

}  // namespace palpate
