#pragma once
// What the Properties panels of one element of a scene list share (a
// light, a material, an object, a camera): the element they show (its
// index in the list, -1 for none), the undoable edit of it through the
// document, and the check that the index still names one. Each panel adds
// its widgets and refresh().
#include "Document.h"
#include "PropertyWidgets.h"

#include <QWidget>

#include <functional>
#include <vector>

namespace lpv::editor {

template <typename Element> class ElementPanel : public QWidget {
  public:
    using List = std::vector<Element> scene::Scene::*;
    using Setter = void (Document::*)(int, const Element&, const QString&);

    // -1 shows nothing.
    void setIndex(int index) {
        if (index != index_) {
            index_ = index;
            forgetLastElement();
        }
        refresh();
    }
    int index() const { return index_; }
    // Re-reads the element from the document without emitting edits.
    virtual void refresh() = 0;

  protected:
    ElementPanel(Document* doc, List list, Setter set, QWidget* parent)
        : QWidget(parent), doc_(doc), list_(list), set_(set) {}

    // What a panel keeps of the element it showed (angles typed, a colour
    // set aside) is dropped when it shows another.
    virtual void forgetLastElement() {}
    // One undoable edit of the element shown; nothing when none is.
    void edit(const QString& text, const std::function<void(Element&)>& change) {
        editElement(doc_, list_, set_, index_, text, change);
    }
    // The element shown, or null when the index names none; the panel is
    // enabled only while it shows one.
    const Element* shownElement() {
        const std::vector<Element>& elements = doc_->scene().*list_;
        const bool valid = index_ >= 0 && std::size_t(index_) < elements.size();
        setEnabled(valid);
        return valid ? &elements[std::size_t(index_)] : nullptr;
    }

    Document* doc_;

  private:
    int index_ = -1;
    List list_;
    Setter set_;
};

} // namespace lpv::editor
