#pragma once
// The sky's colour and intensity, shown when nothing is selected.
#include <QWidget>

class QDoubleSpinBox;

namespace lpv::editor {

class ColorButton;
class Document;

class SkyProperties : public QWidget {
    Q_OBJECT
  public:
    explicit SkyProperties(Document* doc, QWidget* parent = nullptr);
    void refresh();

  public slots:
    // What the colour button calls once its dialog returns.
    void applyColor(const QColor& color);

  private:
    Document* doc_;
    ColorButton* color_ = nullptr;
    QDoubleSpinBox* intensity_ = nullptr;
};

} // namespace lpv::editor
