#pragma once
// Small building blocks shared by the property panels: a three-component
// number editor, a colour swatch button, and the angle conversions the panels
// show instead of raw quaternions and vectors.
#include <QColor>
#include <QPushButton>
#include <QWidget>

#include "lpv/scene/Scene.h"
#include "lpv/scene/SceneField.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <functional>
#include <utility>
#include <vector>

class QDoubleSpinBox;
class QLineEdit;

namespace lpv::editor {

// A spin box set up the way every property field wants it: emits only when a
// value is committed (Enter, focus out, arrows, wheel), not on each keystroke,
// so typing "12" makes one edit, not two.
QDoubleSpinBox* makeSpinBox(double min, double max, int decimals, double step, const QString& suffix = {},
                            QWidget* parent = nullptr);
// Shows a model value without emitting an edit; leaves the box alone when it
// already shows that value (so a refresh does not reset the cursor of a box
// being edited).
void showValue(QDoubleSpinBox* box, double value);

// Boxes for scene fields take their range from the field's table entry
// (SceneFields.h), so they cannot offer a value the project loader refuses.
// An angle stored in radians may be shown in degrees.
enum class Shown { AsStored, Degrees };
double shownValue(double stored, Shown shown);
float storedValue(double shownValue, Shown shown);
// The box's ends at `decimals`: an open end, or one that rounding moved
// outside the range, moves inward by one step of the last decimal.
std::pair<double, double> spinBoxBounds(const scene::FieldRange& range, Shown shown, int decimals);
void setFieldRange(QDoubleSpinBox* box, const scene::FieldRange& range, Shown shown = Shown::AsStored);
// The box of a table field, its property "sceneField" naming the field
// (the tests walk every box by it).
QDoubleSpinBox* makeFieldSpinBox(const char* field, const scene::FieldRange& range, int decimals, double step,
                                 const QString& suffix = {}, QWidget* parent = nullptr,
                                 Shown shown = Shown::AsStored);
template <class S, class T>
QDoubleSpinBox* makeFieldSpinBox(const scene::Field<S, T>& field, int decimals, double step,
                                 const QString& suffix = {}, QWidget* parent = nullptr,
                                 Shown shown = Shown::AsStored) {
    return makeFieldSpinBox(field.name, field.widgetRange(), decimals, step, suffix, parent, shown);
}
void showText(QLineEdit* edit, const QString& text);

// One edit of the selected element of a scene list (`doc->scene().*list`):
// a copy changed by `change` and handed to the Document's setter, which makes
// it one undo step; nothing when `index` selects no element.
template <class Doc, class T>
void editElement(Doc* doc, std::vector<T> scene::Scene::*list,
                 void (Doc::*set)(int, const T&, const QString&), int index, const QString& text,
                 const std::function<void(T&)>& change) {
    const std::vector<T>& elements = doc->scene().*list;
    if (index < 0 || std::size_t(index) >= elements.size())
        return;
    T element = elements[std::size_t(index)];
    change(element);
    (doc->*set)(index, element, text);
}

// Three spin boxes in a row (x, y, z) for positions, rotations and scales.
class Vec3Edit : public QWidget {
    Q_OBJECT
  public:
    Vec3Edit(double min, double max, int decimals, double step, const QString& suffix = {},
             QWidget* parent = nullptr);
    // A table field's three components, each box ranged by the field.
    template <class S, class T>
    Vec3Edit(const scene::Field<S, T>& field, int decimals, double step, const QString& suffix = {},
             QWidget* parent = nullptr)
        : Vec3Edit(0.0, 0.0, decimals, step, suffix, parent) {
        setField(field.name, field.widgetRange());
    }
    QDoubleSpinBox* box(int axis) const { return boxes_[std::size_t(axis)]; }
    void showValue(const glm::dvec3& v);
    glm::dvec3 value() const;

  signals:
    // One component was committed by the user.
    void edited(int axis, double value);

  private:
    void setField(const char* name, const scene::FieldRange& range);
    std::array<QDoubleSpinBox*, 3> boxes_{};
};

// A button showing a colour swatch; a click opens QColorDialog. Colours are
// the scene's linear floats clamped to 0..1 for display.
class ColorButton : public QPushButton {
    Q_OBJECT
  public:
    explicit ColorButton(QWidget* parent = nullptr);
    QColor color() const { return color_; }
    // Shows a colour without emitting `picked`.
    void showColor(const QColor& color);

  signals:
    void picked(const QColor& color);

  private:
    void choose();
    QColor color_;
};

QColor toQColor(const glm::vec3& c);
glm::vec3 toVec3(const QColor& c);

// Euler angles in degrees, applied about X, then Y, then Z (glm's
// quat(eulerAngles) convention: q = qz * qy * qx).
glm::dvec3 eulerDegrees(const glm::quat& q);
glm::quat quatFromEulerDegrees(const glm::dvec3& degrees);

// Where a light comes from, as a sun is described: elevation above the
// horizon (XZ plane, +Y up) and azimuth measured from +Z towards +X, both in
// degrees. `direction` is the way the light travels, i.e. the opposite.
struct AzimuthElevation {
    double azimuth = 0.0;
    double elevation = 0.0;
};
AzimuthElevation azimuthElevationOf(const glm::vec3& direction);
glm::vec3 directionFrom(const AzimuthElevation& angles);

} // namespace lpv::editor
