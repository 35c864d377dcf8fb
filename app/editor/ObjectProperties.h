#pragma once
// The selected object's name, visibility, transform, mesh and the materials
// of its submeshes. Choosing a submesh in the list tells the property panel
// which material to show below.
#include "ElementPanel.h"

#include <QWidget>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <functional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;

namespace lpv::editor {

class Vec3Edit;

class ObjectProperties : public ElementPanel<scene::Object> {
    Q_OBJECT
  public:
    explicit ObjectProperties(Document* doc, QWidget* parent = nullptr);
    void refresh() override;

    // The material of the submesh chosen in the list, or -1.
    int chosenMaterial() const;

  signals:
    void materialChosen(int materialIndex);

  private:
    void forgetLastElement() override;
    void editRotation(int axis, double degrees);
    void refreshMaterials();
    void announceMaterial();

    QLineEdit* name_ = nullptr;
    QCheckBox* visible_ = nullptr;
    Vec3Edit* translation_ = nullptr;
    Vec3Edit* rotation_ = nullptr;
    Vec3Edit* scale_ = nullptr;
    QLabel* meshInfo_ = nullptr;
    QListWidget* materials_ = nullptr;
    // The Euler angles the user typed, kept while the quaternion is the one
    // they produced: converting back would give an equivalent but different
    // triple (y = 100 reads back as 180/80/180) and make the fields jump.
    glm::dvec3 euler_{0.0};
    glm::quat eulerQuat_{1.0f, 0.0f, 0.0f, 0.0f};
    int eulerObject_ = -1;
    int announced_ = -1; // the material last sent with materialChosen
};

} // namespace lpv::editor
