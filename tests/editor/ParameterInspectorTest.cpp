// The parameter inspector, driven through its real widgets as a user would:
// every registry parameter has an editor of the right kind that reports
// edits with exactly the value shown and shows what setParameters() gives it
// without reporting an edit.
#include "ParameterInspector.h"

#include "lpv/scene/ParameterRegistry.h"

#include <QAbstractSlider>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QTextDocumentFragment>
#include <QToolButton>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <cmath>

using lpv::editor::ParameterEditor;
using lpv::editor::ParameterInspector;
using lpv::scene::ParameterInfo;
using lpv::scene::ParameterRegistry;
using lpv::scene::ParameterSet;
using lpv::scene::ParameterType;
using lpv::scene::ParameterValue;

namespace {

const ParameterRegistry& registry() {
    return ParameterRegistry::instance();
}

QString qKey(const ParameterInfo& p) {
    return QString::fromStdString(p.key);
}

std::string describe(const ParameterValue& v) {
    static const char* kTypes[] = {"bool", "int", "double", "string"};
    return std::string(kTypes[v.index()]) + " " + lpv::scene::formatValue(v);
}

// The arguments of one parameterEdited emission.
struct Edit {
    QString key;
    ParameterValue value;
};

Edit editAt(const QSignalSpy& spy, qsizetype i) {
    return {spy.at(i).at(0).toString(), spy.at(i).at(1).value<ParameterValue>()};
}

// Two values in range other than `avoid` (for bool: only one exists).
ParameterValue otherInt(const ParameterInfo& p, int avoid) {
    const int lo = static_cast<int>(p.minValue);
    const int hi = static_cast<int>(p.maxValue);
    const int mid = lo + (hi - lo) / 3;
    return mid != avoid ? mid : mid + 1;
}

// The check box of a Float parameter's word ("auto"), beside its spin box `w`.
QCheckBox* wordBox(QWidget* w) {
    return w->parentWidget() ? w->parentWidget()->findChild<QCheckBox*>() : nullptr;
}

// Changes the editor of `p` to a value other than its current one, through
// the widget, as a click, a typed value or a pick would; returns the value
// now shown (for floats, as rounded by the spin box).
ParameterValue editLikeAUser(QWidget* w, const ParameterInfo& p, double fraction) {
    switch (p.type) {
    case ParameterType::Bool: {
        auto* check = qobject_cast<QCheckBox*>(w);
        check->click();
        return check->isChecked();
    }
    case ParameterType::Int: {
        auto* spin = qobject_cast<QSpinBox*>(w);
        const int lo = static_cast<int>(p.minValue);
        const int hi = static_cast<int>(p.maxValue);
        int v = lo + static_cast<int>(std::lround((hi - lo) * fraction));
        if (v == spin->value())
            v = v == hi ? lo : v + 1;
        spin->setValue(v);
        return spin->value();
    }
    case ParameterType::Float: {
        auto* spin = qobject_cast<QDoubleSpinBox*>(w);
        if (QCheckBox* word = wordBox(w); word && word->isChecked()) {
            word->click(); // from "auto" to the number beside it: one edit
            return spin->value();
        }
        double v = p.minValue + (p.maxValue - p.minValue) * fraction;
        if (std::abs(spin->valueFromText(spin->textFromValue(v)) - spin->value()) < 1e-12)
            v = p.maxValue;
        spin->setValue(v);
        return spin->value();
    }
    case ParameterType::Enum: {
        auto* combo = qobject_cast<QComboBox*>(w);
        const int next = (combo->currentIndex() + 1) % combo->count();
        combo->setCurrentIndex(next);
        return combo->currentText().toStdString();
    }
    }
    return false;
}

// What the widget shows, in the registry's type.
ParameterValue shown(QWidget* w, const ParameterInfo& p) {
    switch (p.type) {
    case ParameterType::Bool:
        return qobject_cast<QCheckBox*>(w)->isChecked();
    case ParameterType::Int:
        return qobject_cast<QSpinBox*>(w)->value();
    case ParameterType::Float:
        if (QCheckBox* word = wordBox(w); word && word->isChecked())
            return word->text().toStdString();
        return qobject_cast<QDoubleSpinBox*>(w)->value();
    case ParameterType::Enum:
        return qobject_cast<QComboBox*>(w)->currentText().toStdString();
    }
    return false;
}

QString plainToolTip(const QWidget* w) {
    return QTextDocumentFragment::fromHtml(w->toolTip()).toPlainText();
}

} // namespace

TEST(ParameterInspector, EveryParameterHasAnEditorThatRoundTripsItsValue) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    QSignalSpy resets(&inspector, &ParameterInspector::parameterResetRequested);
    ASSERT_FALSE(registry().all().empty());
    for (const ParameterInfo& p : registry().all()) {
        SCOPED_TRACE(p.key);
        QWidget* w = inspector.editorFor(qKey(p));
        ASSERT_NE(w, nullptr) << "no editor";

        // The right widget for the type, limited to the declared range.
        switch (p.type) {
        case ParameterType::Bool:
            ASSERT_NE(qobject_cast<QCheckBox*>(w), nullptr);
            break;
        case ParameterType::Int: {
            auto* spin = qobject_cast<QSpinBox*>(w);
            ASSERT_NE(spin, nullptr);
            EXPECT_EQ(spin->minimum(), static_cast<int>(p.minValue));
            EXPECT_EQ(spin->maximum(), static_cast<int>(p.maxValue));
            break;
        }
        case ParameterType::Float: {
            auto* spin = qobject_cast<QDoubleSpinBox*>(w);
            ASSERT_NE(spin, nullptr);
            EXPECT_DOUBLE_EQ(spin->minimum(), p.minValue);
            EXPECT_DOUBLE_EQ(spin->maximum(), p.maxValue);
            EXPECT_NE(inspector.parameterEditor(qKey(p))->slider(), nullptr) << "finite ranges get a slider";
            break;
        }
        case ParameterType::Enum: {
            auto* combo = qobject_cast<QComboBox*>(w);
            ASSERT_NE(combo, nullptr);
            ASSERT_EQ(combo->count(), static_cast<int>(p.enumValues.size()));
            for (int i = 0; i < combo->count(); ++i)
                EXPECT_EQ(combo->itemText(i).toStdString(), p.enumValues[static_cast<std::size_t>(i)]);
            break;
        }
        }
        // It starts at the default, exactly.
        EXPECT_EQ(shown(w, p), p.defaultValue) << describe(shown(w, p));
        EXPECT_FALSE(inspector.parameterEditor(qKey(p))->resetButton()->isEnabled());

        // A user edit reports exactly the value the widget now shows, once.
        edits.clear();
        const ParameterValue edited = editLikeAUser(w, p, 0.3);
        ASSERT_NE(edited, p.defaultValue) << describe(edited);
        ASSERT_EQ(edits.count(), 1);
        const Edit e = editAt(edits, 0);
        EXPECT_EQ(e.key, qKey(p));
        // A Float whose default is a word ("auto") is edited to a number.
        const bool wordDefault = p.type == ParameterType::Float && !p.enumValues.empty();
        EXPECT_EQ(e.value.index(), wordDefault ? ParameterValue(0.0).index() : p.defaultValue.index())
            << "type: " << describe(e.value);
        EXPECT_EQ(e.value, edited) << describe(e.value) << " vs " << describe(edited);
        EXPECT_TRUE(registry().validate(p.key, e.value, "test")) << "the value is in range";
        if (p.type == ParameterType::Float && !wordDefault) {
            // Within the precision the spin box shows.
            const double target = p.minValue + (p.maxValue - p.minValue) * 0.3;
            const double precision = std::pow(10.0, -qobject_cast<QDoubleSpinBox*>(w)->decimals());
            if (std::get<double>(e.value) != p.maxValue) {
                EXPECT_NEAR(std::get<double>(e.value), target, precision / 2 + 1e-12);
            }
        }
        EXPECT_TRUE(inspector.parameterEditor(qKey(p))->resetButton()->isEnabled());
        EXPECT_TRUE(inspector.labelFor(qKey(p))->font().bold()) << "a modified value is marked";

        // setParameters() shows another value and reports no edit.
        ParameterSet values;
        ParameterValue other;
        switch (p.type) {
        case ParameterType::Bool:
            other = !std::get<bool>(edited);
            break;
        case ParameterType::Int:
            other = otherInt(p, std::get<int>(edited));
            break;
        case ParameterType::Float:
            other = p.minValue + (p.maxValue - p.minValue) * 0.75;
            break;
        case ParameterType::Enum: {
            const auto& names = p.enumValues;
            other = names[(std::size_t(std::find(names.begin(), names.end(), std::get<std::string>(edited)) -
                                       names.begin()) +
                           1) %
                          names.size()];
            break;
        }
        }
        ASSERT_NE(other, edited);
        ASSERT_TRUE(values.set(p.key, other, "test"));
        edits.clear();
        inspector.setParameters(values);
        EXPECT_EQ(edits.count(), 0) << "setParameters must not report edits";
        EXPECT_EQ(inspector.parameterEditor(qKey(p))->value(), other);
        if (p.type == ParameterType::Float) {
            const double precision = std::pow(10.0, -qobject_cast<QDoubleSpinBox*>(w)->decimals());
            EXPECT_NEAR(std::get<double>(shown(w, p)), std::get<double>(other), precision / 2 + 1e-12);
        } else {
            EXPECT_EQ(shown(w, p), other) << describe(shown(w, p));
        }
        EXPECT_EQ(inspector.parameterEditor(qKey(p))->resetButton()->isEnabled(), other != p.defaultValue);

        // And back to all defaults.
        inspector.setParameters(ParameterSet{});
        EXPECT_EQ(shown(w, p), p.defaultValue);
        EXPECT_FALSE(inspector.labelFor(qKey(p))->font().bold());
    }
    EXPECT_EQ(edits.count(), 0);
    EXPECT_EQ(resets.count(), 0);
}

TEST(ParameterInspector, SettingEveryParameterAtOnceReportsNoEdit) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    ParameterSet values;
    for (const ParameterInfo& p : registry().all()) {
        ParameterValue v;
        switch (p.type) {
        case ParameterType::Bool:
            v = !std::get<bool>(p.defaultValue);
            break;
        case ParameterType::Int:
            v = static_cast<int>(p.maxValue);
            break;
        case ParameterType::Float:
            v = p.maxValue;
            break;
        case ParameterType::Enum:
            v = p.enumValues.back() != std::get<std::string>(p.defaultValue) ? p.enumValues.back()
                                                                             : p.enumValues.front();
            break;
        }
        ASSERT_TRUE(values.set(p.key, v, "test"));
    }
    inspector.setParameters(values);
    EXPECT_EQ(edits.count(), 0);
    for (const ParameterInfo& p : registry().all()) {
        SCOPED_TRACE(p.key);
        EXPECT_EQ(inspector.parameterEditor(qKey(p))->value(), values.get(p.key));
        EXPECT_EQ(shown(inspector.editorFor(qKey(p)), p), values.get(p.key));
    }
}

TEST(ParameterInspector, KeyboardStepsAndTypedValuesAreEdits) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    auto* steps = qobject_cast<QSpinBox*>(inspector.editorFor("lpv.propagationSteps"));
    ASSERT_NE(steps, nullptr);
    steps->setFocus();
    QTest::keyClick(steps, Qt::Key_Up);
    ASSERT_EQ(edits.count(), 1);
    EXPECT_EQ(editAt(edits, 0).value, ParameterValue(9));

    // A typed number is one edit, on Enter, not one per keystroke.
    edits.clear();
    steps->selectAll();
    QTest::keyClicks(steps, "16");
    EXPECT_EQ(edits.count(), 0);
    QTest::keyClick(steps, Qt::Key_Return);
    ASSERT_EQ(edits.count(), 1);
    EXPECT_EQ(editAt(edits, 0).value, ParameterValue(16));
    EXPECT_EQ(steps->text(), "16 steps");
}

// Scrolling the panel with the wheel must not change the values that pass under the mouse.
TEST(ParameterInspector, TheWheelChangesOnlyAFocusedEditor) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    auto* steps = qobject_cast<QSpinBox*>(inspector.editorFor("lpv.propagationSteps"));
    const auto wheel = [&](QWidget* w) {
        const QPointF at(w->width() / 2.0, w->height() / 2.0);
        QWheelEvent event(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(w, &event);
    };
    wheel(steps);
    wheel(inspector.parameterEditor("lpv.propagationSteps")->slider());
    EXPECT_EQ(edits.count(), 0);
    EXPECT_EQ(steps->value(), 8);

    inspector.activateWindow();
    steps->setFocus();
    if (!QTest::qWaitFor([&] { return steps->hasFocus(); }, 1000))
        GTEST_SKIP() << "this platform gives no focus";
    wheel(steps);
    ASSERT_EQ(edits.count(), 1);
    EXPECT_EQ(steps->value(), 9);
}

TEST(ParameterInspector, SliderDragEmitsEveryStepAndKeepsSpinBoxInStep) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    ParameterEditor* offset = inspector.parameterEditor("lpv.injectionOffset"); // [0, 4] cells
    ASSERT_NE(offset, nullptr);
    QAbstractSlider* slider = offset->slider();
    ASSERT_NE(slider, nullptr);
    auto* spin = qobject_cast<QDoubleSpinBox*>(offset->input());

    ASSERT_EQ(slider->value(), std::lround(slider->maximum() * 0.875 / 4.0)) << "the default, 0.875 cells";
    slider->setSliderDown(true);
    slider->setValue(slider->maximum() / 2);
    slider->setValue(slider->maximum() * 3 / 4);
    ASSERT_EQ(edits.count(), 2) << "continuous edits while dragging";
    EXPECT_EQ(editAt(edits, 0).value, ParameterValue(2.0));
    EXPECT_EQ(editAt(edits, 1).value, ParameterValue(3.0));
    EXPECT_DOUBLE_EQ(spin->value(), 3.0) << "immediate feedback in the spin box";

    // The holder of the values answers with setParameters; the slider stays under the mouse.
    ParameterSet values;
    ASSERT_TRUE(values.set("lpv.injectionOffset", 2.97));
    inspector.setParameters(values);
    EXPECT_EQ(slider->value(), slider->maximum() * 3 / 4);
    EXPECT_DOUBLE_EQ(spin->value(), 2.97);
    slider->setSliderDown(false);
    EXPECT_EQ(edits.count(), 2);

    // The spin box moves the slider along without a second edit.
    edits.clear();
    spin->setValue(1.5);
    EXPECT_EQ(edits.count(), 1);
    EXPECT_EQ(slider->value(), slider->maximum() * 3 / 8);
}

TEST(ParameterInspector, WideRangesGetALogarithmicSlider) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    const ParameterInfo* cell = registry().find("lpv.cellSize"); // auto, or [1e-6, 1e6] m
    ASSERT_NE(cell, nullptr);
    auto* spin = qobject_cast<QDoubleSpinBox*>(inspector.editorFor("lpv.cellSize"));
    wordBox(spin)->click(); // off auto: the number is used
    edits.clear();
    QAbstractSlider* slider = inspector.parameterEditor("lpv.cellSize")->slider();
    ASSERT_NE(slider, nullptr);
    slider->setValue(slider->maximum() / 4);
    ASSERT_EQ(edits.count(), 1);
    // A quarter of the way on a log scale: 1e-6 * (1e12)^0.25 = 1e-3.
    EXPECT_NEAR(std::get<double>(editAt(edits, 0).value), std::pow(cell->minValue, 0.75) * std::pow(cell->maxValue, 0.25),
                1e-5);
    EXPECT_GE(spin->decimals(), 6) << "the minimum, 1 micrometre, must be reachable";
    auto* threshold = qobject_cast<QDoubleSpinBox*>(inspector.editorFor("radiosity.convergenceThreshold"));
    EXPECT_GE(threshold->decimals(), 5);
    EXPECT_EQ(threshold->stepType(), QAbstractSpinBox::AdaptiveDecimalStepType);
}

TEST(ParameterInspector, SearchFiltersByKeyLabelAndDescription) {
    ParameterInspector inspector;
    inspector.show();
    QTest::keyClicks(inspector.searchField(), "propagation");
    EXPECT_TRUE(inspector.matchesFilter("lpv.propagationSteps"));
    EXPECT_FALSE(inspector.matchesFilter("shadow.mapSize"));
    EXPECT_TRUE(inspector.editorFor("lpv.propagationSteps")->isVisibleTo(&inspector));
    EXPECT_FALSE(inspector.editorFor("shadow.mapSize")->isVisibleTo(&inspector));
    EXPECT_FALSE(inspector.labelFor("shadow.mapSize")->isVisibleTo(&inspector));
    EXPECT_FALSE(inspector.groupHeader("Shadows")->isVisibleTo(&inspector))
        << "a group without matches hides";
    EXPECT_TRUE(inspector.groupHeader("LPV")->isVisibleTo(&inspector));

    // By label ("Map size"), by a word of the description, case-insensitive, all words must match.
    inspector.setFilter("MAP SIZE");
    EXPECT_EQ(inspector.searchField()->text(), "MAP SIZE");
    EXPECT_TRUE(inspector.matchesFilter("shadow.mapSize"));
    EXPECT_FALSE(inspector.matchesFilter("lpv.propagationSteps"));
    inspector.setFilter("shimmer");
    EXPECT_TRUE(inspector.matchesFilter("shadow.stabilize"));
    EXPECT_FALSE(inspector.matchesFilter("shadow.mapSize"));
    inspector.setFilter("rsm.tile");
    EXPECT_TRUE(inspector.matchesFilter("rsm.tileSize"));
    EXPECT_FALSE(inspector.matchesFilter("rsm.cascades"));

    // Matches show even in a collapsed group; clearing brings back everything.
    inspector.setFilter("");
    inspector.setGroupExpanded("Shadows", false);
    EXPECT_FALSE(inspector.editorFor("shadow.mapSize")->isVisibleTo(&inspector));
    inspector.setFilter("shadow map");
    EXPECT_TRUE(inspector.editorFor("shadow.mapSize")->isVisibleTo(&inspector));
    inspector.searchField()->clear();
    for (const ParameterInfo& p : registry().all())
        EXPECT_TRUE(inspector.matchesFilter(qKey(p))) << p.key;
    EXPECT_FALSE(inspector.editorFor("shadow.mapSize")->isVisibleTo(&inspector)) << "still collapsed";
    EXPECT_TRUE(inspector.editorFor("lpv.propagationSteps")->isVisibleTo(&inspector));

    inspector.setFilter("no such thing anywhere");
    for (const QString& group : inspector.groups())
        EXPECT_FALSE(inspector.groupHeader(group)->isVisibleTo(&inspector)) << group.toStdString();
}

TEST(ParameterInspector, GroupsFollowTheIssueOrderAndCollapse) {
    ParameterInspector inspector;
    inspector.show();
    const QStringList groups = inspector.groups();
    ASSERT_GE(groups.size(), 4);
    EXPECT_EQ(groups.first(), "LPV");
    EXPECT_LT(groups.indexOf("RSM"), groups.indexOf("Shadows"));
    EXPECT_LT(groups.indexOf("Shadows"), groups.indexOf("Effects"));
    for (const ParameterInfo& p : registry().all())
        EXPECT_TRUE(groups.contains(QString::fromStdString(p.group))) << p.key;

    QToolButton* header = inspector.groupHeader("LPV");
    EXPECT_TRUE(inspector.editorFor("lpv.gridSize")->isVisibleTo(&inspector));
    header->click();
    EXPECT_FALSE(inspector.isGroupExpanded("LPV"));
    EXPECT_FALSE(inspector.editorFor("lpv.gridSize")->isVisibleTo(&inspector));
    header->click();
    EXPECT_TRUE(inspector.editorFor("lpv.gridSize")->isVisibleTo(&inspector));
}

TEST(ParameterInspector, ResetButtonRequestsTheDefaultAndIsDisabledAtIt) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    QSignalSpy resets(&inspector, &ParameterInspector::parameterResetRequested);
    for (const char* key : {"lpv.propagationSteps", "lpv.cellSize", "lpv.occlusion", "output.tonemapper"}) {
        SCOPED_TRACE(key);
        const ParameterInfo& p = *registry().find(key);
        ParameterEditor* editor = inspector.parameterEditor(key);
        EXPECT_FALSE(editor->resetButton()->isEnabled()) << "disabled at the default";

        editLikeAUser(editor->input(), p, 0.8);
        EXPECT_TRUE(editor->resetButton()->isEnabled());
        edits.clear();
        resets.clear();
        editor->resetButton()->click();
        ASSERT_EQ(resets.count(), 1);
        EXPECT_EQ(resets.at(0).at(0).toString(), key);
        EXPECT_EQ(edits.count(), 0) << "a reset is not also an edit";
        EXPECT_EQ(editor->value(), p.defaultValue) << "shown at once";
        EXPECT_EQ(shown(editor->input(), p), p.defaultValue);
        EXPECT_FALSE(editor->resetButton()->isEnabled());
    }

    // A value set explicitly to the default is at the default.
    ParameterSet values;
    ASSERT_TRUE(values.set("lpv.propagationSteps", 8));
    inspector.setParameters(values);
    EXPECT_FALSE(inspector.parameterEditor("lpv.propagationSteps")->resetButton()->isEnabled());
    ASSERT_TRUE(values.set("lpv.propagationSteps", 9));
    inspector.setParameter("lpv.propagationSteps", 9);
    EXPECT_TRUE(inspector.parameterEditor("lpv.propagationSteps")->resetButton()->isEnabled());
}

TEST(ParameterInspector, ToolTipsCarryDescriptionUnitKeyAndDefault) {
    ParameterInspector inspector;
    inspector.show();
    for (const ParameterInfo& p : registry().all()) {
        SCOPED_TRACE(p.key);
        const QString tip = plainToolTip(inspector.editorFor(qKey(p)));
        EXPECT_TRUE(tip.contains(QString::fromStdString(p.description))) << tip.toStdString();
        EXPECT_TRUE(tip.contains(qKey(p))) << tip.toStdString();
        EXPECT_TRUE(tip.contains("Default: ")) << tip.toStdString();
        if (!p.unit.empty()) {
            EXPECT_TRUE(tip.contains(lpv::editor::parameterUnit(p))) << tip.toStdString();
        }
        EXPECT_EQ(plainToolTip(inspector.labelFor(qKey(p))), tip);
    }
    const QString steps = plainToolTip(inspector.editorFor("lpv.propagationSteps"));
    EXPECT_TRUE(steps.contains("Default: 8 steps")) << steps.toStdString();
    EXPECT_TRUE(steps.contains("Range: 0 steps to 64 steps")) << steps.toStdString();
    const QString area = plainToolTip(inspector.editorFor("radiosity.maxPatchArea"));
    EXPECT_TRUE(area.contains(QString::fromUtf8("m\u00b2"))) << area.toStdString();
    EXPECT_EQ(qobject_cast<QDoubleSpinBox*>(inspector.editorFor("radiosity.maxPatchArea"))->suffix(),
              QString::fromUtf8(" m\u00b2"));
}

TEST(ParameterInspector, LabelsAreReadable) {
    ParameterInspector inspector;
    inspector.show();
    EXPECT_EQ(inspector.labelFor("lpv.propagationSteps")->text(), "Propagation steps");
    EXPECT_EQ(inspector.labelFor("lpv.gvFromCamera")->text(), "GV from camera");
    EXPECT_EQ(inspector.labelFor("shadow.mapSize")->text(), "Map size");
    EXPECT_EQ(inspector.labelFor("lpv.propagationSteps")->buddy(),
              inspector.editorFor("lpv.propagationSteps"));
    EXPECT_EQ(inspector.editorFor("no.suchKey"), nullptr);
}

// lpv.cellSize = auto (issue #41): a check box beside the number. On, the
// number is greyed out and the value is the word; off, the number is used;
// a project's number unticks it.
TEST(ParameterInspector, AFloatThatAdmitsAutoHasACheckBoxForIt) {
    ParameterInspector inspector;
    inspector.show();
    QSignalSpy edits(&inspector, &ParameterInspector::parameterEdited);
    QWidget* spin = inspector.editorFor("lpv.cellSize");
    ASSERT_NE(spin, nullptr);
    QCheckBox* word = wordBox(spin);
    ASSERT_NE(word, nullptr);
    EXPECT_EQ(word->text(), "auto");
    EXPECT_TRUE(word->isChecked());
    EXPECT_FALSE(spin->isEnabled());
    // The greyed box says what is used, not the range's minimum ("0.000001 m", issue #46).
    EXPECT_EQ(qobject_cast<QDoubleSpinBox*>(spin)->text().toStdString(), "auto");
    EXPECT_EQ(inspector.parameterEditor("lpv.cellSize")->value(), ParameterValue(std::string("auto")));

    word->click();
    ASSERT_EQ(edits.count(), 1);
    EXPECT_TRUE(spin->isEnabled());
    const ParameterValue number = editAt(edits, 0).value;
    ASSERT_TRUE(std::holds_alternative<double>(number));
    EXPECT_TRUE(registry().validate("lpv.cellSize", number, "test"));

    qobject_cast<QDoubleSpinBox*>(spin)->setValue(0.3);
    ASSERT_EQ(edits.count(), 2);
    EXPECT_DOUBLE_EQ(std::get<double>(editAt(edits, 1).value), 0.3);
    word->click();
    ASSERT_EQ(edits.count(), 3);
    EXPECT_EQ(editAt(edits, 2).value, ParameterValue(std::string("auto")));
    EXPECT_FALSE(spin->isEnabled());

    ParameterSet values;
    ASSERT_TRUE(values.set("lpv.cellSize", 0.125, "test"));
    inspector.setParameters(values);
    EXPECT_EQ(edits.count(), 3) << "setParameters must not report edits";
    EXPECT_FALSE(word->isChecked());
    EXPECT_DOUBLE_EQ(qobject_cast<QDoubleSpinBox*>(spin)->value(), 0.125);
    EXPECT_NE(qobject_cast<QDoubleSpinBox*>(spin)->text().toStdString(), "auto");
    inspector.setParameters(ParameterSet{});
    EXPECT_TRUE(word->isChecked());
    EXPECT_EQ(qobject_cast<QDoubleSpinBox*>(spin)->text().toStdString(), "auto");
}
