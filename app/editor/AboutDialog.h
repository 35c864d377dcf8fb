#pragma once
// Help > About LPV Studio: the report `lpv --version` prints (version, git
// revision, build, libraries; lpv/app/VersionInfo.h) plus Qt's version and
// the OpenGL driver the viewport renders with. The text can be selected and
// copied whole, for bug reports.
#include <QDialog>

class QOpenGLWidget;
class QPlainTextEdit;

namespace lpv::editor {

// The report as plain text. `viewport` may be null or not yet initialised;
// the OpenGL line then says so.
QString aboutReport(QOpenGLWidget* viewport);

class AboutDialog : public QDialog {
    Q_OBJECT
  public:
    explicit AboutDialog(QOpenGLWidget* viewport, QWidget* parent = nullptr);

    QString reportText() const;

  private:
    QPlainTextEdit* text_ = nullptr;
};

} // namespace lpv::editor
