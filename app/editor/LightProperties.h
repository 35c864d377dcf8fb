#pragma once
// A light's type, colour, intensity (with its unit), placement and shadows.
// Directions are shown as azimuth/elevation of where the light comes from.
#include "PropertyWidgets.h"

#include "ElementPanel.h"

#include <QWidget>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLineEdit;

namespace lpv::editor {

class LightProperties : public ElementPanel<scene::Light> {
    Q_OBJECT
  public:
    explicit LightProperties(Document* doc, QWidget* parent = nullptr);
    void refresh() override;

  public slots:
    // What the colour button calls once its dialog returns.
    void applyColor(const QColor& color);

  private:
    void forgetLastElement() override;
    void editDirection();

    QFormLayout* form_ = nullptr;
    QLineEdit* name_ = nullptr;
    QComboBox* type_ = nullptr;
    ColorButton* color_ = nullptr;
    QDoubleSpinBox* intensity_ = nullptr;
    QDoubleSpinBox* azimuth_ = nullptr;
    QDoubleSpinBox* elevation_ = nullptr;
    QWidget* direction_ = nullptr;
    Vec3Edit* position_ = nullptr;
    QDoubleSpinBox* range_ = nullptr;
    QDoubleSpinBox* innerCone_ = nullptr;
    QDoubleSpinBox* outerCone_ = nullptr;
    QCheckBox* castShadows_ = nullptr;
    // Area lights only.
    QComboBox* areaShape_ = nullptr;
    QDoubleSpinBox* areaWidth_ = nullptr;
    QDoubleSpinBox* areaHeight_ = nullptr;
    QDoubleSpinBox* areaRadius_ = nullptr;
    QComboBox* areaUnit_ = nullptr;
    QCheckBox* areaTwoSided_ = nullptr;
    // The angles the user set, kept while the direction is the one they
    // produced: at elevation ±90° the azimuth cannot be read back.
    AzimuthElevation angles_;
    glm::vec3 anglesDirection_{0.0f};
    int anglesLight_ = -1;
};

} // namespace lpv::editor
