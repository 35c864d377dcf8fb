// The property panels edit through the Document: one undo step per edit,
// undo restores the element exactly, and the fields show the model back.
#include "PropertyPanel.h"
#include "CameraProperties.h"
#include "Document.h"
#include "LightProperties.h"
#include "MaterialProperties.h"
#include "ObjectProperties.h"
#include "PropertyWidgets.h"

#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ValueChecks.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QTemporaryDir>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

using namespace lpv;
using editor::Selection;

namespace {

class PropertyPanelTest : public ::testing::Test {
  protected:
    void SetUp() override {
        doc.reset(scene::makeCornellBoxProject(), QString());
        panel = std::make_unique<editor::PropertyPanel>(&doc);
        panel->show(); // a hidden panel defers its refreshes
    }
    QDoubleSpinBox* box(const char* name) const {
        auto* b = panel->findChild<QDoubleSpinBox*>(name);
        EXPECT_NE(b, nullptr) << name;
        return b;
    }
    QDoubleSpinBox* axis(const char* vec3Name, int axis) const {
        auto* v = panel->findChild<editor::Vec3Edit*>(vec3Name);
        EXPECT_NE(v, nullptr) << vec3Name;
        return v->box(axis);
    }
    int objectIndex(const std::string& name) const {
        const auto& objects = doc.scene().objects;
        for (std::size_t i = 0; i < objects.size(); ++i)
            if (objects[i].name == name)
                return int(i);
        ADD_FAILURE() << "no object " << name;
        return -1;
    }

    editor::Document doc;
    std::unique_ptr<editor::PropertyPanel> panel;
};

} // namespace

TEST_F(PropertyPanelTest, LightIntensityEditIsOneUndoStepAndUndoRestoresExactly) {
    doc.select({Selection::Kind::Light, 0});
    const scene::Light before = doc.scene().lights[0];
    QDoubleSpinBox* intensity = box("lightIntensity");
    ASSERT_TRUE(intensity->isVisibleTo(panel.get()));
    EXPECT_TRUE(intensity->suffix().contains("W/m²/sr")) << "the Cornell lamp is an area light given by its radiance";
    EXPECT_NEAR(intensity->value(), before.intensity, 1e-3);

    intensity->setValue(42.5);
    scene::Light expected = before;
    expected.intensity = 42.5f;
    EXPECT_EQ(doc.scene().lights[0], expected) << "only the intensity changed";
    EXPECT_EQ(doc.undoStack()->count(), 1);
    EXPECT_EQ(doc.undoStack()->undoText(), "Edit light intensity");

    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().lights[0], before);
    EXPECT_NEAR(intensity->value(), before.intensity, 1e-3) << "the field shows the undone value";
    EXPECT_EQ(doc.undoStack()->count(), 1) << "refreshing the field must not push an edit";
    EXPECT_EQ(doc.undoStack()->index(), 0);

    doc.undoStack()->redo();
    EXPECT_EQ(doc.scene().lights[0], expected);
    EXPECT_DOUBLE_EQ(intensity->value(), 42.5);
}

TEST_F(PropertyPanelTest, LightIntensityCannotGoNegative) {
    doc.select({Selection::Kind::Light, 0});
    QDoubleSpinBox* intensity = box("lightIntensity");
    intensity->setValue(-5.0);
    EXPECT_EQ(doc.scene().lights[0].intensity, 0.0f);
}

TEST_F(PropertyPanelTest, SunShowsIrradianceUnitAndHidesPosition) {
    scene::Light sun = doc.scene().lights[0];
    sun.type = scene::LightType::Directional;
    doc.setLight(0, sun, "make sun");
    doc.select({Selection::Kind::Light, 0});
    EXPECT_TRUE(box("lightIntensity")->suffix().contains("W/m²"));
    EXPECT_FALSE(panel->findChild<editor::Vec3Edit*>("lightPosition")->isVisibleTo(panel.get()));
    EXPECT_FALSE(box("lightOuterCone")->isVisibleTo(panel.get()));
    EXPECT_TRUE(box("lightElevation")->isVisibleTo(panel.get()));
}

TEST_F(PropertyPanelTest, LightDirectionFromAzimuthElevation) {
    doc.select({Selection::Kind::Light, 0});
    // The Cornell light points straight down: it comes from elevation 90.
    EXPECT_NEAR(box("lightElevation")->value(), 90.0, 1e-6);
    box("lightElevation")->setValue(45.0);
    box("lightAzimuth")->setValue(90.0);
    // Coming from +X, 45 degrees up: travelling towards -X and down.
    const glm::vec3 d = doc.scene().lights[0].direction;
    EXPECT_NEAR(d.x, -std::sqrt(0.5f), 1e-5);
    EXPECT_NEAR(d.y, -std::sqrt(0.5f), 1e-5);
    EXPECT_NEAR(d.z, 0.0f, 1e-5);
    EXPECT_EQ(doc.undoStack()->count(), 1) << "both angles within a second are one step";
}

TEST_F(PropertyPanelTest, SpotInnerConeIsBoundedByOuter) {
    scene::Light spot = doc.scene().lights[0];
    spot.type = scene::LightType::Spot;
    spot.innerConeAngle = 0.0f;
    spot.outerConeAngle = glm::radians(80.0f);
    doc.setLight(0, spot, "make spot");
    doc.select({Selection::Kind::Light, 0});
    EXPECT_TRUE(box("lightIntensity")->suffix().contains("W/sr"));
    QDoubleSpinBox* inner = box("lightInnerCone");
    QDoubleSpinBox* outer = box("lightOuterCone");
    EXPECT_NEAR(outer->value(), 80.0, 1e-3);
    inner->setValue(89.0);
    EXPECT_LE(doc.scene().lights[0].innerConeAngle, doc.scene().lights[0].outerConeAngle);
    outer->setValue(10.0);
    EXPECT_LE(doc.scene().lights[0].innerConeAngle, doc.scene().lights[0].outerConeAngle);
    EXPECT_NEAR(doc.scene().lights[0].outerConeAngle, glm::radians(80.0f), 1e-5)
        << "outer cannot go below inner";
}

TEST_F(PropertyPanelTest, TranslationMovesObjectAndWorldBounds) {
    const int index = objectIndex("shortBlock");
    doc.select({Selection::Kind::Object, index});
    const scene::Object before = doc.scene().objects[std::size_t(index)];
    const scene::Bounds meshBounds = doc.scene().meshes[std::size_t(before.mesh)].computeBounds();
    const float roomMaxX = doc.scene().worldBounds().max.x;
    ASSERT_GT(meshBounds.max.x + 10.0f, roomMaxX);

    axis("objectTranslation", 0)->setValue(10.0);
    scene::Object expected = before;
    expected.transform.translation.x = 10.0f;
    EXPECT_EQ(doc.scene().objects[std::size_t(index)], expected);
    // The block now sticks out of the room on +X: the scene's bounds grow with it.
    EXPECT_NEAR(doc.scene().worldBounds().max.x, meshBounds.max.x + 10.0f, 1e-4);
    EXPECT_GT(doc.scene().worldBounds().max.x, roomMaxX);
    EXPECT_EQ(doc.undoStack()->count(), 1);
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().objects[std::size_t(index)], before);
    EXPECT_EQ(doc.scene().worldBounds().max.x, roomMaxX);
}

TEST_F(PropertyPanelTest, EulerRotationGivesExpectedQuaternion) {
    const int index = objectIndex("tallBlock");
    doc.select({Selection::Kind::Object, index});
    axis("objectRotation", 0)->setValue(30.0);
    const glm::quat q = doc.scene().objects[std::size_t(index)].transform.rotation;
    const float half = glm::radians(15.0f);
    EXPECT_NEAR(q.w, std::cos(half), 1e-5);
    EXPECT_NEAR(q.x, std::sin(half), 1e-5);
    EXPECT_NEAR(q.y, 0.0f, 1e-5);
    EXPECT_NEAR(q.z, 0.0f, 1e-5);
    const glm::dvec3 back = editor::eulerDegrees(q);
    EXPECT_NEAR(back.x, 30.0, 1e-4);
    EXPECT_NEAR(back.y, 0.0, 1e-4);
    EXPECT_NEAR(back.z, 0.0, 1e-4);
    EXPECT_NEAR(axis("objectRotation", 0)->value(), 30.0, 1e-9);
}

TEST_F(PropertyPanelTest, EulerFieldsKeepWhatWasTyped) {
    const int index = objectIndex("tallBlock");
    doc.select({Selection::Kind::Object, index});
    // 100 degrees about Y reads back from the quaternion as 180/80/180 (glm
    // keeps Y within +-90); the fields must keep showing 0/100/0 while the
    // quaternion is the one typed.
    axis("objectRotation", 1)->setValue(100.0);
    EXPECT_NEAR(editor::eulerDegrees(doc.scene().objects[std::size_t(index)].transform.rotation).y, 80.0,
                1e-3)
        << "the premise: Y = 100 does not read back as typed";
    EXPECT_NEAR(axis("objectRotation", 0)->value(), 0.0, 1e-9);
    EXPECT_NEAR(axis("objectRotation", 1)->value(), 100.0, 1e-9);
    EXPECT_NEAR(axis("objectRotation", 2)->value(), 0.0, 1e-9);
    axis("objectRotation", 2)->setValue(20.0);
    const glm::quat expected = glm::quat(glm::radians(glm::vec3(0.0f, 100.0f, 20.0f)));
    const glm::quat q = doc.scene().objects[std::size_t(index)].transform.rotation;
    EXPECT_NEAR(std::abs(glm::dot(q, expected)), 1.0f, 1e-6);
    EXPECT_NEAR(axis("objectRotation", 1)->value(), 100.0, 1e-9);
    EXPECT_EQ(doc.undoStack()->count(), 1) << "a rotation typed axis by axis is one step";
    // An edit from elsewhere (undo) re-reads the angles from the quaternion.
    doc.undoStack()->undo();
    EXPECT_NEAR(axis("objectRotation", 1)->value(), 0.0, 1e-9);
    EXPECT_NEAR(axis("objectRotation", 2)->value(), 0.0, 1e-9);
}

TEST_F(PropertyPanelTest, ObjectListsSubmeshMaterialsAndEditsTheChosenOne) {
    const int room = objectIndex("room");
    doc.select({Selection::Kind::Object, room});
    auto* list = panel->findChild<QListWidget*>("objectMaterials");
    ASSERT_NE(list, nullptr);
    ASSERT_EQ(list->count(), 3); // white, red, green
    EXPECT_EQ(panel->materialProperties()->index(), 0) << "the first submesh's material";
    EXPECT_TRUE(panel->findChild<QLabel*>("objectMeshInfo")->text().contains("3 submeshes"));

    list->setCurrentRow(1);
    const int red = int(doc.scene()
                            .meshes[std::size_t(doc.scene().objects[std::size_t(room)].mesh)]
                            .submeshes[1]
                            .materialIndex);
    ASSERT_EQ(panel->materialProperties()->index(), red);
    const auto materialsBefore = doc.scene().materials;

    panel->materialProperties()->applyDiffuseColor(QColor::fromRgbF(0.25f, 0.5f, 0.75f));
    const glm::vec3 c = doc.scene().materials[std::size_t(red)].diffuseColor;
    EXPECT_NEAR(c.r, 0.25f, 1e-4);
    EXPECT_NEAR(c.g, 0.5f, 1e-4);
    EXPECT_NEAR(c.b, 0.75f, 1e-4);
    scene::Material expected = materialsBefore[std::size_t(red)];
    expected.diffuseColor = c;
    EXPECT_EQ(doc.scene().materials[std::size_t(red)], expected) << "only the diffuse colour changed";
    for (std::size_t i = 0; i < materialsBefore.size(); ++i) {
        if (int(i) == red)
            continue;
        EXPECT_EQ(doc.scene().materials[i], materialsBefore[i]);
    }
    EXPECT_EQ(doc.undoStack()->count(), 1);
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().materials, materialsBefore);
    EXPECT_EQ(list->currentRow(), 1) << "the chosen submesh survives the refresh";
}

TEST_F(PropertyPanelTest, MaterialSelectionEditsTranslucencyAndGlossiness) {
    doc.select({Selection::Kind::Material, 2});
    ASSERT_TRUE(panel->materialProperties()->isVisibleTo(panel.get()));
    const scene::Material before = doc.scene().materials[2];
    box("materialTranslucency")->setValue(0.4);
    box("materialGlossiness")->setValue(0.7);
    box("materialGlossiness")->setValue(1.5); // clamped to the range
    EXPECT_FLOAT_EQ(doc.scene().materials[2].translucency, 0.4f);
    EXPECT_FLOAT_EQ(doc.scene().materials[2].glossiness, 1.0f);
    EXPECT_EQ(doc.undoStack()->count(), 2) << "one step per field";
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().materials[2], before);
}

TEST_F(PropertyPanelTest, EmissiveStrengthScalesTheColour) {
    const auto& materials = doc.scene().materials;
    int light = -1;
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (materials[i].emissive != glm::vec3(0.0f))
            light = int(i);
    ASSERT_GE(light, 0);
    doc.select({Selection::Kind::Material, light});
    EXPECT_NEAR(box("materialEmissiveStrength")->value(), 17.0, 1e-3);
    box("materialEmissiveStrength")->setValue(34.0);
    const glm::vec3 e = doc.scene().materials[std::size_t(light)].emissive;
    EXPECT_NEAR(e.r, 34.0f, 1e-4);
    EXPECT_NEAR(e.g, 24.0f, 1e-4);
    EXPECT_NEAR(e.b, 8.0f, 1e-4);
}

TEST_F(PropertyPanelTest, TexturesShowFileNameAndMissingMarker) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QFile file(dir.filePath("brick.png"));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("not really a png");
    file.close();
    scene::Project project = scene::makeCornellBoxProject();
    project.scene.materials[0].diffuseTexture = "brick.png";
    project.scene.materials[0].normalTexture = "maps/gone_normal.png";
    doc.reset(std::move(project), dir.filePath("box.lpvproj"));
    doc.select({Selection::Kind::Material, 0});
    auto* diffuse = panel->findChild<QLabel*>("materialTexture0");
    auto* normal = panel->findChild<QLabel*>("materialTexture1");
    auto* height = panel->findChild<QLabel*>("materialTexture2");
    ASSERT_TRUE(diffuse && normal && height);
    EXPECT_EQ(diffuse->text(), "brick.png");
    EXPECT_TRUE(diffuse->isVisibleTo(panel.get()));
    EXPECT_EQ(normal->text(), "gone_normal.png (missing)");
    EXPECT_FALSE(height->isVisibleTo(panel.get())) << "empty slots are not listed";
}

TEST_F(PropertyPanelTest, CameraFieldOfViewInDegrees) {
    doc.select({Selection::Kind::Camera, 0});
    const scene::Camera before = doc.scene().cameras[0];
    EXPECT_NEAR(box("cameraFov")->value(), glm::degrees(double(before.fovY)), 0.01);
    box("cameraFov")->setValue(60.0);
    scene::Camera expected = before;
    expected.fovY = glm::radians(60.0f);
    EXPECT_NEAR(doc.scene().cameras[0].fovY, expected.fovY, 1e-6);
    expected.fovY = doc.scene().cameras[0].fovY;
    EXPECT_EQ(doc.scene().cameras[0], expected);
    // The near plane cannot be pushed past the far one.
    box("cameraNear")->setValue(1.0e6);
    EXPECT_LT(doc.scene().cameras[0].nearPlane, doc.scene().cameras[0].farPlane);
}

TEST_F(PropertyPanelTest, SkyShownWithoutSelection) {
    doc.select({});
    QDoubleSpinBox* intensity = box("skyIntensity");
    ASSERT_TRUE(intensity->isVisibleTo(panel.get()));
    EXPECT_FALSE(panel->objectProperties()->isVisibleTo(panel.get()));
    intensity->setValue(0.5);
    EXPECT_FLOAT_EQ(doc.scene().sky.intensity, 0.5f);
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().sky, scene::makeCornellBoxProject().scene.sky);
}

TEST_F(PropertyPanelTest, SelectionDroppedByUndoEmptiesThePanel) {
    doc.editScene("Add light", editor::Change::Lights,
                  [](scene::Scene& s) { s.lights.push_back(scene::Light{}); });
    doc.select({Selection::Kind::Light, 1});
    EXPECT_EQ(panel->lightProperties()->index(), 1);
    doc.undoStack()->undo(); // the light is gone; the document drops the selection
    EXPECT_EQ(panel->lightProperties()->index(), -1);
    EXPECT_TRUE(box("skyIntensity")->isVisibleTo(panel.get()));
}

TEST_F(PropertyPanelTest, AreaLightShowsItsShapeSizeAndUnit) {
    doc.select({Selection::Kind::Light, 0});
    const scene::Light before = doc.scene().lights[0];
    ASSERT_EQ(before.type, scene::LightType::Area);
    EXPECT_TRUE(box("lightAreaWidth")->isVisibleTo(panel.get()));
    EXPECT_FALSE(box("lightAreaRadius")->isVisibleTo(panel.get()));
    EXPECT_FALSE(box("lightOuterCone")->isVisibleTo(panel.get()));
    EXPECT_NEAR(box("lightAreaWidth")->value(), 1.3, 1e-4);
    box("lightAreaWidth")->setValue(2.0);
    EXPECT_FLOAT_EQ(doc.scene().lights[0].size.x, 2.0f);
    EXPECT_EQ(doc.undoStack()->undoText(), "Edit area light width");
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().lights[0], before);

    auto* shape = panel->findChild<QComboBox*>("lightAreaShape");
    ASSERT_NE(shape, nullptr);
    shape->setCurrentIndex(shape->findData(int(scene::AreaShape::Disc)));
    EXPECT_EQ(doc.scene().lights[0].shape, scene::AreaShape::Disc);
    EXPECT_TRUE(box("lightAreaRadius")->isVisibleTo(panel.get()));
    EXPECT_FALSE(box("lightAreaWidth")->isVisibleTo(panel.get()));
    auto* unit = panel->findChild<QComboBox*>("lightAreaUnit");
    ASSERT_NE(unit, nullptr);
    unit->setCurrentIndex(unit->findData(int(scene::AreaUnit::Power)));
    EXPECT_EQ(doc.scene().lights[0].unit, scene::AreaUnit::Power);
    EXPECT_TRUE(box("lightIntensity")->suffix().endsWith(" W"));
}

// Issue #42: an edit the project reader would refuse (a product of values
// that overflows, an up vector along the view) is not applied, and says why.
TEST_F(PropertyPanelTest, EditsThatASaveWouldRefuseAreNotAppliedAndSayWhy) {
    QStringList refused;
    QObject::connect(&doc, &editor::Document::editRefused, [&](const QString& m) { refused << m; });
    const scene::Scene before = doc.scene();
    scene::Light bright = before.lights[0];
    bright.intensity = 3.4e38f;
    doc.setLight(0, bright, "too bright");
    scene::Camera looksUp = before.cameras[0];
    looksUp.target = looksUp.position + glm::vec3(0, 1, 0);
    doc.setCamera(0, looksUp, "up along the view");
    EXPECT_EQ(doc.scene(), before);
    EXPECT_EQ(doc.undoStack()->count(), 0);
    ASSERT_EQ(refused.size(), 2);
    EXPECT_EQ(refused[0],
              "Light, intensity: the radiance (colour x intensity) is 3.39999995e+38, over 1e30: "
              "products kept under 1e30 leave 1e8 of float headroom for exposure, SH constants and "
              "sums over lights");
    EXPECT_TRUE(refused[1].startsWith("Camera, up: the up vector is parallel to the view direction"))
        << refused[1].toStdString();
    // A sound edit still goes through.
    scene::Light dimmer = before.lights[0];
    dimmer.intensity = 5.0f;
    doc.setLight(0, dimmer, "dimmer");
    EXPECT_EQ(doc.scene().lights[0].intensity, 5.0f);
}

// --- every scene field's box against the loader ------------------------------
// Every box the panels show for a scene field (its "sceneField" property
// names the table entry, SceneFields.h) is walked to each end and one step
// inside it: the project loader must take every scene the walk leaves
// (issue #44: the spot cone's box went down to 0 degrees, which the loader
// refuses, so a saved project would not open again).

namespace {

class SceneFieldWidgetsTest : public PropertyPanelTest {
  protected:
    // The loader's verdict on the document's scene as it stands.
    void expectLoadable(const std::string& what) {
        scene::Scene copy = doc.scene();
        const auto valid = scene::validateSceneContent(copy, "walk");
        EXPECT_TRUE(valid.has_value()) << what << ": " << (valid ? std::string() : valid.error().describe());
    }

    // Walks every visible field box of the panel; returns how many it walked.
    int walkBoxes(const std::string& page) {
        int walked = 0;
        QString refusal;
        const auto listening = QObject::connect(&doc, &editor::Document::editRefused,
                                                [&](const QString& why) { refusal = why; });
        const int startIndex = doc.undoStack()->index();
        for (QDoubleSpinBox* box : panel->findChildren<QDoubleSpinBox*>()) {
            const QVariant field = box->property("sceneField");
            if (!field.isValid() || !box->isVisibleTo(panel.get()))
                continue;
            ++walked;
            const double step = std::pow(10.0, -box->decimals());
            // Read each end afresh: a box's range follows the fields that bound it.
            const auto ends = [&] {
                return std::array<double, 4>{box->minimum(), box->minimum() + step, box->maximum() - step,
                                             box->maximum()};
            };
            for (int k = 0; k < 4; ++k) {
                const double v = ends()[std::size_t(k)];
                if (v < box->minimum() || v > box->maximum())
                    continue;
                const double shownBefore = box->value();
                const scene::Scene before = doc.scene();
                refusal.clear();
                box->setValue(v);
                // The Document refuses what its product checks refuse: a box must not offer that either.
                // Except the camera's vector rules (target off the position, up off the view
                // direction), which tie three vectors no range of one component can express.
                const bool vectorRule =
                    refusal.startsWith("Camera, up:") || refusal.startsWith("Camera, target:");
                if (float(box->value()) != float(shownBefore) && !vectorRule) // else nothing to store
                    EXPECT_FALSE(doc.scene() == before)
                        << page << " " << field.toString().toStdString() << " = " << box->value()
                        << ": the box offers it, the document refused it: " << refusal.toStdString();
                expectLoadable(page + " " + field.toString().toStdString() + " (" +
                               box->objectName().toStdString() + ") = " + std::to_string(box->value()));
            }
            // Each box from the page's first state, so one box's ends do not meet another's.
            doc.undoStack()->setIndex(startIndex);
        }
        QObject::disconnect(listening);
        return walked;
    }

    void setLight(scene::LightType type, scene::AreaShape shape = scene::AreaShape::Rectangle) {
        scene::Light l = doc.scene().lights[0];
        l.type = type;
        l.shape = shape;
        doc.setLight(0, l, "retype");
        doc.select({Selection::Kind::Light, 0});
    }
};

} // namespace

TEST_F(SceneFieldWidgetsTest, EveryLightBoxValueLoads) {
    for (const auto type : {scene::LightType::Spot, scene::LightType::Point, scene::LightType::Directional}) {
        setLight(type);
        EXPECT_GT(walkBoxes(scene::toString(type)), 0);
    }
    setLight(scene::LightType::Area, scene::AreaShape::Rectangle);
    EXPECT_GE(walkBoxes("area rectangle"), 4);
    setLight(scene::LightType::Area, scene::AreaShape::Disc);
    EXPECT_GE(walkBoxes("area disc"), 2);
}

TEST_F(SceneFieldWidgetsTest, EveryMaterialCameraObjectAndSkyBoxValueLoads) {
    doc.select({Selection::Kind::Material, 0});
    EXPECT_GE(walkBoxes("material (Blinn-Phong)"), 4);
    scene::Material pbr = doc.scene().materials[1];
    pbr.shading = scene::ShadingModel::MetallicRoughness;
    doc.setMaterial(1, pbr, "pbr");
    doc.select({Selection::Kind::Material, 1});
    EXPECT_GE(walkBoxes("material (metallic-roughness)"), 4);
    doc.select({Selection::Kind::Camera, 0});
    EXPECT_GE(walkBoxes("camera"), 9);
    doc.select({Selection::Kind::Object, 0});
    EXPECT_GE(walkBoxes("object"), 6);
    doc.select({});
    EXPECT_EQ(walkBoxes("sky"), 1);
}

// The case issue #44 found: 0 degrees, refused by the loader as outside (0, pi/2].
TEST_F(SceneFieldWidgetsTest, SpotConeBoxStopsAboveZero) {
    setLight(scene::LightType::Spot);
    QDoubleSpinBox* outer = panel->findChild<QDoubleSpinBox*>("lightOuterCone");
    ASSERT_NE(outer, nullptr);
    outer->setValue(0.0);
    EXPECT_GT(outer->minimum(), 0.0);
    EXPECT_GE(doc.scene().lights[0].outerConeAngle, float(scene::kMinSpotCone));
    expectLoadable("outer cone at its box's minimum");
}
