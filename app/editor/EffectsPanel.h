#pragma once
// The scene analysis in the editor: per effect whether it runs and why
// (renderer::decideEffects), with its auto/on/off override as a combo box
// that edits the parameter through the Document (undoable), and the
// renderer's own note on what the LPV did in the last frame.
#include "Document.h"

#include "lpv/renderer/SceneAnalysis.h"

#include <QTimer>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace lpv::editor {

class Viewport;

class EffectsPanel : public QWidget {
    Q_OBJECT
public:
    EffectsPanel(Document* document, Viewport* viewport, QWidget* parent = nullptr);

    QTableWidget* table() const { return table_; }
    const std::vector<renderer::EffectDecision>& decisions() const { return decisions_; }

public slots:
    void setRendererNote(const QString& note);

protected:
    // Decisions are not kept up to date while the dock is hidden: shown, it catches up.
    void showEvent(QShowEvent* event) override;

private:
    void reanalyse();
    void redecide();

    Document* document_;
    Viewport* viewport_;
    QTableWidget* table_;
    QLabel* note_;
    QLabel* traitsLabel_;
    QTimer analyseLater_; // the traits cast rays: once after a burst of edits
    renderer::SceneTraits traits_;
    std::vector<renderer::EffectDecision> decisions_;
    bool updating_ = false;
};

} // namespace lpv::editor
