#include "SkyProperties.h"

#include "Document.h"
#include "PropertyWidgets.h"

#include "lpv/scene/SceneFields.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QVBoxLayout>

namespace lpv::editor {

SkyProperties::SkyProperties(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* group = new QGroupBox(tr("Sky"), this);
    auto* form = new QFormLayout(group);
    layout->addWidget(group);

    color_ = new ColorButton(group);
    color_->setObjectName("skyColor");
    intensity_ = makeFieldSpinBox(scene::fieldOf<&scene::Sky::intensity>(), 3, 0.1, {}, group);
    intensity_->setObjectName("skyIntensity");
    intensity_->setToolTip(tr("0 = no sky light (closed interiors)"));
    form->addRow(tr("Colour"), color_);
    form->addRow(tr("Intensity"), intensity_);

    connect(color_, &ColorButton::picked, this, &SkyProperties::applyColor);
    connect(intensity_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        scene::Sky sky = doc_->scene().sky;
        sky.intensity = float(v);
        doc_->setSky(sky, tr("Edit sky intensity"));
    });
    refresh();
}

void SkyProperties::applyColor(const QColor& color) {
    scene::Sky sky = doc_->scene().sky;
    sky.color = toVec3(color);
    doc_->setSky(sky, tr("Edit sky colour"));
}

void SkyProperties::refresh() {
    const scene::Sky& sky = doc_->scene().sky;
    color_->showColor(toQColor(sky.color));
    showValue(intensity_, sky.intensity);
}

} // namespace lpv::editor
