#pragma once
// One material's colours, textures (shown, with a marker for files that are
// not there) and surface parameters, including the LPV extensions'
// translucency and glossiness.
#include <QWidget>

#include <glm/glm.hpp>

#include <array>
#include <functional>

class QCheckBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace lpv::scene {
struct Material;
}

namespace lpv::editor {

class ColorButton;
class Document;

class MaterialProperties : public QWidget {
    Q_OBJECT
  public:
    explicit MaterialProperties(Document* doc, QWidget* parent = nullptr);

    // -1 shows nothing.
    void setMaterialIndex(int index);
    int materialIndex() const { return index_; }
    void refresh();

  public slots:
    // What the colour buttons call once their dialog returns; public so a
    // test (or a future eyedropper) can set a colour without the modal dialog.
    void applyDiffuseColor(const QColor& color);
    void applySpecularColor(const QColor& color);
    void applyEmissiveColor(const QColor& color);

  private:
    void edit(const QString& text, const std::function<void(scene::Material&)>& change);
    void refreshTextures(const scene::Material& m);

    Document* doc_;
    int index_ = -1;
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
