#pragma once
// Shows an image whole, scaled to fit the widget with its aspect kept: the
// Visualizers dock's slice. In a scroll area at its own size, a slice of a
// 32-cell grid with its axes (about 600 px) showed a third of itself in the
// dock beside the Inspector (issue #46). Enlarged by whole multiples only,
// so cells stay sharp squares; made smaller smoothly, so captions stay legible.
#include <QImage>
#include <QRect>
#include <QWidget>

namespace lpv::editor {

class FittedImageView : public QWidget {
  public:
    explicit FittedImageView(QWidget* parent = nullptr);

    void setImage(const QImage& image);
    const QImage& image() const { return image_; }
    // Where the image is drawn, in the widget's coordinates (empty without one).
    QRect shownRect() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    QImage image_;
};

} // namespace lpv::editor
