#pragma once
// The properties of what is selected (Document::selection()): an object with
// the material of one of its submeshes, a material, a light, a camera, or the
// sky when nothing is selected. Every field edits through the Document, so
// each change is one undo step; the panel refreshes on Document::changed.
#include "Document.h"

#include <QWidget>

class QLabel;

namespace lpv::editor {

class CameraProperties;
class LightProperties;
class MaterialProperties;
class ObjectProperties;
class SkyProperties;

class PropertyPanel : public QWidget {
    Q_OBJECT
  public:
    explicit PropertyPanel(Document* doc, QWidget* parent = nullptr);

    ObjectProperties* objectProperties() const { return object_; }
    // Shown under the object (its chosen submesh's material) or alone (Selection::Kind::Material).
    MaterialProperties* materialProperties() const { return material_; }
    LightProperties* lightProperties() const { return light_; }
    CameraProperties* cameraProperties() const { return camera_; }
    SkyProperties* skyProperties() const { return sky_; }

  protected:
    void showEvent(QShowEvent* event) override;

  private:
    // Shows the pages for `selection` and refreshes them from the document.
    void showSelection(const Selection& selection);
    void refresh(Changes changes);

    Document* doc_;
    QLabel* title_ = nullptr;
    ObjectProperties* object_ = nullptr;
    MaterialProperties* material_ = nullptr;
    LightProperties* light_ = nullptr;
    CameraProperties* camera_ = nullptr;
    SkyProperties* sky_ = nullptr;
    QLabel* other_ = nullptr;
    bool stale_ = false; // a change arrived while hidden
};

} // namespace lpv::editor
