#pragma once
// A named camera of the project: where it stands, what it looks at, its
// field of view and clip planes.
#include <QWidget>

#include <functional>

class QDoubleSpinBox;
class QLineEdit;

namespace lpv::scene {
struct Camera;
}

namespace lpv::editor {

class Document;
class Vec3Edit;

class CameraProperties : public QWidget {
    Q_OBJECT
  public:
    explicit CameraProperties(Document* doc, QWidget* parent = nullptr);

    // -1 shows nothing.
    void setCameraIndex(int index);
    int cameraIndex() const { return index_; }
    void refresh();

  private:
    void edit(const QString& text, const std::function<void(scene::Camera&)>& change);

    Document* doc_;
    int index_ = -1;
    QLineEdit* name_ = nullptr;
    Vec3Edit* position_ = nullptr;
    Vec3Edit* target_ = nullptr;
    QDoubleSpinBox* fov_ = nullptr;
    QDoubleSpinBox* near_ = nullptr;
    QDoubleSpinBox* far_ = nullptr;
};

} // namespace lpv::editor
