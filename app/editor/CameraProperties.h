#pragma once
// A named camera of the project: where it stands, what it looks at, its
// field of view and clip planes.
#include "ElementPanel.h"

#include <QWidget>

class QDoubleSpinBox;
class QLineEdit;

namespace lpv::editor {

class Vec3Edit;

class CameraProperties : public ElementPanel<scene::Camera> {
    Q_OBJECT
  public:
    explicit CameraProperties(Document* doc, QWidget* parent = nullptr);
    void refresh() override;

  private:
    QLineEdit* name_ = nullptr;
    Vec3Edit* position_ = nullptr;
    Vec3Edit* target_ = nullptr;
    QDoubleSpinBox* fov_ = nullptr;
    QDoubleSpinBox* near_ = nullptr;
    QDoubleSpinBox* far_ = nullptr;
};

} // namespace lpv::editor
