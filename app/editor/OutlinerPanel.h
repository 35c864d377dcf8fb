#pragma once
// The scene tree: objects (nested by parent), lights, cameras and camera
// paths. Selection is synced both ways with the Document; the check box of
// an object shows/hides it, double-click renames; every change is an undo
// command made through the Document.
#include "Document.h"

#include <QWidget>

class QTreeWidget;
class QTreeWidgetItem;
class QLineEdit;

namespace lpv::editor {

class OutlinerPanel : public QWidget {
    Q_OBJECT
public:
    explicit OutlinerPanel(Document* document, QWidget* parent = nullptr);

    QTreeWidget* tree() const { return tree_; }
    // The item showing `selection`, or null.
    QTreeWidgetItem* itemFor(const Selection& selection) const;

public slots:
    void deleteSelected();
    void duplicateSelected();
    void renameSelected();

private:
    void rebuild();
    void refreshObjectLabels();
    void syncSelectionFromDocument();
    void onItemChanged(QTreeWidgetItem* item, int column);
    void applyFilter(const QString& text);

    Document* document_;
    QTreeWidget* tree_;
    QLineEdit* filter_;
    bool updating_ = false;
};

} // namespace lpv::editor
