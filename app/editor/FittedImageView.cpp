#include "FittedImageView.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace lpv::editor {

FittedImageView::FittedImageView(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void FittedImageView::setImage(const QImage& image) {
    image_ = image;
    updateGeometry();
    update();
}

QRect FittedImageView::shownRect() const {
    if (image_.isNull() || width() <= 0 || height() <= 0)
        return {};
    double scale = std::min(double(width()) / image_.width(), double(height()) / image_.height());
    if (scale >= 1.0)
        scale = std::floor(scale); // whole multiples: every cell the same size
    const int w = std::max(1, int(std::lround(image_.width() * scale)));
    const int h = std::max(1, int(std::lround(image_.height() * scale)));
    // Top-left, as the dock's controls above it: the caption stays next to them.
    return QRect(0, 0, w, h);
}

// Modest, not the image's size: in the dock's scroll area a hint of the
// whole image made the panel taller than the dock, and the slice scrolled out
// of sight again. The view takes what the dock leaves and fits the image to it.
QSize FittedImageView::sizeHint() const {
    if (image_.isNull())
        return QSize(256, 256);
    return image_.size().scaled(QSize(256, 256), Qt::KeepAspectRatio);
}

QSize FittedImageView::minimumSizeHint() const { return QSize(64, 64); }

void FittedImageView::paintEvent(QPaintEvent*) {
    const QRect target = shownRect();
    if (target.isEmpty())
        return;
    QPainter painter(this);
    painter.setRenderHint(QPainter::SmoothPixmapTransform, target.width() < image_.width());
    painter.drawImage(target, image_);
}

} // namespace lpv::editor
