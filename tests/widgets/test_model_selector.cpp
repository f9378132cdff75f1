// The Parameters panel's model selector (docs/models.md): every registry model is listed, slope-ring
// methods first, each with a tooltip; the chosen model's own fields are shown and validated by
// name; Apply switches the haptic session's model, and undo goes back. Offscreen, stepped loop;
// main() is in test_viewport.cpp.
#include "base/resources/ShippedResources.h"
#include "app/gui/HapticSession.h"
#include "widgets/ParameterCommands.h"
#include "widgets/ParameterPanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace palpate;

namespace {

QComboBox* modelCombo(ParameterPanel& panel) { return panel.findChild<QComboBox*>(QStringLiteral("modelCombo")); }

void choose(ParameterPanel& panel, const char* name) {
    QComboBox* combo = modelCombo(panel);
    const int index = combo->findData(QString::fromLatin1(name));
    ASSERT_GE(index, 0) << name;
    combo->setCurrentIndex(index);
}

bool shown(ParameterPanel& panel, const char* objectName) {
    auto* w = panel.findChild<QWidget*>(QString::fromLatin1(objectName));
    return w && w->isVisibleTo(&panel);
}

}  // namespace

TEST(ModelSelector, ListsEveryModelSlopeRingMethodsFirstWithTooltips) {
    ParameterPanel panel;
    QComboBox* combo = modelCombo(panel);
    ASSERT_TRUE(combo);
    int lastSlopeRing = -1, firstOther = combo->count();
    for (const std::string& name : modelNames()) {
        const int index = combo->findData(QString::fromStdString(name));
        ASSERT_GE(index, 0) << name << " is not listed";
        EXPECT_FALSE(combo->itemText(index).isEmpty()) << name;
        const QString tip = combo->itemData(index, Qt::ToolTipRole).toString();
        EXPECT_TRUE(tip.contains(QStringLiteral("Cost"))) << name << ": " << tip.toStdString();
        if (modelDefForName(name)->kind == ModelKind::SlopeRing)
            lastSlopeRing = std::max(lastSlopeRing, index);
        else
            firstOther = std::min(firstOther, index);
    }
    EXPECT_LT(lastSlopeRing, firstOther) << "slope-ring methods first, then the others";
}

TEST(ModelSelector, ShowsTheChosenModelsOwnFieldsAndNamesBadOnes) {
    ParameterPanel panel;
    EXPECT_TRUE(shown(panel, "slopeGroup"));
    EXPECT_FALSE(shown(panel, "modelParamsGroup"));

    choose(panel, "radius-of-influence");
    EXPECT_TRUE(shown(panel, "radiusOfInfluenceRadiusMmSpin"));
    EXPECT_TRUE(shown(panel, "radiusOfInfluenceDegreeSpin"));
    EXPECT_FALSE(shown(panel, "ffdControlPointsPerAxisSpin"));
    EXPECT_FALSE(shown(panel, "slopeGroup"));
    EXPECT_EQ(presetModelName(panel.preset()), "radius-of-influence");

    auto* radius = panel.findChild<QDoubleSpinBox*>(QStringLiteral("radiusOfInfluenceRadiusMmSpin"));
    ASSERT_TRUE(radius);
    radius->setValue(0.0);
    EXPECT_FALSE(panel.isValid());
    ASSERT_FALSE(panel.problems().isEmpty());
    EXPECT_TRUE(panel.problems().join(QLatin1Char('\n')).contains(QStringLiteral("radiusMm")))
        << panel.problems().join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(radius->property("invalid").toBool());
    radius->setValue(12.5);
    EXPECT_TRUE(panel.isValid()) << panel.problems().join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(panel.preset().model.radiusOfInfluence.radiusMm, 12.5);

    choose(panel, "mass-spring-local");
    EXPECT_TRUE(shown(panel, "massSpringLocalRingCountSpin"));
    EXPECT_TRUE(shown(panel, "massSpringLocalIntegratorCombo"));
    choose(panel, "mass-spring-rk4");
    EXPECT_TRUE(shown(panel, "massSpringEdgeStiffnessNPerMmSpin"));
    EXPECT_FALSE(shown(panel, "massSpringLocalRingCountSpin"));
    choose(panel, "ffd");
    auto* moved = panel.findChild<QSpinBox*>(QStringLiteral("ffdMovedPerAxisSpin"));
    ASSERT_TRUE(moved && moved->isVisibleTo(&panel));
    moved->setValue(9);  // more than the 8 control points per axis
    EXPECT_FALSE(panel.isValid());
    EXPECT_TRUE(panel.problems().join(QLatin1Char('\n')).contains(QStringLiteral("movedPerAxis")));
    moved->setValue(4);
    choose(panel, "volumetric-rings");
    EXPECT_TRUE(shown(panel, "slopeGroup"));
    EXPECT_FALSE(shown(panel, "modelParamsGroup"));
    EXPECT_TRUE(panel.isValid());

    // Each choice and edit is one undo step; undoing them all goes back to the start.
    while (panel.undoStack()->canUndo()) panel.undoStack()->undo();
    EXPECT_EQ(presetModelName(panel.preset()), "coherent");
    EXPECT_EQ(panel.preset().model.radiusOfInfluence.radiusMm, RadiusOfInfluenceParams{}.radiusMm);
    EXPECT_TRUE(shown(panel, "slopeGroup"));
}

TEST(ModelSelector, ApplySwitchesTheSessionsModelAndUndoGoesBack) {
    const std::string meshPath = findResource(kDefaultMesh);
    ASSERT_FALSE(meshPath.empty()) << "resources/" << kDefaultMesh << " not found";
    HapticSession session(LoopMode::Stepped);
    ASSERT_EQ(session.loadMesh(meshPath), "");
    session.step(1);
    EXPECT_EQ(session.loopModelName(), "slope-ring/coherent");

    ParameterPanel panel;
    panel.setPreset(session.preset());
    std::vector<std::string> applyErrors;
    QObject::connect(&panel, &ParameterPanel::applyRequested,
                     [&](const TissuePreset& preset) { applyErrors.push_back(session.applyPreset(preset)); });

    choose(panel, "radius-of-influence");
    ASSERT_TRUE(panel.isValid()) << panel.problems().join(QLatin1Char('\n')).toStdString();
    auto* apply = panel.findChild<QPushButton*>(QStringLiteral("applyButton"));
    ASSERT_TRUE(apply);
    QTest::mouseClick(apply, Qt::LeftButton);
    ASSERT_EQ(applyErrors, std::vector<std::string>{""});
    EXPECT_EQ(session.preset().model.kind, ModelKind::RadiusOfInfluence);

    // A fresh press on the new scene: the stepped snapshot shows contact and a dent.
    ASSERT_EQ(session.setDevice("sim:press"), "");
    bool contact = false, switched = false;
    for (int i = 0; i < 4000 && !contact; ++i) {
        session.step(1);
        if (session.observe() == HapticSession::Observation::SceneSwitched) switched = true;
        contact = switched && session.observed().contact && session.observed().displacedCount > 0;
    }
    EXPECT_TRUE(switched);
    EXPECT_EQ(session.loopModelName(), "radius-of-influence");
    EXPECT_TRUE(contact) << "no contact under the press with radius-of-influence";
    EXPECT_GT(session.observed().displacedCount, 1u) << "the radius moves more than the touched vertex";

    // Undo: the panel shows the slope-ring model again, and Apply sends it back to the session.
    panel.undoStack()->undo();
    EXPECT_EQ(presetModelName(panel.preset()), "coherent");
    QTest::mouseClick(apply, Qt::LeftButton);
    ASSERT_EQ(applyErrors.size(), 2u);
    EXPECT_EQ(applyErrors[1], "");
    session.step(2);
    session.observe();
    EXPECT_EQ(session.loopModelName(), "slope-ring/coherent");
    panel.undoStack()->redo();
    EXPECT_EQ(presetModelName(panel.preset()), "radius-of-influence");
}
