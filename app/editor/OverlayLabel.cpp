#include "OverlayLabel.h"

#include <QFontMetricsF>
#include <QPainter>

namespace lpv::editor {

QRectF drawOverlayLabel(QPainter& painter, const QPointF& topLeft, const QString& text, double maxWidth) {
    const QFontMetricsF metrics(painter.font());
    // Padding in the font's own units, so the box grows with a larger font.
    const double padX = metrics.averageCharWidth() * 0.6, padY = metrics.descent() + 1.0;
    const QString shown = metrics.elidedText(text, Qt::ElideRight, std::max(0.0, maxWidth - 2.0 * padX));
    const QRectF box(topLeft,
                     QSizeF(metrics.horizontalAdvance(shown) + 2.0 * padX, metrics.height() + 2.0 * padY));
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, kOverlayLabelBackdropAlpha));
    painter.drawRoundedRect(box, 3.0, 3.0);
    painter.setPen(Qt::white);
    painter.drawText(box, Qt::AlignCenter, shown);
    painter.restore();
    return box;
}

} // namespace lpv::editor
