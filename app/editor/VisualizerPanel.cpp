#include "VisualizerPanel.h"

#include "Document.h"
#include "FittedImageView.h"
#include "Viewport.h"

#include "lpv/renderer/viz/TileImages.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace lpv::editor {

namespace viz = renderer::viz;

namespace {

QImage toQImage(const scene::Image8& image) {
    // Copied: the QImage outlives the buffer it was made from.
    return QImage(image.pixels.data(), image.width, image.height, image.width * 4, QImage::Format_RGBA8888)
        .copy();
}

const std::pair<const char*, glm::vec3> kDirections[] = {
    {"+y (floor)", {0, 1, 0}}, {"-y (ceiling)", {0, -1, 0}}, {"+x", {1, 0, 0}}, {"-x", {-1, 0, 0}},
    {"+z", {0, 0, 1}},         {"-z", {0, 0, -1}},
};

} // namespace

VisualizerPanel::VisualizerPanel(Document* document, Viewport* viewport, QWidget* parent)
    : QWidget(parent), document_(document), viewport_(viewport) {
    buildControls();
    connect(viewport_, &Viewport::visualizerFrame, this, &VisualizerPanel::onFrame);
    // Parameter edits re-render the viewport, which brings a new frame; the
    // step slider follows lpv.propagationSteps at once.
    connect(document_, &Document::changed, this, [this](Changes) { syncRanges(); });
    playTimer_.setInterval(600);
    connect(&playTimer_, &QTimer::timeout, this, [this] { stepBy(1); });
    syncRanges();
}

void VisualizerPanel::buildControls() {
    auto* form = new QFormLayout;
    auto combo = [&](const char* name, const QStringList& items) {
        auto* c = new QComboBox(this);
        c->setObjectName(name);
        c->addItems(items);
        connect(c, &QComboBox::currentIndexChanged, this, &VisualizerPanel::pushRequest);
        return c;
    };
    view_ = combo("vizView", {tr("LPV light"), tr("Geometry volume"), tr("Leak heat map"),
                              tr("Back-side light"), tr("RSM tiles"), tr("Shadow maps")});
    form->addRow(tr("View"), view_);

    cascade_ = new QSpinBox(this);
    cascade_->setObjectName("vizCascade");
    cascade_->setRange(0, 5);
    connect(cascade_, &QSpinBox::valueChanged, this, &VisualizerPanel::pushRequest);
    form->addRow(tr("Cascade"), cascade_);

    axis_ = combo("vizAxis", {"x", "y", "z"});
    axis_->setCurrentIndex(2);
    form->addRow(tr("Axis"), axis_);

    auto* sliceRow = new QHBoxLayout;
    slice_ = new QSlider(Qt::Horizontal, this);
    slice_->setObjectName("vizSlice");
    sliceLabel_ = new QLabel(this);
    sliceLabel_->setMinimumWidth(48);
    connect(slice_, &QSlider::valueChanged, this, &VisualizerPanel::pushRequest);
    sliceRow->addWidget(slice_);
    sliceRow->addWidget(sliceLabel_);
    form->addRow(tr("Slice"), sliceRow);

    source_ = combo("vizSource", {tr("Injected"), tr("One step alone"), tr("Accumulated to step")});
    source_->setCurrentIndex(2);
    form->addRow(tr("Volume"), source_);

    auto* stepRow = new QHBoxLayout;
    auto button = [&](const char* name, const QString& text, const QString& tip) {
        auto* b = new QToolButton(this);
        b->setObjectName(name);
        b->setText(text);
        b->setToolTip(tip);
        stepRow->addWidget(b);
        return b;
    };
    auto* back = button("vizStepBack", "<", tr("One propagation step back"));
    step_ = new QSlider(Qt::Horizontal, this);
    step_->setObjectName("vizStep");
    stepRow->addWidget(step_);
    auto* forward = button("vizStepForward", ">", tr("One propagation step forward"));
    play_ = button("vizPlay", tr("Play"), tr("Step through the propagation iterations, looping"));
    play_->setCheckable(true);
    stepLabel_ = new QLabel(this);
    stepLabel_->setMinimumWidth(40);
    stepRow->addWidget(stepLabel_);
    connect(back, &QToolButton::clicked, this, [this] { stepBy(-1); });
    connect(forward, &QToolButton::clicked, this, [this] { stepBy(1); });
    connect(play_, &QToolButton::toggled, this,
            [this](bool on) { on ? playTimer_.start() : playTimer_.stop(); });
    connect(step_, &QSlider::valueChanged, this, &VisualizerPanel::pushRequest);
    form->addRow(tr("Step"), stepRow);

    quantity_ = combo("vizQuantity", {tr("SH band 0"), tr("SH coefficient"), tr("Irradiance toward")});
    form->addRow(tr("Show"), quantity_);
    coefficient_ = new QSpinBox(this);
    coefficient_->setObjectName("vizCoefficient");
    coefficient_->setRange(0, 3);
    coefficient_->setToolTip(tr("0: Y00, 1: Y1-1 (y), 2: Y10 (z), 3: Y11 (x)"));
    connect(coefficient_, &QSpinBox::valueChanged, this, &VisualizerPanel::pushRequest);
    form->addRow(tr("Coefficient"), coefficient_);
    QStringList directions;
    for (const auto& [name, d] : kDirections)
        directions << name;
    direction_ = combo("vizDirection", directions);
    direction_->setToolTip(
        tr("Irradiance on a surface facing this way; for the geometry volume, the blocking of "
           "light travelling this way"));
    form->addRow(tr("Direction"), direction_);
    channel_ = combo("vizChannel", {tr("Red"), tr("Green"), tr("Blue"), tr("Luminance"), tr("RGB")});
    channel_->setCurrentIndex(3);
    form->addRow(tr("Channel"), channel_);
    scale_ = combo("vizScale", {tr("Linear"), tr("Log (4 decades)")});
    form->addRow(tr("Scale"), scale_);

    auto check = [&](const char* name, const QString& text, bool on) {
        auto* c = new QCheckBox(text, this);
        c->setObjectName(name);
        c->setChecked(on);
        connect(c, &QCheckBox::toggled, this, &VisualizerPanel::pushRequest);
        return c;
    };
    falseColour_ = check("vizFalseColour", tr("False colour"), true);
    lockRange_ = check("vizLockRange", tr("Lock range"), false);
    lockRange_->setToolTip(tr("Keep the colour range while stepping, so steps compare"));
    auto* colourRow = new QHBoxLayout;
    colourRow->addWidget(falseColour_);
    colourRow->addWidget(lockRange_);
    form->addRow(QString(), colourRow);
    bounds_ = check("vizBounds", tr("Cascade boxes"), true);
    plane_ = check("vizPlane", tr("Slice plane"), true);
    probes_ = check("vizProbes", tr("SH probes"), false);
    auto* overlayRow = new QHBoxLayout;
    overlayRow->addWidget(bounds_);
    overlayRow->addWidget(plane_);
    overlayRow->addWidget(probes_);
    form->addRow(tr("In the view"), overlayRow);

    picture_ = new FittedImageView(this);
    picture_->setObjectName("vizImage");
    statusLabel_ = new QLabel(this);
    statusLabel_->setWordWrap(true);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(statusLabel_);
    layout->addWidget(picture_, 1);
}

VisualizerPanel::View VisualizerPanel::view() const {
    return View(view_->currentIndex());
}

void VisualizerPanel::setActive(bool active) {
    if (active == active_)
        return;
    active_ = active;
    if (!active_) {
        playTimer_.stop();
        play_->setChecked(false);
        frame_.reset();
    }
    pushRequest();
}

void VisualizerPanel::setView(View v) {
    view_->setCurrentIndex(int(v));
}
void VisualizerPanel::setSlice(int index) {
    slice_->setValue(index);
}
void VisualizerPanel::setStep(int step) {
    step_->setValue(step);
}

void VisualizerPanel::stepBy(int delta) {
    int next = step_->value() + delta;
    if (next > step_->maximum())
        next = play_->isChecked() ? 0 : step_->maximum();
    step_->setValue(std::max(next, 0));
}

void VisualizerPanel::syncRanges() {
    if (!picture_)
        return;
    const int steps = document_->parameters().getInt("lpv.propagationSteps");
    const int cascades = document_->parameters().getInt("lpv.cascades");
    const int grid = document_->parameters().getInt("lpv.gridSize");
    const QSignalBlocker b1(step_), b2(cascade_), b3(slice_);
    // Follows the last step as the count changes (and starts there: what shading reads).
    const bool atEnd = step_->value() == step_->maximum() || (step_->maximum() == 99 && step_->value() == 0);
    step_->setRange(0, steps);
    if (atEnd)
        step_->setValue(steps);
    cascade_->setRange(0, std::max(cascades - 1, 0));
    const int slices = grid + (view() == View::Geometry ? 1 : 0);
    const bool fresh = slice_->maximum() == 99 && slice_->value() == 0; // a QSlider's defaults: not set yet
    slice_->setRange(0, slices - 1);
    if (fresh)
        slice_->setValue(slices / 2);
    sliceLabel_->setText(QString("%1 / %2").arg(slice_->value()).arg(slices - 1));
    stepLabel_->setText(QString("%1 / %2").arg(step_->value()).arg(steps));
}

viz::LpvViewSpec VisualizerPanel::spec() const {
    viz::LpvViewSpec s;
    s.cascade = cascade_->value();
    switch (view()) {
    case View::Geometry:
        s.source = viz::LpvSource::Geometry;
        break;
    case View::Leak:
        s.source = viz::LpvSource::LeakHeat;
        break;
    case View::Backside:
        s.source = viz::LpvSource::Backside;
        break;
    default:
        s.source = viz::LpvSource(source_->currentIndex()); // Injected, Step, Accumulated
        break;
    }
    s.step = step_->value();
    s.slice.axis = viz::Axis(axis_->currentIndex());
    s.slice.index = slice_->value();
    s.slice.quantity = viz::Quantity(quantity_->currentIndex());
    s.slice.coefficient = coefficient_->value();
    s.slice.direction = kDirections[std::size_t(std::max(direction_->currentIndex(), 0))].second;
    s.slice.channel = viz::Channel(channel_->currentIndex());
    s.colour.scale = scale_->currentIndex() == 1 ? viz::Scale::Log : viz::Scale::Linear;
    s.colour.falseColour = falseColour_->isChecked();
    s.colour.pixelsPerCell = 12;
    s.colour.rangeMax = lockedMax_;
    return s;
}

void VisualizerPanel::pushRequest() {
    if (!picture_)
        return; // still building the controls
    syncRanges();
    const View v = view();
    const bool slices = v != View::Rsm && v != View::Shadow;
    for (QWidget* w : std::initializer_list<QWidget*>{axis_, slice_, quantity_, channel_, scale_,
                                                      falseColour_, lockRange_, plane_})
        w->setEnabled(slices);
    source_->setEnabled(v == View::Light);
    step_->setEnabled(slices && v != View::Geometry);
    coefficient_->setEnabled(slices && quantity_->currentIndex() == 1);
    direction_->setEnabled(slices && quantity_->currentIndex() == 2);
    if (!lockRange_->isChecked())
        lockedMax_.reset();

    VisualizerRequest request;
    if (active_) {
        const viz::LpvViewSpec s = spec();
        if (slices || probes_->isChecked())
            request.lpv = viz::captureFor(s);
        request.rsm = v == View::Rsm;
        request.shadow = v == View::Shadow;
        request.shadowTint = v == View::Shadow;
        request.cascadeBounds = bounds_->isChecked();
        if (slices && plane_->isChecked())
            request.slicePlane = SlicePlane{s.cascade, s.slice.axis, s.slice.index, v == View::Geometry};
        request.probes = probes_->isChecked();
    }
    viewport_->setVisualizerRequest(request);
    // The last frame already holds what a slice, quantity or colour change needs.
    rebuildImage();
}

void VisualizerPanel::onFrame(std::shared_ptr<const VisualizerFrame> frame) {
    if (!active_)
        return;
    frame_ = std::move(frame);
    rebuildImage();
}

void VisualizerPanel::rebuildImage() {
    image_ = QImage();
    status_.clear();
    if (!active_ || !frame_) {
        status_ = active_ ? tr("Waiting for a frame...") : tr("Closed: nothing is read back.");
    } else if (view() == View::Rsm || view() == View::Shadow) {
        const bool rsm = view() == View::Rsm;
        const auto images =
            rsm ? viz::imagesNamed(frame_->rsm, "rsm-" + std::to_string(cascade_->value()) + "-")
                : frame_->shadow;
        if (images.empty())
            status_ = rsm ? tr("No RSM tile for this cascade (the scene needs a sun).")
                          : tr("No shadow maps (no light casts shadows).");
        else
            image_ = toQImage(viz::tileRow(images, 256));
    } else if (!frame_->lpv) {
        status_ = QString::fromStdString(frame_->lpvNote);
    } else {
        const viz::LpvViewSpec s = spec();
        viz::SliceRange range;
        auto image = viz::renderLpvView(*frame_->lpv, s, &range);
        if (!image) {
            status_ = QString::fromStdString(image.error().message);
        } else {
            image_ = toQImage(*image);
            if (lockRange_->isChecked() && !lockedMax_)
                lockedMax_ = range.high;
            status_ = QString::fromStdString(viz::viewTitle(*frame_->lpv, s)).toLower() +
                      QString("\ncolour range %1 .. %2")
                          .arg(double(range.low), 0, 'g', 3)
                          .arg(double(range.high), 0, 'g', 3);
        }
    }
    statusLabel_->setText(status_);
    picture_->setImage(image_);
    emit imageUpdated();
}

QString VisualizerPanel::status() const {
    return status_;
}

} // namespace lpv::editor
