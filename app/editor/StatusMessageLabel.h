#pragma once
// The status bar's message, elided to the room left of the permanent fields
// (GPU time, memory, textures, log) with the whole text in its tooltip.
// QStatusBar clips a long message at the first permanent field and drops the
// rest, so an error's cause was cut off (issue #46).
#include <QLabel>

class QStatusBar;

namespace lpv::editor {

class StatusMessageLabel : public QLabel {
    Q_OBJECT
public:
    // Shows `bar`'s messages (showMessage, clearMessage) in its place; added as
    // the bar's first permanent widget so the bar paints no text of its own.
    explicit StatusMessageLabel(QStatusBar* bar);
    const QString& fullText() const { return full_; }
    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void showFull(const QString& text);
    void elide();
    QString full_;
};

} // namespace lpv::editor
