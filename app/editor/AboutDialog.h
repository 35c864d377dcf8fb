#pragma once
// Help > About LPV Studio: the report `lpv --version` prints (version, git
// revision, build, libraries; lpv/app/VersionInfo.h) plus Qt's version and
// the OpenGL driver the viewport renders with. The text can be selected and
// copied whole, for bug reports.
#include "lpv/renderer/GlContext.h"

#include <QDialog>

#include <optional>

class QPlainTextEdit;

namespace lpv::editor {

// The report as plain text. `renderer`: the driver of the viewport's render
// context (Viewport::renderGlInfo); nothing before the viewport's first
// frame, and the OpenGL line then says so.
QString aboutReport(const std::optional<renderer::GlInfo>& renderer);

class AboutDialog : public QDialog {
    Q_OBJECT
  public:
    explicit AboutDialog(const std::optional<renderer::GlInfo>& renderer, QWidget* parent = nullptr);

    QString reportText() const;

  private:
    QPlainTextEdit* text_ = nullptr;
};

} // namespace lpv::editor
