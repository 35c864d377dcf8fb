#include "OutlinerPanel.h"

#include <QHeaderView>
#include <QLineEdit>
#include <QMenu>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <functional>

namespace lpv::editor {
namespace {

constexpr int kKindRole = Qt::UserRole;
constexpr int kIndexRole = Qt::UserRole + 1;

Selection selectionOf(const QTreeWidgetItem* item) {
    if (!item || !item->data(0, kKindRole).isValid())
        return {};
    return {Selection::Kind(item->data(0, kKindRole).toInt()), item->data(0, kIndexRole).toInt()};
}

QTreeWidgetItem* makeItem(const QString& name, Selection::Kind kind, int index, bool editable) {
    auto* item = new QTreeWidgetItem(QStringList{name});
    item->setData(0, kKindRole, int(kind));
    item->setData(0, kIndexRole, index);
    if (editable)
        item->setFlags(item->flags() | Qt::ItemIsEditable);
    return item;
}

QString nameOr(const std::string& name, const QString& fallback) {
    return name.empty() ? fallback : QString::fromStdString(name);
}

} // namespace

OutlinerPanel::OutlinerPanel(Document* document, QWidget* parent)
    : QWidget(parent), document_(document), tree_(new QTreeWidget(this)), filter_(new QLineEdit(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    filter_->setPlaceholderText(tr("Filter by name"));
    filter_->setClearButtonEnabled(true);
    layout->addWidget(filter_);
    layout->addWidget(tree_);
    tree_->setHeaderHidden(true);
    tree_->setSelectionMode(QAbstractItemView::SingleSelection);
    tree_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    tree_->setContextMenuPolicy(Qt::CustomContextMenu);

    connect(filter_, &QLineEdit::textChanged, this, &OutlinerPanel::applyFilter);
    connect(document_, &Document::changed, this, [this](Changes c) {
        // Transform drags only change names and visibility here: relabel in place, no rebuild.
        if (c & (Change::Structure | Change::Lights | Change::Cameras | Change::CameraPaths))
            rebuild();
        else if (c & Change::Transforms)
            refreshObjectLabels();
    });
    connect(document_, &Document::selectionChanged, this, &OutlinerPanel::syncSelectionFromDocument);
    connect(tree_, &QTreeWidget::itemSelectionChanged, this, [this] {
        if (updating_)
            return;
        const auto items = tree_->selectedItems();
        document_->select(items.isEmpty() ? Selection{} : selectionOf(items.front()));
    });
    connect(tree_, &QTreeWidget::itemChanged, this, &OutlinerPanel::onItemChanged);
    connect(tree_, &QTreeWidget::customContextMenuRequested, this, [this](const QPoint& p) {
        if (!tree_->itemAt(p) || selectionOf(tree_->itemAt(p)).kind == Selection::Kind::None)
            return;
        QMenu menu;
        menu.addAction(tr("Rename"), this, &OutlinerPanel::renameSelected);
        menu.addAction(tr("Duplicate"), this, &OutlinerPanel::duplicateSelected);
        menu.addAction(tr("Delete"), this, &OutlinerPanel::deleteSelected);
        menu.exec(tree_->viewport()->mapToGlobal(p));
    });
    rebuild();
}

void OutlinerPanel::rebuild() {
    updating_ = true;
    // Keep which groups the user collapsed.
    QSet<QString> collapsed;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i)
        if (!tree_->topLevelItem(i)->isExpanded())
            collapsed.insert(tree_->topLevelItem(i)->text(0));
    tree_->clear();
    const scene::Scene& s = document_->scene();

    auto* objects = new QTreeWidgetItem(QStringList{tr("Objects (%1)").arg(s.objects.size())});
    std::vector<QTreeWidgetItem*> objectItems(s.objects.size());
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const scene::Object& o = s.objects[i];
        auto* item = makeItem(nameOr(o.name, tr("object %1").arg(i)), Selection::Kind::Object, int(i), true);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(0, o.visible ? Qt::Checked : Qt::Unchecked);
        item->setToolTip(0, tr("Check box: show/hide. Double-click: rename."));
        objectItems[i] = item;
    }
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const int parent = s.objects[i].parent;
        if (parent >= 0 && std::size_t(parent) < s.objects.size() && parent != int(i))
            objectItems[std::size_t(parent)]->addChild(objectItems[i]);
        else
            objects->addChild(objectItems[i]);
    }
    auto* lights = new QTreeWidgetItem(QStringList{tr("Lights (%1)").arg(s.lights.size())});
    for (std::size_t i = 0; i < s.lights.size(); ++i)
        lights->addChild(makeItem(nameOr(s.lights[i].name, tr("light %1").arg(i)) +
                                      QString(" [%1]").arg(scene::toString(s.lights[i].type)),
                                  Selection::Kind::Light, int(i), false));
    auto* cameras = new QTreeWidgetItem(QStringList{tr("Cameras (%1)").arg(s.cameras.size())});
    for (std::size_t i = 0; i < s.cameras.size(); ++i)
        cameras->addChild(makeItem(nameOr(s.cameras[i].name, tr("camera %1").arg(i)), Selection::Kind::Camera,
                                   int(i), true));
    auto* paths = new QTreeWidgetItem(QStringList{tr("Camera paths (%1)").arg(s.cameraPaths.size())});
    for (std::size_t i = 0; i < s.cameraPaths.size(); ++i)
        paths->addChild(makeItem(nameOr(s.cameraPaths[i].name, tr("path %1").arg(i)), Selection::Kind::CameraPath,
                                 int(i), false));
    for (QTreeWidgetItem* group : {objects, lights, cameras, paths}) {
        group->setFlags(Qt::ItemIsEnabled);
        tree_->addTopLevelItem(group);
        group->setExpanded(!collapsed.contains(group->text(0)));
    }
    updating_ = false;
    applyFilter(filter_->text());
    syncSelectionFromDocument();
}

QTreeWidgetItem* OutlinerPanel::itemFor(const Selection& selection) const {
    if (selection.kind == Selection::Kind::None)
        return nullptr;
    std::function<QTreeWidgetItem*(QTreeWidgetItem*)> find = [&](QTreeWidgetItem* item) -> QTreeWidgetItem* {
        if (selectionOf(item) == selection)
            return item;
        for (int i = 0; i < item->childCount(); ++i)
            if (QTreeWidgetItem* found = find(item->child(i)))
                return found;
        return nullptr;
    };
    for (int i = 0; i < tree_->topLevelItemCount(); ++i)
        if (QTreeWidgetItem* found = find(tree_->topLevelItem(i)))
            return found;
    return nullptr;
}

void OutlinerPanel::refreshObjectLabels() {
    updating_ = true;
    const scene::Scene& s = document_->scene();
    std::function<void(QTreeWidgetItem*)> visit = [&](QTreeWidgetItem* item) {
        const Selection sel = selectionOf(item);
        if (sel.kind == Selection::Kind::Object && std::size_t(sel.index) < s.objects.size()) {
            const scene::Object& o = s.objects[std::size_t(sel.index)];
            const QString name = nameOr(o.name, tr("object %1").arg(sel.index));
            if (item->text(0) != name)
                item->setText(0, name);
            const Qt::CheckState state = o.visible ? Qt::Checked : Qt::Unchecked;
            if (item->checkState(0) != state)
                item->setCheckState(0, state);
        }
        for (int i = 0; i < item->childCount(); ++i)
            visit(item->child(i));
    };
    if (tree_->topLevelItemCount() > 0)
        visit(tree_->topLevelItem(0));
    updating_ = false;
}

void OutlinerPanel::syncSelectionFromDocument() {
    updating_ = true;
    tree_->clearSelection();
    if (QTreeWidgetItem* item = itemFor(document_->selection())) {
        item->setSelected(true);
        for (QTreeWidgetItem* p = item->parent(); p; p = p->parent())
            p->setExpanded(true);
        tree_->scrollToItem(item);
    }
    updating_ = false;
}

void OutlinerPanel::onItemChanged(QTreeWidgetItem* item, int) {
    if (updating_)
        return;
    const Selection sel = selectionOf(item);
    const std::string name = item->text(0).toStdString();
    if (sel.kind == Selection::Kind::Object) {
        scene::Object o = document_->scene().objects[std::size_t(sel.index)];
        const bool visible = item->checkState(0) == Qt::Checked;
        if (visible != o.visible) {
            o.visible = visible;
            document_->setObject(sel.index, o, visible ? tr("Show object") : tr("Hide object"));
        } else if (name != o.name) {
            o.name = name;
            document_->setObject(sel.index, o, tr("Rename object"));
        }
    } else if (sel.kind == Selection::Kind::Camera) {
        scene::Camera c = document_->scene().cameras[std::size_t(sel.index)];
        if (name != c.name) {
            c.name = name;
            document_->setCamera(sel.index, c, tr("Rename camera"));
        }
    }
}

void OutlinerPanel::applyFilter(const QString& text) {
    std::function<bool(QTreeWidgetItem*)> apply = [&](QTreeWidgetItem* item) {
        bool anyChild = false;
        for (int i = 0; i < item->childCount(); ++i)
            anyChild = apply(item->child(i)) || anyChild;
        const bool match = text.isEmpty() || item->text(0).contains(text, Qt::CaseInsensitive);
        item->setHidden(!(match || anyChild));
        return match || anyChild;
    };
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        QTreeWidgetItem* group = tree_->topLevelItem(i);
        for (int c = 0; c < group->childCount(); ++c)
            apply(group->child(c));
    }
}

void OutlinerPanel::renameSelected() {
    if (QTreeWidgetItem* item = itemFor(document_->selection()); item && (item->flags() & Qt::ItemIsEditable))
        tree_->editItem(item, 0);
}

void OutlinerPanel::deleteSelected() {
    const Selection sel = document_->selection();
    const int i = sel.index;
    switch (sel.kind) {
    case Selection::Kind::Object:
        document_->editScene(tr("Delete object"), Change::Structure, [i](scene::Scene& s) {
            // Children move up to the deleted object's parent; later indices shift down by one.
            const int grandParent = s.objects[std::size_t(i)].parent;
            for (scene::Object& o : s.objects) {
                if (o.parent == i)
                    o.parent = grandParent;
                if (o.parent > i)
                    --o.parent;
            }
            s.objects.erase(s.objects.begin() + i);
        });
        break;
    case Selection::Kind::Light:
        document_->editScene(tr("Delete light"), Change::Lights,
                             [i](scene::Scene& s) { s.lights.erase(s.lights.begin() + i); });
        break;
    case Selection::Kind::Camera:
        document_->editScene(tr("Delete camera"), Change::Cameras,
                             [i](scene::Scene& s) { s.cameras.erase(s.cameras.begin() + i); });
        break;
    case Selection::Kind::CameraPath:
        document_->editScene(tr("Delete camera path"), Change::CameraPaths,
                             [i](scene::Scene& s) { s.cameraPaths.erase(s.cameraPaths.begin() + i); });
        break;
    default: return;
    }
    document_->select({});
}

namespace {

// Appends a copy of items[i] named "<name> copy"; returns its index.
template <class Item>
int appendCopy(std::vector<Item>& items, int i) {
    Item copy = items[std::size_t(i)];
    copy.name += " copy";
    items.push_back(copy);
    return int(items.size()) - 1;
}

} // namespace

void OutlinerPanel::duplicateSelected() {
    const Selection sel = document_->selection();
    const int i = sel.index;
    int created = -1;
    switch (sel.kind) {
    case Selection::Kind::Object:
        // The copy shares the mesh (no new geometry) and gets the same parent; children are not copied.
        document_->editScene(tr("Duplicate object"), Change::Structure,
                             [i, &created](scene::Scene& s) { created = appendCopy(s.objects, i); });
        break;
    case Selection::Kind::Light:
        document_->editScene(tr("Duplicate light"), Change::Lights,
                             [i, &created](scene::Scene& s) { created = appendCopy(s.lights, i); });
        break;
    case Selection::Kind::Camera:
        document_->editScene(tr("Duplicate camera"), Change::Cameras,
                             [i, &created](scene::Scene& s) { created = appendCopy(s.cameras, i); });
        break;
    default: return;
    }
    document_->select({sel.kind, created});
}

} // namespace lpv::editor
