#pragma once
// A caption drawn over the rendered view (the Accuracy split's "LPV" and
// "Reference", the A/B split's preset names): white text on a dark
// translucent box, so it reads on any image under it. White text alone
// could not be read on a bright sky (issue #46).
#include <QPointF>
#include <QRectF>
#include <QString>

class QPainter;

namespace lpv::editor {

// The box's opacity over the image: black at this alpha over pure white
// leaves sRGB 89, a WCAG contrast of about 7:1 against the white text.
inline constexpr int kOverlayLabelBackdropAlpha = 166;

// Draws `text` with its box's top-left corner at `topLeft`, at most
// `maxWidth` wide (elided beyond); returns the box drawn.
QRectF drawOverlayLabel(QPainter& painter, const QPointF& topLeft, const QString& text, double maxWidth);

} // namespace lpv::editor
