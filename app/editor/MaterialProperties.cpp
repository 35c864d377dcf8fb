#include "MaterialProperties.h"

#include "Document.h"
#include "PropertyWidgets.h"

#include "lpv/scene/SceneFields.h"

#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace lpv::editor {

namespace {

struct TextureSlot {
    const char* label;
    std::string scene::Material::*path;
};

const std::array<TextureSlot, 9> kTextureSlots = {{
    {QT_TRANSLATE_NOOP("MaterialProperties", "Diffuse map"), &scene::Material::diffuseTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Normal map"), &scene::Material::normalTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Height map"), &scene::Material::heightTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Specular map"), &scene::Material::specularTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Metal/rough map"), &scene::Material::metallicRoughnessTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Occlusion map"), &scene::Material::occlusionTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Emissive map"), &scene::Material::emissiveTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Alpha map"), &scene::Material::alphaTexture},
    {QT_TRANSLATE_NOOP("MaterialProperties", "Environment map"), &scene::Material::environmentTexture},
}};

// A box for a table field in [0, 1].
template <class Field> QDoubleSpinBox* unitBox(QWidget* parent, const char* objectName, const Field& field) {
    QDoubleSpinBox* box = makeFieldSpinBox(field, 3, 0.05, {}, parent);
    box->setObjectName(objectName);
    return box;
}

} // namespace

MaterialProperties::MaterialProperties(Document* doc, QWidget* parent)
    : ElementPanel(doc, &scene::Scene::materials, &Document::setMaterial, parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* group = new QGroupBox(tr("Material"), this);
    form_ = new QFormLayout(group);
    layout->addWidget(group);

    name_ = new QLineEdit(group);
    name_->setObjectName("materialName");
    shading_ = new QLabel(group);
    shading_->setObjectName("materialShading");
    diffuse_ = new ColorButton(group);
    diffuse_->setObjectName("materialDiffuse");
    specular_ = new ColorButton(group);
    specular_->setObjectName("materialSpecular");
    shininess_ = makeFieldSpinBox(scene::fieldOf<&scene::Material::shininess>(), 1, 4.0, {}, group);
    shininess_->setObjectName("materialShininess");
    shininess_->setToolTip(tr("Blinn-Phong exponent: higher is a smaller, sharper highlight"));
    metallic_ = unitBox(group, "materialMetallic", scene::fieldOf<&scene::Material::metallic>());
    roughness_ = unitBox(group, "materialRoughness", scene::fieldOf<&scene::Material::roughness>());
    emissive_ = new ColorButton(group);
    emissive_->setObjectName("materialEmissive");
    emissiveStrength_ = makeSpinBox(0.0, 1.0e6, 3, 0.1, {}, group);
    emissiveStrength_->setObjectName("materialEmissiveStrength");
    emissiveStrength_->setToolTip(tr("Emitted radiance = colour × strength"));
    opacity_ = unitBox(group, "materialOpacity", scene::fieldOf<&scene::Material::opacity>());
    translucency_ = unitBox(group, "materialTranslucency", scene::fieldOf<&scene::Material::translucency>());
    translucency_->setToolTip(tr("Fraction of light that passes through the surface (subsurface LPV)"));
    glossiness_ = unitBox(group, "materialGlossiness", scene::fieldOf<&scene::Material::glossiness>());
    glossiness_->setToolTip(tr("0 = diffuse, 1 = mirror (glossy LPV reflections)"));
    twoSided_ = new QCheckBox(tr("Two-sided"), group);
    twoSided_->setObjectName("materialTwoSided");

    form_->addRow(tr("Name"), name_);
    form_->addRow(tr("Shading"), shading_);
    form_->addRow(tr("Diffuse"), diffuse_);
    form_->addRow(tr("Specular"), specular_);
    form_->addRow(tr("Shininess"), shininess_);
    form_->addRow(tr("Metallic"), metallic_);
    form_->addRow(tr("Roughness"), roughness_);
    form_->addRow(tr("Emissive"), emissive_);
    form_->addRow(tr("Emissive strength"), emissiveStrength_);
    form_->addRow(tr("Opacity"), opacity_);
    form_->addRow(tr("Translucency"), translucency_);
    form_->addRow(tr("Glossiness"), glossiness_);
    form_->addRow(QString(), twoSided_);

    auto* textures = new QGroupBox(tr("Textures"), this);
    texturesGroup_ = textures;
    textures_ = new QFormLayout(textures);
    for (std::size_t i = 0; i < kTextureSlots.size(); ++i) {
        auto* label = new QLabel(textures);
        label->setObjectName(QStringLiteral("materialTexture%1").arg(i));
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        textures_->addRow(tr(kTextureSlots[i].label), label);
        textureLabels_[i] = label;
    }
    layout->addWidget(textures);

    connect(name_, &QLineEdit::editingFinished, this, [this] {
        const std::string name = name_->text().toStdString();
        edit(tr("Rename material"), [&](scene::Material& m) { m.name = name; });
    });
    connect(diffuse_, &ColorButton::picked, this, &MaterialProperties::applyDiffuseColor);
    connect(specular_, &ColorButton::picked, this, &MaterialProperties::applySpecularColor);
    connect(emissive_, &ColorButton::picked, this, &MaterialProperties::applyEmissiveColor);
    auto field = [this](QDoubleSpinBox* box, const QString& text, float scene::Material::*member) {
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, text, member](double v) {
            edit(text, [&](scene::Material& m) { m.*member = float(v); });
        });
    };
    field(shininess_, tr("Edit material shininess"), &scene::Material::shininess);
    field(metallic_, tr("Edit material metallic"), &scene::Material::metallic);
    field(roughness_, tr("Edit material roughness"), &scene::Material::roughness);
    field(opacity_, tr("Edit material opacity"), &scene::Material::opacity);
    field(translucency_, tr("Edit material translucency"), &scene::Material::translucency);
    field(glossiness_, tr("Edit material glossiness"), &scene::Material::glossiness);
    connect(emissiveStrength_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        const glm::vec3 emissive = emissiveColor_ * float(v);
        edit(tr("Edit material emission"), [&](scene::Material& m) { m.emissive = emissive; });
    });
    connect(twoSided_, &QCheckBox::toggled, this, [this](bool on) {
        edit(tr("Toggle material two-sided"), [&](scene::Material& m) { m.twoSided = on; });
    });

    setIndex(-1);
}

void MaterialProperties::forgetLastElement() {
    emissiveColor_ = glm::vec3(1.0f);
}

void MaterialProperties::applyDiffuseColor(const QColor& color) {
    const glm::vec3 c = toVec3(color);
    edit(tr("Edit material diffuse colour"), [&](scene::Material& m) { m.diffuseColor = c; });
}

void MaterialProperties::applySpecularColor(const QColor& color) {
    const glm::vec3 c = toVec3(color);
    edit(tr("Edit material specular colour"), [&](scene::Material& m) { m.specularColor = c; });
}

void MaterialProperties::applyEmissiveColor(const QColor& color) {
    emissiveColor_ = toVec3(color);
    const glm::vec3 emissive = emissiveColor_ * float(emissiveStrength_->value());
    emissive_->showColor(color);
    edit(tr("Edit material emission"), [&](scene::Material& m) { m.emissive = emissive; });
}

void MaterialProperties::refresh() {
    const scene::Material* shown = shownElement();
    if (!shown) {
        showText(name_, {});
        shading_->clear();
        texturesGroup_->hide();
        return;
    }
    const scene::Material& m = *shown;
    showText(name_, QString::fromStdString(m.name));
    const bool pbr = m.shading == scene::ShadingModel::MetallicRoughness;
    shading_->setText(pbr ? tr("Metallic-roughness (glTF)") : tr("Blinn-Phong"));
    // Only the fields the shading model reads are shown.
    form_->setRowVisible(specular_, !pbr);
    form_->setRowVisible(shininess_, !pbr);
    form_->setRowVisible(metallic_, pbr);
    form_->setRowVisible(roughness_, pbr);

    diffuse_->showColor(toQColor(m.diffuseColor));
    specular_->showColor(toQColor(m.specularColor));
    showValue(shininess_, m.shininess);
    showValue(metallic_, m.metallic);
    showValue(roughness_, m.roughness);
    const float strength = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
    if (strength > 0.0f)
        emissiveColor_ = m.emissive / strength;
    emissive_->showColor(toQColor(emissiveColor_));
    showValue(emissiveStrength_, strength);
    showValue(opacity_, m.opacity);
    showValue(translucency_, m.translucency);
    showValue(glossiness_, m.glossiness);
    {
        const QSignalBlocker block(twoSided_);
        twoSided_->setChecked(m.twoSided);
    }
    refreshTextures(m);
}

void MaterialProperties::refreshTextures(const scene::Material& m) {
    const QString dir = doc_->projectDir();
    bool any = false;
    for (std::size_t i = 0; i < kTextureSlots.size(); ++i) {
        const std::string& path = m.*(kTextureSlots[i].path);
        textures_->setRowVisible(int(i), !path.empty());
        if (path.empty())
            continue;
        any = true;
        // Relative paths are relative to the project file; an unsaved project has no folder to look in.
        const QString p = QString::fromStdString(path);
        const QFileInfo info(p);
        const QString full = info.isAbsolute() ? p : dir.isEmpty() ? QString() : QDir(dir).filePath(p);
        const bool exists = !full.isEmpty() && QFileInfo::exists(full);
        QLabel* label = textureLabels_[i];
        label->setText(exists ? info.fileName() : tr("%1 (missing)").arg(info.fileName()));
        label->setStyleSheet(exists ? QString() : QStringLiteral("color: #d04040;"));
        label->setToolTip(full.isEmpty() ? p : QDir::toNativeSeparators(full));
    }
    texturesGroup_->setVisible(any);
}

} // namespace lpv::editor
