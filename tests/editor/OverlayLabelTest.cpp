// Captions over the rendered view (issue #46): the Accuracy split's
// "Reference" was white text on the bright sky and could not be read. A
// label now has a dark translucent box under it; its text must reach a WCAG
// contrast of 4.5:1 against that box over the brightest image, measured
// from the drawn pixels.
#include "OverlayLabel.h"
#include "WcagContrast.h"

#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lpv::editor;
using lpv::test::wcagContrast;
using lpv::test::wcagLuminance;

namespace {

// A bright sky: pale blue at the top to white, as the Accuracy split showed it.
QImage brightSky(int width, int height) {
    QImage image(width, height, QImage::Format_RGB32);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int t = 215 + 40 * y / std::max(height - 1, 1);
            image.setPixel(x, y, qRgb(t, std::min(255, t + 15), 255));
        }
    return image;
}

} // namespace

TEST(OverlayLabel, TextReadsOnABrightSky) {
    for (const QString& text : {QString("Reference"), QString("LPV"), QString("A: current parameters")}) {
        QImage image = brightSky(320, 80);
        QPainter painter(&image);
        const QRectF box = drawOverlayLabel(painter, QPointF(8, 8), text, 300.0);
        painter.end();
        ASSERT_GT(box.width(), 10.0);
        ASSERT_GT(box.height(), 8.0);
        ASSERT_LE(box.right(), 308.0) << "within the width it was given";

        // The text: the brightest pixel inside the box. The box under it: the
        // brightest pixel of its left padding (no glyph there), the worst case.
        const QRect inside = box.toAlignedRect().adjusted(2, 4, -2, -4);
        double glyphs = 0.0, backdrop = 0.0;
        for (int y = inside.top(); y <= inside.bottom(); ++y) {
            for (int x = inside.left(); x <= inside.right(); ++x)
                glyphs = std::max(glyphs, wcagLuminance(image.pixel(x, y)));
            backdrop = std::max(backdrop, wcagLuminance(image.pixel(inside.left(), y)));
        }
        const double sky = wcagLuminance(image.pixel(image.width() - 1, image.height() - 1));
        EXPECT_LT(wcagContrast(glyphs, sky), 1.5)
            << "white on the bare sky cannot be read: the case the box is for";
        EXPECT_GE(wcagContrast(glyphs, backdrop), 4.5)
            << text.toStdString() << ": text " << glyphs << ", box " << backdrop;
    }
}

TEST(OverlayLabel, ALongTextIsElidedToTheWidthGiven) {
    QImage image = brightSky(200, 40);
    QPainter painter(&image);
    const QRectF box = drawOverlayLabel(painter, QPointF(8, 8),
                                        "B: a preset with a name far longer than half the view", 120.0);
    painter.end();
    EXPECT_LE(box.width(), 120.0);
}
