#pragma once
// The instructor's Class view (Exercise > Class View…, docs/results-store.md): every trainee's
// sessions, latest and best score per exercise and the verdict against the experts' marks, by
// class, from
// this workstation's database or the class's server, read off the GUI thread; CSV export.

#include "results/ClassSummary.h"

#include <QDialog>
#include <QString>

#include <memory>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QThread;

namespace palpate {

class ClassDialog final : public QDialog {
    Q_OBJECT
public:
    /// `localPath`: this workstation's database; `serverUrl`: the class's server ("" : none, the
    /// choice is not offered); `examplesFolder`: where exercises are found by name.
    ClassDialog(const QString& localPath, const QString& serverUrl, const QString& examplesFolder, QWidget* parent = nullptr);
    ~ClassDialog() override;

    /// Reads the chosen database on a worker thread; false while one read runs.
    bool refresh();
    bool busy() const { return mThread != nullptr; }
    const std::vector<ClassRow>& rows() const { return mRows; }
    /// The rows the table shows (those of the chosen class), and what Export CSV… writes.
    const std::vector<ClassRow>& shownRows() const { return mShown; }
    /// Shows only `className`'s rows, when the rows have that class.
    void setClassFilter(const QString& className);
    QString statusText() const;
    /// Writes the rows as CSV; "" or the problem.
    QString exportCsv(const QString& path) const;

signals:
    void loaded(bool ok);

private:
    void onLoaded(const std::vector<ClassRow>& rows, const QString& error, const QString& source);
    void fill();
    void showSummary();

    QString mLocal, mServer, mExamples;
    QComboBox* mSource = nullptr;
    QComboBox* mClassFilter = nullptr;
    QString mSourceText;
    QPushButton* mRefresh = nullptr;
    QPushButton* mExport = nullptr;
    QTableWidget* mTable = nullptr;
    QLabel* mStatus = nullptr;
    QThread* mThread = nullptr;
    std::vector<ClassRow> mRows;
    std::vector<ClassRow> mShown;
};

}  // namespace palpate
