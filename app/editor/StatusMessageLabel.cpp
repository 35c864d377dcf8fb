#include "StatusMessageLabel.h"

#include <QStatusBar>

#include <algorithm>

namespace lpv::editor {

StatusMessageLabel::StatusMessageLabel(QStatusBar* bar) : QLabel(bar) {
    setObjectName("statusMessage");
    setTextFormat(Qt::PlainText);
    // Takes what the fields leave and never pushes them (or the window) wider.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    // A permanent widget, first: QStatusBar paints its message only left of
    // the first permanent widget, which leaves it no room; this label shows it.
    bar->addPermanentWidget(this, 1);
    connect(bar, &QStatusBar::messageChanged, this, &StatusMessageLabel::showFull);
}

QSize StatusMessageLabel::minimumSizeHint() const { return {0, QLabel::minimumSizeHint().height()}; }

QSize StatusMessageLabel::sizeHint() const { return {0, QLabel::sizeHint().height()}; }

void StatusMessageLabel::showFull(const QString& text) {
    full_ = text;
    setToolTip(text);
    elide();
}

void StatusMessageLabel::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    elide();
}

void StatusMessageLabel::elide() {
    // One line: a message with line breaks (a loader error) shows its first ones joined.
    QString line = full_;
    line.replace('\n', ' ');
    setText(fontMetrics().elidedText(line, Qt::ElideRight, std::max(contentsRect().width(), 0)));
}

} // namespace lpv::editor
