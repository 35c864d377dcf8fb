#pragma once
// One material's colours, textures (shown, with a marker for files that are
// not there) and surface parameters, including the LPV extensions'
// translucency and glossiness.
#include "ElementPanel.h"

#include <QWidget>

#include <glm/glm.hpp>

#include <array>
#include <functional>

class QCheckBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace lpv::editor {

class ColorButton;

class MaterialProperties : public ElementPanel<scene::Material> {
    Q_OBJECT
  public:
    explicit MaterialProperties(Document* doc, QWidget* parent = nullptr);
    void refresh() override;

  public slots:
    // What the colour buttons call once their dialog returns; public so a
    // test (or a future eyedropper) can set a colour without the modal dialog.
    void applyDiffuseColor(const QColor& color);
    void applySpecularColor(const QColor& color);
    void applyEmissiveColor(const QColor& color);

  private:
    void forgetLastElement() override;
    void refreshTextures(const scene::Material& m);

    QFormLayout* form_ = nullptr;
    QLineEdit* name_ = nullptr;
    QLabel* shading_ = nullptr;
    ColorButton* diffuse_ = nullptr;
    ColorButton* specular_ = nullptr;
    QDoubleSpinBox* shininess_ = nullptr;
    QDoubleSpinBox* metallic_ = nullptr;
    QDoubleSpinBox* roughness_ = nullptr;
    ColorButton* emissive_ = nullptr;
    QDoubleSpinBox* emissiveStrength_ = nullptr;
    QDoubleSpinBox* opacity_ = nullptr;
    QDoubleSpinBox* translucency_ = nullptr;
    QDoubleSpinBox* glossiness_ = nullptr;
    QCheckBox* twoSided_ = nullptr;
    QWidget* texturesGroup_ = nullptr;
    QFormLayout* textures_ = nullptr;
    std::array<QLabel*, 9> textureLabels_{};
    // The emissive colour is shown apart from its strength (emissive =
    // colour * strength); while the strength is 0 the colour the user chose
    // is kept here so raising the strength brings it back.
    glm::vec3 emissiveColor_{1.0f};
};

} // namespace lpv::editor
