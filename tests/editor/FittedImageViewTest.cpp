// The Visualizers dock's slice is shown whole, fitted to the space the dock
// gives it (issue #46): in a scroll area at its own size, most of it was
// out of sight in the dock beside the Inspector.
#include "FittedImageView.h"

#include <QImage>
#include <gtest/gtest.h>

using lpv::editor::FittedImageView;

namespace {

// A 600x400 image: red with a green top-left corner and a blue bottom-right one.
QImage marked() {
    QImage image(600, 400, QImage::Format_RGB32);
    image.fill(Qt::red);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            image.setPixel(x, y, qRgb(0, 255, 0));
            image.setPixel(599 - x, 399 - y, qRgb(0, 0, 255));
        }
    return image;
}

} // namespace

TEST(FittedImageView, ALargerImageIsShownWholeAtTheScaleThatFits) {
    FittedImageView view;
    view.resize(300, 300);
    view.setImage(marked());
    view.show();
    EXPECT_EQ(view.shownRect(), QRect(0, 0, 300, 200));
    // Both marked corners are on screen, where the scaled image puts them.
    const QImage grabbed = view.grab().toImage();
    ASSERT_GE(grabbed.width(), 300);
    EXPECT_EQ(QColor(grabbed.pixel(5, 5)), QColor(Qt::green));
    EXPECT_EQ(QColor(grabbed.pixel(294, 194)), QColor(Qt::blue));
    EXPECT_EQ(QColor(grabbed.pixel(150, 100)), QColor(Qt::red));
}

TEST(FittedImageView, ASmallerImageGrowsByWholeMultiplesOnly) {
    FittedImageView view;
    view.resize(1000, 1000); // room for 1.67x: shown at 1x, cells stay square pixels
    view.setImage(marked());
    EXPECT_EQ(view.shownRect(), QRect(0, 0, 600, 400));
    view.resize(1300, 900); // 2.17x by width, 2.25x by height: 2x
    EXPECT_EQ(view.shownRect(), QRect(0, 0, 1200, 800));
    view.setImage(QImage());
    EXPECT_TRUE(view.shownRect().isEmpty());
}
