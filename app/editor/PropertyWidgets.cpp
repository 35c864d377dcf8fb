#include "PropertyWidgets.h"

#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lpv::editor {

QDoubleSpinBox* makeSpinBox(double min, double max, int decimals, double step, const QString& suffix,
                            QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setDecimals(decimals);
    box->setRange(min, max);
    box->setSingleStep(step);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    box->setAccelerated(true);
    return box;
}

void showValue(QDoubleSpinBox* box, double value) {
    // Compare at the box's precision: the box rounds what it holds.
    const double shown = QString::number(value, 'f', box->decimals()).toDouble();
    if (shown == box->value())
        return;
    const QSignalBlocker block(box);
    box->setValue(value);
}

double shownValue(double stored, Shown shown) {
    return shown == Shown::Degrees ? stored * (180.0 / std::numbers::pi) : stored;
}

float storedValue(double value, Shown shown) {
    // As glm::radians, which the panels used before the tables.
    return float(shown == Shown::Degrees ? value * (std::numbers::pi / 180.0) : value);
}

std::pair<double, double> spinBoxBounds(const scene::FieldRange& range, Shown shown, int decimals) {
    const double quantum = std::pow(10.0, -decimals);
    // Spin boxes need finite ends; a table field the editor shows has them (editRange).
    constexpr double kLargest = 1.0e15;
    const auto atPrecision = [&](double v) {
        return std::round(std::clamp(shownValue(v, shown), -kLargest, kLargest) / quantum) * quantum;
    };
    double lo = atPrecision(range.min);
    double hi = atPrecision(range.max);
    for (int i = 0; i < 3 && lo <= hi && !range.contains(storedValue(lo, shown)); ++i)
        lo += quantum;
    for (int i = 0; i < 3 && hi >= lo && !range.contains(storedValue(hi, shown)); ++i)
        hi -= quantum;
    return {lo, std::max(lo, hi)};
}

void setFieldRange(QDoubleSpinBox* box, const scene::FieldRange& range, Shown shown) {
    const auto [lo, hi] = spinBoxBounds(range, shown, box->decimals());
    box->setRange(lo, hi);
}

QDoubleSpinBox* makeFieldSpinBox(const char* field, const scene::FieldRange& range, int decimals, double step,
                                 const QString& suffix, QWidget* parent, Shown shown) {
    QDoubleSpinBox* box = makeSpinBox(0.0, 0.0, decimals, step, suffix, parent);
    setFieldRange(box, range, shown);
    box->setProperty("sceneField", QString::fromLatin1(field));
    return box;
}

void showText(QLineEdit* edit, const QString& text) {
    if (edit->text() == text)
        return;
    const QSignalBlocker block(edit);
    edit->setText(text);
}

Vec3Edit::Vec3Edit(double min, double max, int decimals, double step, const QString& suffix, QWidget* parent)
    : QWidget(parent) {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(2);
    static const char* const kAxes[3] = {"X ", "Y ", "Z "};
    for (int axis = 0; axis < 3; ++axis) {
        QDoubleSpinBox* box = makeSpinBox(min, max, decimals, step, suffix, this);
        box->setPrefix(QString::fromLatin1(kAxes[axis]));
        box->setMinimumWidth(60);
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, axis](double v) { emit edited(axis, v); });
        row->addWidget(box, 1);
        boxes_[std::size_t(axis)] = box;
    }
}

void Vec3Edit::setField(const char* name, const scene::FieldRange& range) {
    for (QDoubleSpinBox* box : boxes_) {
        setFieldRange(box, range);
        box->setProperty("sceneField", QString::fromLatin1(name));
    }
}

void Vec3Edit::showValue(const glm::dvec3& v) {
    for (int axis = 0; axis < 3; ++axis)
        editor::showValue(boxes_[std::size_t(axis)], v[axis]);
}

glm::dvec3 Vec3Edit::value() const {
    return {boxes_[0]->value(), boxes_[1]->value(), boxes_[2]->value()};
}

ColorButton::ColorButton(QWidget* parent) : QPushButton(parent) {
    setIconSize(QSize(40, 14));
    connect(this, &QPushButton::clicked, this, &ColorButton::choose);
    showColor(Qt::white);
}

void ColorButton::showColor(const QColor& color) {
    if (color == color_ && !icon().isNull())
        return;
    color_ = color;
    QPixmap swatch(iconSize());
    swatch.fill(color);
    {
        QPainter p(&swatch);
        p.setPen(palette().color(QPalette::WindowText));
        p.drawRect(swatch.rect().adjusted(0, 0, -1, -1));
    }
    setIcon(QIcon(swatch));
    setText(QStringLiteral("%1 %2 %3")
                .arg(color.redF(), 0, 'f', 2)
                .arg(color.greenF(), 0, 'f', 2)
                .arg(color.blueF(), 0, 'f', 2));
}

void ColorButton::choose() {
    const QColor chosen = QColorDialog::getColor(color_, this, tr("Choose colour"));
    if (chosen.isValid() && chosen != color_)
        emit picked(chosen);
}

QColor toQColor(const glm::vec3& c) {
    const glm::vec3 v = glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
    return QColor::fromRgbF(v.r, v.g, v.b);
}

glm::vec3 toVec3(const QColor& c) {
    return {float(c.redF()), float(c.greenF()), float(c.blueF())};
}

glm::dvec3 eulerDegrees(const glm::quat& q) {
    return glm::degrees(glm::dvec3(glm::eulerAngles(q)));
}

glm::quat quatFromEulerDegrees(const glm::dvec3& degrees) {
    return glm::quat(glm::vec3(glm::radians(degrees)));
}

AzimuthElevation azimuthElevationOf(const glm::vec3& direction) {
    AzimuthElevation a;
    if (glm::length(glm::dvec3(direction)) < 1e-12)
        return a;
    const glm::dvec3 toLight = -glm::normalize(glm::dvec3(direction));
    const double horizontal = std::hypot(toLight.x, toLight.z);
    a.elevation = glm::degrees(std::atan2(toLight.y, horizontal));
    // Straight up or down the azimuth is undefined; 0 keeps the field calm.
    a.azimuth = horizontal < 1e-9 ? 0.0 : glm::degrees(std::atan2(toLight.x, toLight.z));
    return a;
}

glm::vec3 directionFrom(const AzimuthElevation& angles) {
    const double az = glm::radians(angles.azimuth);
    const double el = glm::radians(angles.elevation);
    const glm::dvec3 toLight{std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
    return glm::vec3(-toLight);
}

} // namespace lpv::editor
