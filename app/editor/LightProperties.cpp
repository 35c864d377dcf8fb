#include "LightProperties.h"

#include "Document.h"

#include "lpv/scene/SceneFields.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace lpv::editor {

namespace {
// The table entries of the fields this panel edits (SceneFields.h).
using scene::Light;
constexpr const auto& kIntensity = scene::fieldOf<&Light::intensity>();
constexpr const auto& kPosition = scene::fieldOf<&Light::position>();
constexpr const auto& kRange = scene::fieldOf<&Light::range>();
constexpr const auto& kInnerCone = scene::fieldOf<&Light::innerConeAngle>();
constexpr const auto& kOuterCone = scene::fieldOf<&Light::outerConeAngle>();
constexpr const auto& kSize = scene::fieldOf<&Light::size>();
constexpr const auto& kRadius = scene::fieldOf<&Light::radius>();
} // namespace

LightProperties::LightProperties(Document* doc, QWidget* parent)
    : ElementPanel(doc, &scene::Scene::lights, &Document::setLight, parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* group = new QGroupBox(tr("Light"), this);
    form_ = new QFormLayout(group);
    layout->addWidget(group);

    name_ = new QLineEdit(group);
    name_->setObjectName("lightName");
    type_ = new QComboBox(group);
    type_->setObjectName("lightType");
    type_->addItem(tr("Directional (sun)"), int(scene::LightType::Directional));
    type_->addItem(tr("Point"), int(scene::LightType::Point));
    type_->addItem(tr("Spot"), int(scene::LightType::Spot));
    type_->addItem(tr("Area"), int(scene::LightType::Area));
    color_ = new ColorButton(group);
    color_->setObjectName("lightColor");
    intensity_ = makeFieldSpinBox(kIntensity, 3, 0.1, {}, group);
    intensity_->setObjectName("lightIntensity");

    direction_ = new QWidget(group);
    auto* dirRow = new QHBoxLayout(direction_);
    dirRow->setContentsMargins(0, 0, 0, 0);
    azimuth_ = makeSpinBox(-360.0, 360.0, 2, 5.0, QStringLiteral("°"), direction_);
    azimuth_->setObjectName("lightAzimuth");
    azimuth_->setPrefix(tr("az "));
    elevation_ = makeSpinBox(-90.0, 90.0, 2, 5.0, QStringLiteral("°"), direction_);
    elevation_->setObjectName("lightElevation");
    elevation_->setPrefix(tr("el "));
    dirRow->addWidget(azimuth_, 1);
    dirRow->addWidget(elevation_, 1);
    direction_->setToolTip(tr("Where the light comes from: azimuth from +Z towards +X, elevation above the "
                              "horizon (90° = straight down from above)"));

    position_ = new Vec3Edit(kPosition, 3, 0.1, {}, group);
    position_->setObjectName("lightPosition");
    range_ = makeFieldSpinBox(kRange, 3, 0.5, QStringLiteral(" m"), group);
    range_->setObjectName("lightRange");
    range_->setSpecialValueText(tr("unlimited"));
    // Cone angles are half-angles from the axis, as in glTF; 90° is a hemisphere.
    innerCone_ = makeFieldSpinBox(kInnerCone, 2, 1.0, QStringLiteral("°"), group, Shown::Degrees);
    innerCone_->setObjectName("lightInnerCone");
    innerCone_->setToolTip(tr("Full intensity inside this angle from the axis"));
    outerCone_ = makeFieldSpinBox(kOuterCone, 2, 1.0, QStringLiteral("°"), group, Shown::Degrees);
    outerCone_->setObjectName("lightOuterCone");
    outerCone_->setToolTip(tr("No light outside this angle from the axis"));
    castShadows_ = new QCheckBox(tr("Cast shadows"), group);
    castShadows_->setObjectName("lightCastShadows");
    areaShape_ = new QComboBox(group);
    areaShape_->setObjectName("lightAreaShape");
    areaShape_->addItem(tr("Rectangle"), int(scene::AreaShape::Rectangle));
    areaShape_->addItem(tr("Disc"), int(scene::AreaShape::Disc));
    areaWidth_ = makeFieldSpinBox(kSize, 4, 0.05, QStringLiteral(" m"), group);
    areaWidth_->setObjectName("lightAreaWidth");
    areaHeight_ = makeFieldSpinBox(kSize, 4, 0.05, QStringLiteral(" m"), group);
    areaHeight_->setObjectName("lightAreaHeight");
    areaRadius_ = makeFieldSpinBox(kRadius, 4, 0.05, QStringLiteral(" m"), group);
    areaRadius_->setObjectName("lightAreaRadius");
    areaUnit_ = new QComboBox(group);
    areaUnit_->setObjectName("lightAreaUnit");
    areaUnit_->addItem(tr("Radiance (W/m²/sr)"), int(scene::AreaUnit::Radiance));
    areaUnit_->addItem(tr("Power (W)"), int(scene::AreaUnit::Power));
    areaTwoSided_ = new QCheckBox(tr("Emits from both sides"), group);
    areaTwoSided_->setObjectName("lightAreaTwoSided");

    form_->addRow(tr("Name"), name_);
    form_->addRow(tr("Type"), type_);
    form_->addRow(tr("Colour"), color_);
    form_->addRow(tr("Intensity"), intensity_);
    form_->addRow(tr("Direction"), direction_);
    form_->addRow(tr("Position"), position_);
    form_->addRow(tr("Range"), range_);
    form_->addRow(tr("Inner cone"), innerCone_);
    form_->addRow(tr("Outer cone"), outerCone_);
    form_->addRow(tr("Shape"), areaShape_);
    form_->addRow(tr("Width"), areaWidth_);
    form_->addRow(tr("Height"), areaHeight_);
    form_->addRow(tr("Radius"), areaRadius_);
    form_->addRow(tr("Intensity is"), areaUnit_);
    form_->addRow(QString(), areaTwoSided_);
    form_->addRow(QString(), castShadows_);

    connect(name_, &QLineEdit::editingFinished, this, [this] {
        const std::string name = name_->text().toStdString();
        edit(tr("Rename light"), [&](scene::Light& l) { l.name = name; });
    });
    connect(type_, &QComboBox::currentIndexChanged, this, [this] {
        const auto type = scene::LightType(type_->currentData().toInt());
        edit(tr("Change light type"), [&](scene::Light& l) { l.type = type; });
    });
    connect(color_, &ColorButton::picked, this, &LightProperties::applyColor);
    connect(intensity_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(tr("Edit light intensity"), [&](scene::Light& l) { l.intensity = float(v); });
    });
    connect(azimuth_, &QDoubleSpinBox::valueChanged, this, &LightProperties::editDirection);
    connect(elevation_, &QDoubleSpinBox::valueChanged, this, &LightProperties::editDirection);
    connect(position_, &Vec3Edit::edited, this, [this](int axis, double v) {
        edit(tr("Edit light position"), [&](scene::Light& l) { l.position[axis] = float(v); });
    });
    connect(range_, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { edit(tr("Edit light range"), [&](scene::Light& l) { l.range = float(v); }); });
    connect(innerCone_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        // The boxes' ranges keep inner <= outer at their display precision; this keeps it exactly.
        edit(tr("Edit spot inner cone"), [&](Light& l) {
            kInnerCone.of(l) = rangeGivenOthers(l, kInnerCone.name).clamp(storedValue(v, Shown::Degrees));
        });
    });
    connect(outerCone_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(tr("Edit spot outer cone"), [&](Light& l) {
            kOuterCone.of(l) = rangeGivenOthers(l, kOuterCone.name).clamp(storedValue(v, Shown::Degrees));
        });
    });
    connect(areaShape_, &QComboBox::currentIndexChanged, this, [this] {
        const auto shape = scene::AreaShape(areaShape_->currentData().toInt());
        edit(tr("Change area light shape"), [&](scene::Light& l) { l.shape = shape; });
    });
    connect(areaWidth_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(tr("Edit area light width"), [&](scene::Light& l) { l.size.x = float(v); });
    });
    connect(areaHeight_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(tr("Edit area light height"), [&](scene::Light& l) { l.size.y = float(v); });
    });
    connect(areaRadius_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(tr("Edit area light radius"), [&](scene::Light& l) { l.radius = float(v); });
    });
    connect(areaUnit_, &QComboBox::currentIndexChanged, this, [this] {
        const auto unit = scene::AreaUnit(areaUnit_->currentData().toInt());
        edit(tr("Change area light unit"), [&](scene::Light& l) { l.unit = unit; });
    });
    connect(areaTwoSided_, &QCheckBox::toggled, this, [this](bool on) {
        edit(tr("Toggle two-sided area light"), [&](scene::Light& l) { l.twoSided = on; });
    });
    connect(castShadows_, &QCheckBox::toggled, this, [this](bool on) {
        edit(tr("Toggle light shadows"), [&](scene::Light& l) { l.castShadows = on; });
    });

    setIndex(-1);
}

void LightProperties::forgetLastElement() {
    anglesLight_ = -1;
}

void LightProperties::applyColor(const QColor& color) {
    const glm::vec3 c = toVec3(color);
    edit(tr("Edit light colour"), [&](scene::Light& l) { l.color = c; });
}

void LightProperties::editDirection() {
    angles_ = {azimuth_->value(), elevation_->value()};
    anglesDirection_ = directionFrom(angles_);
    anglesLight_ = index();
    const glm::vec3 d = anglesDirection_;
    edit(tr("Edit light direction"), [&](scene::Light& l) { l.direction = d; });
}

void LightProperties::refresh() {
    const scene::Light* shown = shownElement();
    if (!shown) {
        showText(name_, {});
        return;
    }
    const scene::Light& l = *shown;
    showText(name_, QString::fromStdString(l.name));
    {
        const QSignalBlocker block(type_);
        type_->setCurrentIndex(type_->findData(int(l.type)));
    }
    const bool directional = l.type == scene::LightType::Directional;
    const bool spot = l.type == scene::LightType::Spot;
    const bool area = l.type == scene::LightType::Area;
    const bool disc = area && l.shape == scene::AreaShape::Disc;
    form_->setRowVisible(direction_, directional || spot || area);
    form_->setRowVisible(position_, !directional);
    form_->setRowVisible(range_, !directional && !area);
    form_->setRowVisible(innerCone_, spot);
    form_->setRowVisible(outerCone_, spot);
    form_->setRowVisible(areaShape_, area);
    form_->setRowVisible(areaWidth_, area && !disc);
    form_->setRowVisible(areaHeight_, area && !disc);
    form_->setRowVisible(areaRadius_, disc);
    form_->setRowVisible(areaUnit_, area);
    form_->setRowVisible(areaTwoSided_, area);

    color_->showColor(toQColor(l.color));
    // Light.h: irradiance for a sun, radiant intensity for point and spot lights, radiance or power for area lights.
    const bool power = area && l.unit == scene::AreaUnit::Power;
    intensity_->setSuffix(directional ? tr(" W/m²") : !area ? tr(" W/sr") : power ? tr(" W") : tr(" W/m²/sr"));
    intensity_->setToolTip(directional ? tr("Irradiance on a surface facing the sun")
                           : !area     ? tr("Radiant intensity (power per solid angle)")
                           : power     ? tr("The power the light emits in all")
                                       : tr("The radiance leaving its emitting side"));
    showValue(intensity_, l.intensity);
    if (area) {
        const QSignalBlocker blockShape(areaShape_), blockUnit(areaUnit_), blockSides(areaTwoSided_);
        areaShape_->setCurrentIndex(areaShape_->findData(int(l.shape)));
        areaUnit_->setCurrentIndex(areaUnit_->findData(int(l.unit)));
        areaTwoSided_->setChecked(l.twoSided);
        showValue(areaWidth_, l.size.x);
        showValue(areaHeight_, l.size.y);
        showValue(areaRadius_, l.radius);
    }

    if (anglesLight_ != index() || anglesDirection_ != l.direction) {
        angles_ = azimuthElevationOf(l.direction);
        anglesDirection_ = l.direction;
        anglesLight_ = index();
    }
    showValue(azimuth_, angles_.azimuth);
    showValue(elevation_, angles_.elevation);
    position_->showValue(glm::dvec3(l.position));
    showValue(range_, l.range);
    {
        // Each cone bounds the other (SceneFields.h's rule), so the inner one can never exceed the outer one.
        const QSignalBlocker blockInner(innerCone_);
        const QSignalBlocker blockOuter(outerCone_);
        setFieldRange(innerCone_, kInnerCone.widgetRange(), Shown::Degrees);
        setFieldRange(outerCone_, kOuterCone.widgetRange(), Shown::Degrees);
        showValue(innerCone_, shownValue(kInnerCone.of(l), Shown::Degrees));
        showValue(outerCone_, shownValue(kOuterCone.of(l), Shown::Degrees));
        setFieldRange(innerCone_, kInnerCone.widgetRange().within(rangeGivenOthers(l, kInnerCone.name)),
                      Shown::Degrees);
        setFieldRange(outerCone_, kOuterCone.widgetRange().within(rangeGivenOthers(l, kOuterCone.name)),
                      Shown::Degrees);
    }
    {
        const QSignalBlocker block(castShadows_);
        castShadows_->setChecked(l.castShadows);
    }
}

} // namespace lpv::editor
