// The Parameters panel's Tissue group under QT_QPA_PLATFORM=offscreen: typed E, nu and tool radius
// calibrate exactly the slopes calibrateSlopesFromPunch gives (one undoable step), the error label
// shows the calibrated model's error, a bad Poisson's ratio is refused naming the field, and the
// shipped tissue presets fill the tissue and the slopes.
#include "engine/core/MeshGenerator.h"
#include "engine/core/SceneTarget.h"
#include "engine/accuracy/Calibration.h"
#include "widgets/ParameterCommands.h"
#include "widgets/ParameterPanel.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <memory>

using namespace palpate;

namespace {

QDoubleSpinBox* field(ParameterPanel& panel, const char* name) { return panel.findChild<QDoubleSpinBox*>(QLatin1String(name)); }
QDoubleSpinBox* slopeSpin(ParameterPanel& panel, int ring) {
    return panel.findChild<QDoubleSpinBox*>(QStringLiteral("slopeRingSlopeMagnitudeMmPerNSpin%1").arg(ring));
}

/// Types `text` into a spin box as a user would (select all, type, Enter).
void type(QDoubleSpinBox* spin, const QString& text) {
    QLineEdit* edit = spin->findChild<QLineEdit*>();
    edit->selectAll();
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

/// The default stomach mesh's size, generated (no file needed).
const TissueMesh& stomach() {
    static const auto mesh = std::make_shared<TissueMesh>(*generateMesh(GeneratedShape::Stomach, 3970).mesh);
    return *mesh;
}

}  // namespace

TEST(TissueCalibration, TypedTissueCalibratesTheEnginesSlopesAsOneUndoableStep) {
    ParameterPanel panel;
    panel.setMeshProvider([] { return &stomach(); });
    type(field(panel, "tissueYoungsModulusKPaSpin"), QStringLiteral("11.7"));
    type(field(panel, "tissuePoissonRatioSpin"), QStringLiteral("0.49"));
    type(field(panel, "tissueToolRadiusMmSpin"), QStringLiteral("4"));
    QTest::keyClick(panel.findChild<QSpinBox*>(QStringLiteral("slopeRingRingCountSpin"))->findChild<QLineEdit*>(), Qt::Key_Up);
    ASSERT_TRUE(panel.isValid()) << panel.problems().join(QLatin1Char('\n')).toStdString();
    ASSERT_EQ(panel.preset().model.slopeRing.ringCount, 3);
    ASSERT_TRUE(panel.preset().tissue.has_value());
    EXPECT_DOUBLE_EQ(panel.preset().tissue->youngsModulusKPa, 11.7);
    const TissuePreset before = panel.preset();
    const int stepsBefore = panel.undoStack()->count();

    ToolContact contact;
    contact.material = {11.7e-3, 0.49};
    contact.toolRadiusMm = 4.0;
    const SlopeCalibration expected =
        calibrateSlopesFromPunch(stomach(), defaultTargetVertex(stomach()), contact, before.model.slopeRing);

    QTest::mouseClick(panel.findChild<QPushButton*>(QStringLiteral("calibrateSlopesButton")), Qt::LeftButton);
    const TissuePreset after = panel.preset();
    for (int r = 0; r <= 3; ++r)
        EXPECT_NEAR(after.model.slopeRing.slopeMagnitudeMmPerN[std::size_t(r)], expected.params.slopeMagnitudeMmPerN[std::size_t(r)],
                    1e-9)
            << "ring " << r;
    EXPECT_NEAR(after.model.slopeRing.springStiffnessNPerMm, expected.params.springStiffnessNPerMm, 1e-9);
    EXPECT_NEAR(after.model.slopeRing.slopeLimitMmPerN, expected.params.slopeLimitMmPerN, 1e-4);
    EXPECT_TRUE(panel.isValid()) << panel.problems().join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(panel.undoStack()->count(), stepsBefore + 1);
    EXPECT_EQ(panel.undoStack()->undoText(), QStringLiteral("Calibrate slopes"));
    // |m1| = 1 / (2 a E*) = 8.1 mm/N: outside the paper's range, framed amber, noted.
    EXPECT_TRUE(slopeSpin(panel, 0)->property("outsidePaperRange").toBool());

    auto* errorLabel = panel.findChild<QLabel*>(QStringLiteral("calibrationLabel"));
    ASSERT_NE(errorLabel, nullptr);
    EXPECT_TRUE(errorLabel->isVisibleTo(&panel));
    EXPECT_TRUE(errorLabel->text().contains(QRegularExpression(QStringLiteral("displacement error \\d+\\.\\d %"))))
        << errorLabel->text().toStdString();
    EXPECT_TRUE(errorLabel->text().contains(QStringLiteral("force error"))) << errorLabel->text().toStdString();

    if (const QByteArray out = qgetenv("PALPATE_TEST_SCREENSHOTS"); !out.isEmpty()) {
        panel.resize(460, 1100);
        panel.show();
        QApplication::processEvents();
        panel.grab().save(QString::fromLocal8Bit(out) + QStringLiteral("/tissue_calibration.png"));
    }

    // Undo restores the slopes before the calibration (and keeps the typed tissue); redo re-applies.
    panel.undoAction()->trigger();
    EXPECT_TRUE(samePreset(panel.preset(), before));
    EXPECT_DOUBLE_EQ(field(panel, "tissueYoungsModulusKPaSpin")->value(), 11.7);
    panel.redoAction()->trigger();
    EXPECT_NEAR(panel.preset().model.slopeRing.slopeMagnitudeMmPerN[1], expected.params.slopeMagnitudeMmPerN[1], 1e-9);

    // Apply sends them.
    std::vector<TissuePreset> applied;
    QObject::connect(&panel, &ParameterPanel::applyRequested, [&](const TissuePreset& p) { applied.push_back(p); });
    panel.apply();
    ASSERT_EQ(applied.size(), 1u);
    EXPECT_NEAR(applied[0].model.slopeRing.slopeMagnitudeMmPerN[0], expected.params.slopeMagnitudeMmPerN[0], 1e-9);
    ASSERT_TRUE(applied[0].tissue.has_value());
    EXPECT_DOUBLE_EQ(applied[0].tissue->toolRadiusMm, 4.0);
}

TEST(TissueCalibration, BadPoissonRatioIsRejectedNamingTheField) {
    ParameterPanel panel;
    panel.setMeshProvider([] { return &stomach(); });
    const TissuePreset before = panel.preset();
    field(panel, "tissuePoissonRatioSpin")->setValue(0.6);
    EXPECT_FALSE(panel.isValid());
    ASSERT_FALSE(panel.problems().isEmpty());
    EXPECT_TRUE(panel.problems().join(QLatin1Char('\n')).contains(QStringLiteral("Poisson")))
        << panel.problems().join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(field(panel, "tissuePoissonRatioSpin")->property("invalid").toBool());
    EXPECT_FALSE(panel.findChild<QPushButton*>(QStringLiteral("applyButton"))->isEnabled());

    QString error;
    const int steps = panel.undoStack()->count();
    EXPECT_FALSE(panel.calibrateSlopes(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("Poisson"))) << error.toStdString();
    EXPECT_EQ(panel.undoStack()->count(), steps);  // nothing calibrated
    EXPECT_EQ(panel.preset().model.slopeRing.slopeMagnitudeMmPerN, before.model.slopeRing.slopeMagnitudeMmPerN);

    field(panel, "tissuePoissonRatioSpin")->setValue(0.45);
    field(panel, "tissueYoungsModulusKPaSpin")->setValue(0.0);
    EXPECT_TRUE(panel.problems().join(QLatin1Char('\n')).contains(QStringLiteral("Young's modulus")));
    field(panel, "tissueYoungsModulusKPaSpin")->setValue(4.34);
    field(panel, "tissueToolRadiusMmSpin")->setValue(0.0);
    EXPECT_TRUE(panel.problems().join(QLatin1Char('\n')).contains(QStringLiteral("tool radius")));
    field(panel, "tissueToolRadiusMmSpin")->setValue(5.0);
    EXPECT_TRUE(panel.isValid()) << panel.problems().join(QLatin1Char('\n')).toStdString();
}

TEST(TissueCalibration, WithoutAMeshCalibrateSaysSoAndChangesNothing) {
    ParameterPanel panel;
    QString error;
    EXPECT_FALSE(panel.calibrateSlopes(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("mesh"))) << error.toStdString();
    EXPECT_EQ(panel.undoStack()->count(), 0);
    EXPECT_TRUE(samePreset(panel.preset(), TissuePreset{}));
}

TEST(TissueCalibration, ShippedTissuePresetFillsTheTissueAndTheSlopes) {
    ParameterPanel panel;
    panel.setTissuePresetDirectory(QStringLiteral(PALPATE_SOURCE_DIR "/resources/presets/tissues"));
    auto* combo = panel.findChild<QComboBox*>(QStringLiteral("tissuePresetCombo"));
    ASSERT_NE(combo, nullptr);
    ASSERT_GE(combo->count(), 7);  // the placeholder and six tissues
    const int liver = combo->findText(QStringLiteral("Liver"));
    ASSERT_GT(liver, 0);
    EXPECT_TRUE(combo->itemData(liver, Qt::ToolTipRole).toString().contains(QStringLiteral("Source:")));

    combo->setCurrentIndex(liver);
    emit combo->activated(liver);
    const PresetLoadResult file = loadTissuePreset(combo->itemData(liver).toString().toStdString());
    ASSERT_TRUE(file.preset.has_value());
    EXPECT_DOUBLE_EQ(field(panel, "tissueYoungsModulusKPaSpin")->value(), 5.4);
    EXPECT_DOUBLE_EQ(field(panel, "tissuePoissonRatioSpin")->value(), 0.49);
    EXPECT_DOUBLE_EQ(field(panel, "tissueToolRadiusMmSpin")->value(), 5.0);
    for (int r = 0; r <= file.preset->model.slopeRing.ringCount; ++r)
        EXPECT_NEAR(slopeSpin(panel, r)->value(), file.preset->model.slopeRing.slopeMagnitudeMmPerN[std::size_t(r)], 1e-9);
    EXPECT_TRUE(panel.isValid()) << panel.problems().join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(combo->currentIndex(), liver);
    // Its source is kept while the values are the file's ...
    ASSERT_TRUE(panel.preset().tissue.has_value());
    EXPECT_EQ(panel.preset().tissue->source, file.preset->tissue->source);
    // ... and one undo brings back the default preset (placeholder shown).
    panel.undoAction()->trigger();
    EXPECT_TRUE(samePreset(panel.preset(), TissuePreset{}));
    EXPECT_EQ(combo->currentIndex(), 0);
}
