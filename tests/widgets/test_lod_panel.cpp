// The level-of-detail panel under QT_QPA_PLATFORM=offscreen: a real plan (levels + measurement on a
// worker thread) on a copy of the 1442-vertex sphere in a temporary folder (the level cache is
// written next to the mesh, never into resources/); the chosen row against planLod computed here;
// replanning on edited targets without measuring; Use chosen / Use selected (override) with the
// level's file; Cancel (at once, and in the middle of measuring); the cache on a second plan;
// invalid targets; meshes that fail; destruction while planning.
#include "engine/core/TissueMesh.h"
#include "engine/lod/LevelCache.h"
#include "engine/lod/LodPlanner.h"
#include "widgets/LodPanel.h"

#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <memory>

using namespace palpate;

namespace {

constexpr int kPlanTimeoutMs = 180'000;  // a loaded 2-core build machine; normally about a second

/// A copy of a shipped mesh in `dir` (the panel writes "<mesh>.levels/" beside it).
QString copyMesh(const QTemporaryDir& dir, const QString& name = QStringLiteral("sphere_1442.off")) {
    const QString source = QStringLiteral(PALPATE_SOURCE_DIR "/resources/meshes/") + name;
    const QString target = dir.filePath(name);
    if (!QFile::copy(source, target)) return {};
    return target;
}

std::shared_ptr<const TissueMesh> loadMesh(const QString& path) {
    auto loaded = TissueMesh::load(path.toStdString());
    if (!loaded.mesh) return nullptr;
    return std::make_shared<const TissueMesh>(std::move(*loaded.mesh));
}

template <typename T>
T* child(const LodPanel& panel, const char* name) {
    return panel.findChild<T*>(QLatin1String(name));
}

bool waitIdle(const LodPanel& panel) {
    return QTest::qWaitFor([&] { return !panel.busy(); }, kPlanTimeoutMs);
}

/// The table row whose verdict column says `word` (the last column), or -1.
int rowWithVerdict(const LodPanel& panel, const QString& word) {
    const auto* table = child<QTableWidget>(panel, "lodCandidateTable");
    const int verdict = table->columnCount() - 1;
    for (int row = 0; row < table->rowCount(); ++row)
        if (table->item(row, verdict) && table->item(row, verdict)->text() == word) return row;
    return -1;
}

class LodPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(mDir.isValid());
        mMeshPath = copyMesh(mDir);
        ASSERT_FALSE(mMeshPath.isEmpty());
        mMesh = loadMesh(mMeshPath);
        ASSERT_TRUE(mMesh);
    }

    /// setScene + plan() to the end.
    void planToEnd(LodPanel& panel, const LodNeeds& needs = {0.1, 50.0}) {
        panel.setScene(mMeshPath, mMesh, needs, QStringLiteral("the test"));
        QSignalSpy planned(&panel, &LodPanel::planned);
        ASSERT_TRUE(panel.plan());
        EXPECT_TRUE(panel.busy());
        ASSERT_TRUE(waitIdle(panel));
        EXPECT_EQ(planned.count(), 1);
        ASSERT_FALSE(panel.candidates().empty()) << panel.statusText().toStdString();
    }

    QTemporaryDir mDir;
    QString mMeshPath;
    std::shared_ptr<const TissueMesh> mMesh;
};

TEST_F(LodPanelTest, PlansOffTheGuiThreadAndHighlightsThePlannersChoice) {
    LodPanel panel;
    panel.resize(380, 800);
    panel.show();
    planToEnd(panel);

    const LodNeeds needs = panel.needs();
    EXPECT_DOUBLE_EQ(needs.maxErrorFraction, 0.1);
    EXPECT_DOUBLE_EQ(needs.budgetUs, 50.0);
    const LodPlan expected = planLod(panel.candidates(), needs);
    EXPECT_EQ(panel.currentPlan().feasible, expected.feasible);
    EXPECT_EQ(panel.currentPlan().chosen, expected.chosen);
    EXPECT_EQ(panel.currentPlan().closest, expected.closest);
    EXPECT_EQ(panel.currentPlan().reason, expected.reason);
    EXPECT_FALSE(panel.lastPlanCancelled());

    // Every level of the sphere (1442 -> 721 -> 361) with every default ring count.
    const auto* table = child<QTableWidget>(panel, "lodCandidateTable");
    EXPECT_EQ(table->rowCount(), int(panel.candidates().size()));
    EXPECT_EQ(panel.candidates().size(), 3 * LodPanel::defaultMeasureDefinition().ringCounts.size());

    // The highlighted (labelled "chosen") row is the planner's choice, or "closest" when nothing fits.
    if (expected.chosen) {
        EXPECT_EQ(rowWithVerdict(panel, QStringLiteral("chosen")), int(*expected.chosen));
        EXPECT_NE(table->item(int(*expected.chosen), 0)->background(), QBrush());
        EXPECT_EQ(panel.selectedCandidate(), expected.chosen);
        EXPECT_FALSE(panel.isOverride());
        EXPECT_TRUE(child<QLabel>(panel, "lodSummaryLabel")->text().contains(QStringLiteral("Chosen")));
    } else {
        EXPECT_EQ(rowWithVerdict(panel, QStringLiteral("closest")), int(*expected.closest));
    }
    // The reason is shown, word-wrapped.
    const auto* reason = child<QLabel>(panel, "lodReasonLabel");
    EXPECT_TRUE(reason->text().contains(QString::fromStdString(expected.reason)));
    EXPECT_TRUE(reason->wordWrap());

    // The cache folder is next to the copied mesh, with the coarse levels; the levels were generated.
    const QString cacheDir = QString::fromStdString(levelCacheDir(mMeshPath.toStdString()));
    EXPECT_TRUE(QFileInfo(cacheDir).isDir());
    EXPECT_TRUE(QFileInfo::exists(QDir(cacheDir).filePath(QStringLiteral("levels.json"))));
    EXPECT_FALSE(panel.levelsFromCache());
    EXPECT_TRUE(child<QLabel>(panel, "lodLevelsLabel")->text().contains(QStringLiteral("generated")));
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("Planned")));
}

// Linear or stiffening tissue (docs/lod.md): judged at the scene's presses after the plan, and
// re-decided at once when the targets or the presses change.
TEST_F(LodPanelTest, DecidesLinearOrStiffeningTissueAtTheScenesPresses) {
    LodPanel panel;
    ToolContact stiffening;
    stiffening.material = {4.34e-3, 0.45};
    stiffening.stiffeningExponent = 5.0;
    panel.setToolContact(stiffening);
    panel.setSceneDemands({{"press target 1 (up to 1 N)", 1.0, 0.0}});
    EXPECT_FALSE(panel.stiffeningChoice());  // nothing solved yet
    planToEnd(panel, {0.05, 100000.0});
    ASSERT_TRUE(panel.stiffeningReference());
    ASSERT_TRUE(panel.stiffeningChoice());
    EXPECT_TRUE(panel.stiffeningChoice()->error.empty()) << panel.stiffeningChoice()->error;
    EXPECT_TRUE(panel.stiffeningChoice()->nonlinear);
    EXPECT_GT(panel.stiffeningChoice()->linearErrorFraction, 0.05);
    EXPECT_EQ(panel.stiffeningChoice()->worstDepthWhat, "press target 1 (up to 1 N)");
    const auto* reason = child<QLabel>(panel, "lodReasonLabel");
    EXPECT_TRUE(reason->text().contains(QStringLiteral("Tissue: Stiffening tissue"))) << reason->text().toStdString();

    // A lax target: linear is enough, decided without solving again.
    panel.setNeeds({1.0, 100000.0});
    EXPECT_FALSE(panel.busy());
    ASSERT_TRUE(panel.stiffeningChoice());
    EXPECT_FALSE(panel.stiffeningChoice()->nonlinear);
    EXPECT_TRUE(reason->text().contains(QStringLiteral("Tissue: Linear tissue"))) << reason->text().toStdString();

    // Another tissue: the reference was for the old one.
    panel.setToolContact(ToolContact{});
    EXPECT_FALSE(panel.stiffeningReference());
    EXPECT_FALSE(panel.stiffeningChoice());
}

TEST_F(LodPanelTest, EditedTargetsReplanFromTheTableWithoutMeasuring) {
    LodPanel panel;
    planToEnd(panel);
    const std::vector<LodCandidate> measured = panel.candidates();

    QSignalSpy progress(&panel, &LodPanel::progressChanged);
    QSignalSpy planned(&panel, &LodPanel::planned);
    QSignalSpy changed(&panel, &LodPanel::planChanged);
    // No tick on this machine takes a nanosecond: nothing fits.
    child<QDoubleSpinBox>(panel, "lodBudgetSpin")->setValue(0.001);
    EXPECT_FALSE(panel.busy());
    EXPECT_DOUBLE_EQ(panel.needs().budgetUs, 0.001);
    EXPECT_GE(changed.count(), 1);
    EXPECT_EQ(progress.count(), 0);
    EXPECT_EQ(planned.count(), 0);
    ASSERT_EQ(panel.candidates().size(), measured.size());
    for (std::size_t i = 0; i < measured.size(); ++i) EXPECT_EQ(panel.candidates()[i].tickUs, measured[i].tickUs);

    const LodPlan expected = planLod(measured, panel.needs());
    ASSERT_FALSE(expected.feasible);
    ASSERT_TRUE(expected.closest);
    EXPECT_FALSE(panel.currentPlan().feasible);
    EXPECT_FALSE(panel.currentPlan().chosen);
    EXPECT_EQ(panel.currentPlan().closest, expected.closest);
    EXPECT_EQ(rowWithVerdict(panel, QStringLiteral("closest")), int(*expected.closest));
    EXPECT_EQ(rowWithVerdict(panel, QStringLiteral("chosen")), -1);
    EXPECT_TRUE(child<QLabel>(panel, "lodSummaryLabel")->text().contains(QStringLiteral("Nothing meets both targets")));
    EXPECT_TRUE(child<QLabel>(panel, "lodReasonLabel")->text().contains(QStringLiteral("Closest")));
    EXPECT_FALSE(child<QPushButton>(panel, "lodUseChosenButton")->isEnabled());
    // Every row's tick is marked as over the budget (the tick column: value, then the mark).
    const auto* table = child<QTableWidget>(panel, "lodCandidateTable");
    for (int row = 0; row < table->rowCount(); ++row)
        EXPECT_TRUE(table->item(row, 4)->text().endsWith(QStringLiteral("\u2717"))) << table->item(row, 4)->text().toStdString();

    // Back to a budget every candidate meets: a choice again, still without measuring.
    child<QDoubleSpinBox>(panel, "lodBudgetSpin")->setValue(1000.0);
    EXPECT_EQ(panel.currentPlan().chosen, planLod(measured, panel.needs()).chosen);
    EXPECT_EQ(progress.count(), 0);
    // The targets were edited here: the panel says so.
    EXPECT_TRUE(child<QLabel>(panel, "lodNeedsSourceLabel")->text().contains(QStringLiteral("edited")));
}

TEST_F(LodPanelTest, UseChosenAndUseSelectedCarryTheLevelFileAndRings) {
    LodPanel panel;
    planToEnd(panel);
    // A max error just above the coarsest level's best: the planner chooses that level (coarsest first).
    const std::size_t coarsest = panel.candidates().back().level;
    ASSERT_GT(coarsest, 0u);
    double best = 1e9;
    for (const LodCandidate& c : panel.candidates())
        if (c.level == coarsest && std::isfinite(c.errorFraction)) best = std::min(best, c.errorFraction);
    ASSERT_LT(best, 1e9);
    panel.setNeeds({std::ceil(best * 1.01 * 10000.0) / 10000.0, 1000.0});  // the field keeps 0.01 %
    ASSERT_TRUE(panel.currentPlan().chosen) << panel.currentPlan().reason;
    const std::size_t chosen = *panel.currentPlan().chosen;
    const LodCandidate& c = panel.candidates()[chosen];
    ASSERT_EQ(c.level, coarsest);

    QSignalSpy use(&panel, &LodPanel::useRequested);
    auto* useChosen = child<QPushButton>(panel, "lodUseChosenButton");
    auto* useSelected = child<QPushButton>(panel, "lodUseSelectedButton");
    ASSERT_TRUE(useChosen->isEnabled());
    EXPECT_FALSE(useSelected->isEnabled());  // nothing selected: nothing to override with
    useChosen->click();
    ASSERT_EQ(use.count(), 1);
    const QString path = use.at(0).at(0).toString();
    EXPECT_EQ(path, panel.levelMeshPath(chosen));
    EXPECT_EQ(use.at(0).at(1).toInt(), c.rings);
    EXPECT_FALSE(use.at(0).at(2).toBool());
    // The file is the level: same vertex count as measured.
    ASSERT_TRUE(QFileInfo::exists(path)) << path.toStdString();
    const auto level = loadMesh(path);
    ASSERT_TRUE(level);
    EXPECT_EQ(level->vertexCount(), c.vertices);

    // The instructor selects a row of the source (level 0) and uses it: an override, "" = the source.
    std::size_t other = panel.candidates().size();
    for (std::size_t i = 0; i < panel.candidates().size(); ++i)
        if (panel.candidates()[i].level == 0 && panel.candidates()[i].rings == 2) other = i;
    ASSERT_LT(other, panel.candidates().size());
    child<QTableWidget>(panel, "lodCandidateTable")->selectRow(int(other));
    EXPECT_EQ(panel.selectedCandidate(), other);
    EXPECT_TRUE(panel.isOverride());
    EXPECT_EQ(rowWithVerdict(panel, QStringLiteral("override")), int(other));
    EXPECT_TRUE(child<QLabel>(panel, "lodSummaryLabel")->text().contains(QStringLiteral("Override")));
    ASSERT_TRUE(useSelected->isEnabled());
    useSelected->click();
    ASSERT_EQ(use.count(), 2);
    EXPECT_EQ(use.at(1).at(0).toString(), QString());
    EXPECT_EQ(use.at(1).at(1).toInt(), 2);
    EXPECT_TRUE(use.at(1).at(2).toBool());

    // An override on a coarse level gives that level's file.
    std::size_t coarseOther = panel.candidates().size();
    for (std::size_t i = 0; i < panel.candidates().size(); ++i)
        if (panel.candidates()[i].level == 1 && i != chosen) coarseOther = i;
    ASSERT_LT(coarseOther, panel.candidates().size());
    panel.selectCandidate(coarseOther);
    useSelected->click();
    ASSERT_EQ(use.count(), 3);
    EXPECT_TRUE(use.at(2).at(0).toString().endsWith(QStringLiteral("level1.obj")));
    EXPECT_TRUE(QFileInfo::exists(use.at(2).at(0).toString()));
    EXPECT_TRUE(use.at(2).at(2).toBool());

    // Store targets in preset: the fields' needs.
    QSignalSpy store(&panel, &LodPanel::storeNeedsRequested);
    child<QPushButton>(panel, "lodStoreNeedsButton")->click();
    ASSERT_EQ(store.count(), 1);
    const auto stored = store.at(0).at(0).value<LodNeeds>();
    EXPECT_DOUBLE_EQ(stored.maxErrorFraction, panel.needs().maxErrorFraction);
    EXPECT_DOUBLE_EQ(stored.budgetUs, 1000.0);
}

TEST_F(LodPanelTest, CancelAtOnceLeavesThePanelUsable) {
    LodPanel panel;
    panel.setScene(mMeshPath, mMesh, std::nullopt);
    QSignalSpy planned(&panel, &LodPanel::planned);
    ASSERT_TRUE(panel.plan());
    panel.cancel();
    EXPECT_FALSE(child<QPushButton>(panel, "lodCancelButton")->isEnabled());
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_FALSE(panel.busy());
    EXPECT_TRUE(panel.lastPlanCancelled());
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("Cancelled"))) << panel.statusText().toStdString();
    EXPECT_EQ(planned.count(), 1);
    EXPECT_TRUE(child<QPushButton>(panel, "lodPlanButton")->isEnabled());
    EXPECT_FALSE(child<QPushButton>(panel, "lodCancelButton")->isEnabled());

    // Usable: the next plan runs to the end.
    ASSERT_TRUE(panel.plan());
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_FALSE(panel.lastPlanCancelled());
    EXPECT_FALSE(panel.candidates().empty());
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("Planned")));
}

TEST_F(LodPanelTest, CancelWhileMeasuringPlansThePartialTable) {
    // The 8664-vertex sphere: six levels, thirty candidates, so Cancel lands in the middle.
    const QString bigPath = copyMesh(mDir, QStringLiteral("sphere_8664.off"));
    ASSERT_FALSE(bigPath.isEmpty());
    LodPanel panel;
    panel.setScene(bigPath, loadMesh(bigPath), LodNeeds{0.1, 50.0});
    QStringList texts;
    QObject::connect(&panel, &LodPanel::progressChanged, &panel, [&](double, const QString& text) {
        texts << text;
        if (text.startsWith(QStringLiteral("Measuring level 1"))) panel.cancel();
    });
    QSignalSpy planned(&panel, &LodPanel::planned);
    ASSERT_TRUE(panel.plan());
    ASSERT_TRUE(waitIdle(panel));
    ASSERT_EQ(planned.count(), 1);
    // The progress named the stages.
    EXPECT_TRUE(texts.filter(QStringLiteral("Generating")).size() > 0 || texts.filter(QStringLiteral("cached")).size() > 0)
        << texts.join(QLatin1Char('|')).toStdString();
    EXPECT_FALSE(texts.filter(QStringLiteral("Measuring level 0")).isEmpty());
    ASSERT_TRUE(panel.lastPlanCancelled()) << panel.statusText().toStdString();
    EXPECT_FALSE(panel.candidates().empty());
    EXPECT_LT(panel.candidates().size(), 30u);
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("partial"))) << panel.statusText().toStdString();
    // The plan is made from what was measured.
    EXPECT_EQ(panel.currentPlan().chosen, planLod(panel.candidates(), panel.needs()).chosen);
    EXPECT_EQ(panel.currentPlan().closest, planLod(panel.candidates(), panel.needs()).closest);
}

TEST_F(LodPanelTest, SecondPlanIsServedFromTheCache) {
    LodPanel panel;
    planToEnd(panel);
    EXPECT_FALSE(panel.levelsFromCache());
    ASSERT_TRUE(panel.plan());
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_TRUE(panel.levelsFromCache());
    EXPECT_TRUE(child<QLabel>(panel, "lodLevelsLabel")->text().contains(QStringLiteral("read from the cache")))
        << child<QLabel>(panel, "lodLevelsLabel")->text().toStdString();

    // Another panel (a new session) on the same file: the cache too.
    LodPanel again;
    again.setScene(mMeshPath, nullptr, std::nullopt);  // no loaded mesh: the worker loads the file
    ASSERT_TRUE(again.plan());
    ASSERT_TRUE(waitIdle(again));
    EXPECT_TRUE(again.levelsFromCache());
    EXPECT_EQ(again.candidates().size(), panel.candidates().size());
}

TEST_F(LodPanelTest, InvalidTargetsDisablePlanAndNameTheField) {
    LodPanel panel;
    panel.setScene(mMeshPath, mMesh, std::nullopt);
    // No needs from the scene: the panel's defaults, and it says so.
    EXPECT_DOUBLE_EQ(panel.needs().maxErrorFraction, LodPanel::defaultNeeds().maxErrorFraction);
    EXPECT_DOUBLE_EQ(panel.needs().budgetUs, LodPanel::defaultNeeds().budgetUs);
    EXPECT_TRUE(child<QLabel>(panel, "lodNeedsSourceLabel")->text().contains(QStringLiteral("defaults")));
    auto* planButton = child<QPushButton>(panel, "lodPlanButton");
    auto* storeButton = child<QPushButton>(panel, "lodStoreNeedsButton");
    auto* problem = child<QLabel>(panel, "lodNeedsProblemLabel");
    EXPECT_TRUE(planButton->isEnabled());

    child<QDoubleSpinBox>(panel, "lodMaxErrorSpin")->setValue(-5.0);
    EXPECT_FALSE(planButton->isEnabled());
    EXPECT_FALSE(storeButton->isEnabled());
    EXPECT_FALSE(problem->isHidden());
    EXPECT_TRUE(problem->text().contains(QStringLiteral("Max error"))) << problem->text().toStdString();
    ASSERT_EQ(panel.needsProblems().size(), 1);
    EXPECT_TRUE(child<QDoubleSpinBox>(panel, "lodMaxErrorSpin")->property("invalid").toBool());
    EXPECT_FALSE(panel.plan());
    EXPECT_FALSE(panel.busy());

    child<QDoubleSpinBox>(panel, "lodBudgetSpin")->setValue(-1.0);
    EXPECT_EQ(panel.needsProblems().size(), 2);
    EXPECT_TRUE(problem->text().contains(QStringLiteral("Tick budget")));
    // Absurdly large is named too.
    child<QDoubleSpinBox>(panel, "lodBudgetSpin")->setValue(5.0e6);
    EXPECT_TRUE(problem->text().contains(QStringLiteral("absurd")));

    child<QDoubleSpinBox>(panel, "lodMaxErrorSpin")->setValue(10.0);
    child<QDoubleSpinBox>(panel, "lodBudgetSpin")->setValue(50.0);
    EXPECT_TRUE(panel.needsProblems().isEmpty());
    EXPECT_TRUE(problem->isHidden());
    EXPECT_TRUE(planButton->isEnabled());
    EXPECT_TRUE(storeButton->isEnabled());
    EXPECT_FALSE(child<QDoubleSpinBox>(panel, "lodMaxErrorSpin")->property("invalid").toBool());
}

TEST_F(LodPanelTest, TheSameSceneKeepsTheTableAnotherClearsIt) {
    LodPanel panel;
    planToEnd(panel);
    const std::size_t count = panel.candidates().size();
    // The preset changed its needs: same mesh, the table stays and the plan follows the new needs.
    panel.setScene(mMeshPath, mMesh, LodNeeds{0.5, 50.0}, QStringLiteral("preset 'gel'"));
    EXPECT_EQ(panel.candidates().size(), count);
    EXPECT_EQ(panel.currentPlan().chosen, planLod(panel.candidates(), {0.5, 50.0}).chosen);
    EXPECT_TRUE(child<QLabel>(panel, "lodNeedsSourceLabel")->text().contains(QStringLiteral("preset 'gel'")));
    // Another mesh: nothing measured for it yet.
    const QString other = copyMesh(mDir, QStringLiteral("stomach_1442.off"));
    panel.setScene(other, loadMesh(other), std::nullopt);
    EXPECT_TRUE(panel.candidates().empty());
    EXPECT_FALSE(panel.currentPlan().chosen);
    EXPECT_FALSE(child<QPushButton>(panel, "lodUseChosenButton")->isEnabled());
    EXPECT_EQ(child<QTableWidget>(panel, "lodCandidateTable")->rowCount(), 0);
}

TEST_F(LodPanelTest, ChangingTheSceneWhilePlanningDropsTheOldRun) {
    LodPanel panel;
    panel.setScene(mMeshPath, mMesh, std::nullopt);
    ASSERT_TRUE(panel.plan());
    const QString other = copyMesh(mDir, QStringLiteral("stomach_1442.off"));
    panel.setScene(other, loadMesh(other), std::nullopt);
    EXPECT_TRUE(panel.plan());  // starts once the old run has wound down
    ASSERT_TRUE(QTest::qWaitFor([&] { return !panel.busy() && !panel.candidates().empty(); }, kPlanTimeoutMs));
    EXPECT_TRUE(panel.levelMeshPath(panel.candidates().size() - 1).contains(QStringLiteral("stomach_1442.off.levels")));
}

TEST_F(LodPanelTest, AMeshThatFailsShowsTheEnginesErrorAndNeverCrashes) {
    // A file that is not a mesh, without a loaded mesh: the worker's load fails.
    const QString garbage = mDir.filePath(QStringLiteral("garbage.off"));
    {
        QFile f(garbage);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("OFF\n3 1 0\nthis is not a mesh\n");
    }
    LodPanel panel;
    QSignalSpy failed(&panel, &LodPanel::planFailed);
    panel.setScene(garbage, nullptr, std::nullopt);
    ASSERT_TRUE(panel.plan());
    ASSERT_TRUE(waitIdle(panel));
    ASSERT_EQ(failed.count(), 1);
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("Plan failed"))) << panel.statusText().toStdString();
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("garbage.off"))) << panel.statusText().toStdString();
    EXPECT_TRUE(panel.candidates().empty());
    EXPECT_TRUE(child<QPushButton>(panel, "lodPlanButton")->isEnabled());

    // An open surface (a tetrahedron without its base) that loads: whatever the engine says
    // (an error, or candidates it could not measure) is shown and the panel stays usable.
    const QString open = mDir.filePath(QStringLiteral("open.off"));
    {
        QFile f(open);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("OFF\n4 3 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
    }
    const auto openMesh = loadMesh(open);
    QSignalSpy planned(&panel, &LodPanel::planned);
    panel.setScene(open, openMesh, std::nullopt);
    ASSERT_TRUE(panel.plan());
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_EQ(failed.count() + planned.count(), 2);
    if (planned.count() == 1) {
        // Today: four vertices are too few to judge the error; every row says it was not measured.
        EXPECT_FALSE(panel.currentPlan().feasible);
        EXPECT_FALSE(child<QLabel>(panel, "lodReasonLabel")->text().isEmpty());
        EXPECT_GE(rowWithVerdict(panel, QStringLiteral("n/a")), 0);
        EXPECT_TRUE(child<QLabel>(panel, "lodSummaryLabel")->text().contains(QStringLiteral("could not be measured")));
        panel.resize(380, 560);
        panel.show();
        QTest::qWait(100);
        EXPECT_TRUE(panel.grab().toImage().save(QDir::temp().filePath(QStringLiteral("palpate_lod_panel_open.png"))));
    }
    EXPECT_TRUE(child<QPushButton>(panel, "lodPlanButton")->isEnabled());
}

TEST_F(LodPanelTest, AMissingLevelFileIsReportedInsteadOfUsed) {
    LodPanel panel;
    planToEnd(panel);
    // Someone removes the cache folder after the plan: Use must not hand the window a missing file.
    ASSERT_TRUE(QDir(QString::fromStdString(levelCacheDir(mMeshPath.toStdString()))).removeRecursively());
    std::size_t coarse = panel.candidates().size();
    for (std::size_t i = 0; i < panel.candidates().size(); ++i)
        if (panel.candidates()[i].level > 0 && panel.currentPlan().chosen != i) coarse = i;
    ASSERT_LT(coarse, panel.candidates().size());
    QSignalSpy use(&panel, &LodPanel::useRequested);
    panel.selectCandidate(coarse);
    panel.useSelected();
    EXPECT_EQ(use.count(), 0);
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("missing"))) << panel.statusText().toStdString();
    // Clearing the selection ends the override.
    panel.selectCandidate(std::nullopt);
    EXPECT_FALSE(panel.isOverride());
    EXPECT_EQ(panel.selectedCandidate(), panel.currentPlan().chosen);
}

TEST_F(LodPanelTest, AnInvalidMeasureDefinitionIsRefusedWithTheReason) {
    LodPanel panel;
    panel.setScene(mMeshPath, mMesh, std::nullopt);
    LodMeasureDef def = LodPanel::defaultMeasureDefinition();
    def.ringCounts.clear();
    panel.setMeasureDefinition(def);
    QSignalSpy failed(&panel, &LodPanel::planFailed);
    EXPECT_FALSE(panel.plan());
    EXPECT_FALSE(panel.busy());
    ASSERT_EQ(failed.count(), 1);
    EXPECT_TRUE(failed.at(0).at(0).toString().contains(QStringLiteral("ring counts")));
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("ring counts")));
}

TEST_F(LodPanelTest, DestroyingThePanelWhilePlanningIsSafe) {
    // At once after the start.
    {
        auto panel = std::make_unique<LodPanel>();
        panel->setScene(mMeshPath, mMesh, std::nullopt);
        ASSERT_TRUE(panel->plan());
        panel.reset();
    }
    // In the middle of measuring (the worker is posting progress to the panel).
    {
        auto panel = std::make_unique<LodPanel>();
        panel->setScene(mMeshPath, mMesh, std::nullopt);
        bool measuring = false;
        QObject::connect(panel.get(), &LodPanel::progressChanged, panel.get(), [&](double, const QString& text) {
            measuring = measuring || text.startsWith(QStringLiteral("Measuring"));
        });
        ASSERT_TRUE(panel->plan());
        ASSERT_TRUE(QTest::qWaitFor([&] { return measuring || !panel->busy(); }, kPlanTimeoutMs));
        panel.reset();
    }
    // Calls the worker had queued for the panels must not reach them now.
    QTest::qWait(100);
    SUCCEED();
}

TEST_F(LodPanelTest, GrabsTheDockSizedPanelToPng) {
    LodPanel panel;
    panel.resize(380, 760);
    panel.show();
    planToEnd(panel);
    const QString out = QDir::temp().filePath(QStringLiteral("palpate_lod_panel.png"));
    QTest::qWait(100);  // the layout (and the scroll area) follow the labels' new texts
    const QImage image = panel.grab().toImage();
    ASSERT_FALSE(image.isNull());
    EXPECT_TRUE(image.save(out));
    // Infeasible, with an override selected.
    child<QDoubleSpinBox>(panel, "lodBudgetSpin")->setValue(0.001);
    panel.selectCandidate(0);
    QTest::qWait(100);
    EXPECT_TRUE(panel.grab().toImage().save(QDir::temp().filePath(QStringLiteral("palpate_lod_panel_infeasible.png"))));
    // Invalid targets, nothing planned.
    LodPanel fresh;
    fresh.resize(380, 560);
    fresh.show();
    fresh.setScene(mMeshPath, mMesh, std::nullopt);
    child<QDoubleSpinBox>(fresh, "lodMaxErrorSpin")->setValue(-5.0);
    QTest::qWait(100);
    EXPECT_TRUE(fresh.grab().toImage().save(QDir::temp().filePath(QStringLiteral("palpate_lod_panel_invalid.png"))));
}

}  // namespace

int main(int argc, char** argv) {
    // Before QApplication: the platform is chosen in its constructor. No GPU, no display needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings of these tests never touch the user's
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
