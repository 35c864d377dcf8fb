// The preset bar lists the project's presets and turns clicks into requests.
#include "PresetBar.h"

#include <QComboBox>
#include <QInputDialog>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

using lpv::editor::PresetBar;
using lpv::scene::ParameterPreset;

namespace {

std::vector<ParameterPreset> presets(std::initializer_list<const char*> names) {
    std::vector<ParameterPreset> out;
    for (const char* name : names)
        out.push_back(ParameterPreset{name, {}});
    return out;
}

} // namespace

TEST(PresetBar, ListsPresetsAndDisablesWhatNeedsOne) {
    PresetBar bar;
    bar.show();
    EXPECT_EQ(bar.currentIndex(), -1);
    EXPECT_FALSE(bar.applyButton()->isEnabled());
    EXPECT_FALSE(bar.deleteButton()->isEnabled());
    EXPECT_TRUE(bar.saveButton()->isEnabled()) << "the current parameters can always be saved";

    auto list = presets({"thesis", "fast"});
    ASSERT_TRUE(list[1].parameters.set("lpv.propagationSteps", 4));
    bar.setPresets(list);
    ASSERT_EQ(bar.presetCombo()->count(), 2);
    EXPECT_EQ(bar.presetCombo()->itemText(0), "thesis");
    EXPECT_EQ(bar.presetCombo()->itemText(1), "fast");
    EXPECT_EQ(bar.currentIndex(), 0);
    EXPECT_TRUE(bar.applyButton()->isEnabled());
    EXPECT_TRUE(bar.deleteButton()->isEnabled());
    EXPECT_EQ(bar.presetCombo()->itemData(1, Qt::ToolTipRole).toString(), "lpv.propagationSteps = 4");

    bar.setPresets({});
    EXPECT_EQ(bar.currentIndex(), -1);
    EXPECT_FALSE(bar.applyButton()->isEnabled());
}

TEST(PresetBar, ApplyAndDeleteRequestTheSelectedIndex) {
    PresetBar bar;
    bar.show();
    bar.setPresets(presets({"a", "b", "c"}));
    QSignalSpy applied(&bar, &PresetBar::presetApplyRequested);
    QSignalSpy deleted(&bar, &PresetBar::presetDeleteRequested);
    bar.presetCombo()->setCurrentIndex(2);
    bar.applyButton()->click();
    ASSERT_EQ(applied.count(), 1);
    EXPECT_EQ(applied.at(0).at(0).toInt(), 2);
    bar.presetCombo()->setCurrentIndex(1);
    bar.deleteButton()->click();
    ASSERT_EQ(deleted.count(), 1);
    EXPECT_EQ(deleted.at(0).at(0).toInt(), 1);
    EXPECT_EQ(applied.count(), 1) << "requests only; the bar changes nothing itself";
    EXPECT_EQ(bar.presetCombo()->count(), 3);
}

TEST(PresetBar, SelectionFollowsTheNameAcrossUpdates) {
    PresetBar bar;
    bar.setPresets(presets({"a", "b", "c"}));
    bar.setCurrentIndex(2);
    bar.setPresets(presets({"c", "a"})); // "b" deleted and the list reordered
    EXPECT_EQ(bar.currentIndex(), 0);
    EXPECT_EQ(bar.presetCombo()->currentText(), "c");
}

TEST(PresetBar, SaveAsksForANameAndSelectsTheNewPreset) {
    PresetBar bar;
    bar.show();
    bar.setPresets(presets({"thesis"}));
    QSignalSpy saved(&bar, &PresetBar::presetSaveRequested);

    bar.saveButton()->click();
    QInputDialog* dialog = bar.saveDialog();
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->textValue(), "Preset 2") << "an unused name is suggested";
    EXPECT_TRUE(dialog->comboBoxItems().contains("thesis")) << "existing names can be picked to replace one";
    dialog->setTextValue("  warm sun  ");
    dialog->accept();
    ASSERT_EQ(saved.count(), 1);
    EXPECT_EQ(saved.at(0).at(0).toString(), "warm sun");

    // The holder adds it; the bar selects it.
    bar.setPresets(presets({"thesis", "warm sun"}));
    EXPECT_EQ(bar.currentIndex(), 1);

    // A blank name or a cancelled dialog requests nothing.
    bar.saveButton()->click();
    ASSERT_NE(bar.saveDialog(), nullptr);
    bar.saveDialog()->setTextValue("   ");
    bar.saveDialog()->accept();
    bar.saveButton()->click();
    ASSERT_NE(bar.saveDialog(), nullptr);
    bar.saveDialog()->reject();
    EXPECT_EQ(saved.count(), 1);
}
