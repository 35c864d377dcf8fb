#include "AccuracyPanel.h"

#include "Viewport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace lpv::editor {

namespace {

const char* const kRows[4] = {"MARE", "relMSE", "SSIM", "FLIP"};

const char* const kRowTips[4] = {
    QT_TRANSLATE_NOOP("AccuracyPanel",
                      "Mean absolute relative error of the luminance, linear HDR, background "
                      "left out (0 = identical)."),
    QT_TRANSLATE_NOOP("AccuracyPanel",
                      "Relative mean squared error of the luminance, linear HDR (0 = identical)."),
    QT_TRANSLATE_NOOP("AccuracyPanel", "Structural similarity of the tone-mapped luminance (1 = identical)."),
    QT_TRANSLATE_NOOP(
        "AccuracyPanel",
        "FLIP (Andersson et al. 2020): the error a viewer sees flipping between the two images, "
        "both shown with the reference's exposure, 67 pixels per degree (0 = identical, 1 = the "
        "largest)."),
};

QString percent(double v) {
    return QString::number(100.0 * v, 'f', 2) + "%";
}

} // namespace

AccuracyPanel::AccuracyPanel(Document* document, Viewport* viewport, QWidget* parent)
    : QWidget(parent), monitor_(new AccuracyMonitor(document, viewport, this)) {
    auto* layout = new QVBoxLayout(this);
    trace_ = new QCheckBox(tr("Trace reference"), this);
    trace_->setObjectName("traceReference");
    trace_->setToolTip(tr("Path-trace the reference of this view in the background (every core but one), at "
                          "the frame's size; it starts again when the view, the scene or a reference setting "
                          "changes, not when a renderer setting does."));
    heatMap_ = new QCheckBox(tr("Heat map"), this);
    heatMap_->setObjectName("heatMap");
    heatMap_->setToolTip(tr("Show the FLIP error per pixel over the view (magma: black = none, yellow = the "
                            "largest)."));
    split_ = new QCheckBox(tr("Split: LPV | reference"), this);
    split_->setObjectName("referenceSplit");
    split_->setToolTip(tr("Left half: the frame; right half: the reference, both mapped alike (Reference "
                          "mapping), so equal light shows as equal pixels."));
    auto* toggles = new QHBoxLayout;
    toggles->addWidget(trace_);
    toggles->addWidget(heatMap_);
    toggles->addWidget(split_);
    toggles->addStretch();
    layout->addLayout(toggles);
    mapping_ = new QComboBox(this);
    mapping_->setObjectName("referenceMapping");
    mapping_->addItem(tr("frame's tonemap"));
    mapping_->addItem(tr("preview x/(x+mean)"));
    mapping_->setToolTip(tr(
        "How the split and the live reference view (gi.method = reference) show the reference. frame's "
        "tonemap: the frame's exposure (output.exposure, and the metered one on auto) and "
        "output.tonemapper, as the frame itself is shown. preview: lpv reference --preview's x / (x + mean), "
        "gamma 2.2, with the reference's mean for both halves of the split (what FLIP compares)."));
    auto* mappingRow = new QHBoxLayout;
    mappingRow->addWidget(new QLabel(tr("Reference mapping"), this));
    mappingRow->addWidget(mapping_);
    mappingRow->addStretch();
    layout->addLayout(mappingRow);

    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("<b>Frame</b>"), this), 0, 1);
    auto* noiseHeader = new QLabel(tr("<b>Reference noise</b>"), this);
    noiseHeader->setToolTip(
        tr("What the reference's own noise alone would score: an error at or below it is as "
           "close as this reference can tell (trace longer to resolve it)."));
    grid->addWidget(noiseHeader, 0, 2);
    for (int r = 0; r < 4; ++r) {
        auto* name = new QLabel(kRows[r], this);
        name->setToolTip(tr(kRowTips[r]));
        grid->addWidget(name, r + 1, 0);
        for (int c = 0; c < 2; ++c) {
            values_[r][c] = new QLabel(this);
            values_[r][c]->setObjectName(QString(kRows[r]) + (c ? "Noise" : "Value"));
            values_[r][c]->setTextInteractionFlags(Qt::TextSelectableByMouse);
            grid->addWidget(values_[r][c], r + 1, c + 1);
        }
    }
    grid->addWidget(new QLabel(tr("GPU time"), this), 5, 0);
    gpuTime_ = new QLabel(this);
    gpuTime_->setObjectName("gpuTime");
    gpuTime_->setToolTip(tr("The measured frame's GPU time: the sum of its passes' timer queries."));
    grid->addWidget(gpuTime_, 5, 1, 1, 2);
    grid->addWidget(new QLabel(tr("Reference"), this), 6, 0);
    referenceInfo_ = new QLabel(this);
    grid->addWidget(referenceInfo_, 6, 1, 1, 2);
    grid->setColumnStretch(3, 1);
    layout->addLayout(grid);
    status_ = new QLabel(this);
    status_->setObjectName("accuracyStatus");
    status_->setWordWrap(true);
    layout->addWidget(status_);
    layout->addStretch();

    connect(trace_, &QCheckBox::toggled, monitor_, &AccuracyMonitor::setTracing);
    connect(heatMap_, &QCheckBox::toggled, monitor_, &AccuracyMonitor::setHeatMapShown);
    connect(split_, &QCheckBox::toggled, monitor_, &AccuracyMonitor::setSplitShown);
    connect(mapping_, &QComboBox::currentIndexChanged, this, [this, viewport](int index) {
        const ReferenceMapping mapping =
            index == 1 ? ReferenceMapping::Preview : ReferenceMapping::FrameTonemap;
        monitor_->setReferenceMapping(mapping);
        viewport->setReferenceMapping(mapping);
    });
    connect(monitor_, &AccuracyMonitor::measured, this, &AccuracyPanel::showSample);
    connect(monitor_, &AccuracyMonitor::statusChanged, this, [this](const QString& status) {
        status_->setText(status);
        if (!monitor_->latest())
            clearFigures(); // another view, or off: the old figures no longer hold
    });
    clearFigures();
    status_->setText(tr("Trace a reference of this view to measure the frame against it."));
}

void AccuracyPanel::clearFigures() {
    for (auto& row : values_)
        for (QLabel* l : row)
            l->setText(QStringLiteral("-"));
    gpuTime_->setText(QStringLiteral("-"));
    referenceInfo_->setText(QStringLiteral("-"));
}

void AccuracyPanel::showSample(const std::shared_ptr<const AccuracySample>& sample) {
    const reference::Accuracy& a = sample->accuracy;
    const reference::ErrorMetrics& m = a.metrics;
    // An error the noise could explain is marked: more samples are needed to tell.
    auto mark = [](const QString& text, bool belowNoise) {
        return belowNoise ? text + " (below noise)" : text;
    };
    // One sample has no variance yet: its noise is unknown, not zero.
    const bool noiseKnown = sample->samplesPerPixel >= 2;
    values_[0][0]->setText(mark(percent(m.mare), noiseKnown && m.mareBelowNoise()));
    values_[0][1]->setText(percent(m.noiseMare));
    values_[1][0]->setText(mark(QString::number(m.relMse, 'g', 4), noiseKnown && m.relMseBelowNoise()));
    values_[1][1]->setText(QString::number(m.noiseRelMse, 'g', 4));
    values_[2][0]->setText(mark(QString::number(m.ssim, 'f', 4), noiseKnown && a.ssimBelowNoise()));
    values_[2][1]->setText(QString::number(a.noiseSsim, 'f', 4));
    values_[3][0]->setText(mark(QString::number(a.flip, 'f', 4), noiseKnown && a.flipBelowNoise()));
    values_[3][1]->setText(QString::number(a.noiseFlip, 'f', 4));
    if (!noiseKnown)
        for (auto& row : values_)
            row[1]->setText(tr("(from 2 spp)"));
    gpuTime_->setText(tr("%1 ms").arg(sample->gpuMs, 0, 'f', 2));
    referenceInfo_->setText(tr("%1 spp, %2 s, layer %3; measured in %4 ms")
                                .arg(sample->samplesPerPixel)
                                .arg(sample->referenceSeconds, 0, 'f', 1)
                                .arg(QString::fromStdString(sample->layer))
                                .arg(sample->measureMs, 0, 'f', 0));
}

QString AccuracyPanel::figureText(const QString& row, bool noise) const {
    for (int r = 0; r < 4; ++r)
        if (row == kRows[r])
            return values_[r][noise ? 1 : 0]->text();
    return {};
}

QString AccuracyPanel::gpuTimeText() const {
    return gpuTime_->text();
}
QString AccuracyPanel::statusText() const {
    return status_->text();
}

} // namespace lpv::editor
