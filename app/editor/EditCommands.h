#pragma once
// The undo commands behind every Document edit. Like Tiled's ChangeValue,
// one generic command swaps a value in and out; edits of the same target
// that follow each other within a second (dragging a slider or a gizmo)
// merge into one undo step.
#include "Document.h"

#include <QElapsedTimer>
#include <QUndoCommand>

#include <optional>
#include <string>
#include <vector>

namespace lpv::editor {

// Merge ids, one per command type (QUndoCommand::id).
enum CommandId { kParameterCommand = 1, kElementCommand = 2, kSkyCommand = 3 };

// How long after an edit a following edit of the same target still merges into it.
inline constexpr qint64 kMergeWindowMs = 1000;

class ParameterCommand : public QUndoCommand {
public:
    ParameterCommand(Document* doc, std::string key, std::optional<scene::ParameterValue> before,
                     std::optional<scene::ParameterValue> after);
    void undo() override;
    void redo() override;
    int id() const override { return kParameterCommand; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const std::optional<scene::ParameterValue>& value);
    Document* doc_;
    std::string key_;
    std::optional<scene::ParameterValue> before_, after_;
    QElapsedTimer age_;
};

class AllParametersCommand : public QUndoCommand {
public:
    AllParametersCommand(Document* doc, scene::ParameterSet before, scene::ParameterSet after, const QString& text);
    void undo() override;
    void redo() override;

private:
    Document* doc_;
    scene::ParameterSet before_, after_;
};

// Replaces one element of one of the scene's vectors (an object, a material, a light, a camera).
template <class T>
class ElementCommand : public QUndoCommand {
public:
    using Member = std::vector<T> scene::Scene::*;
    ElementCommand(Document* doc, Member member, int index, T before, T after, Changes changes, const QString& text)
        : QUndoCommand(text), doc_(doc), member_(member), index_(index), before_(std::move(before)),
          after_(std::move(after)), changes_(changes) {
        age_.start();
    }
    void undo() override { apply(before_); }
    void redo() override { apply(after_); }
    int id() const override { return kElementCommand; }
    bool mergeWith(const QUndoCommand* other) override {
        auto* o = dynamic_cast<const ElementCommand<T>*>(other);
        if (!o || o->member_ != member_ || o->index_ != index_ || o->text() != text() ||
            age_.elapsed() > kMergeWindowMs)
            return false;
        after_ = o->after_;
        age_.restart();
        return true;
    }

private:
    void apply(const T& value) {
        (doc_->mutableProject().scene.*member_)[std::size_t(index_)] = value;
        doc_->notifyChanged(changes_);
    }
    Document* doc_;
    Member member_;
    int index_;
    T before_, after_;
    Changes changes_;
    QElapsedTimer age_;
};

class SkyCommand : public QUndoCommand {
public:
    SkyCommand(Document* doc, scene::Sky before, scene::Sky after, const QString& text);
    void undo() override;
    void redo() override;
    int id() const override { return kSkyCommand; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* doc_;
    scene::Sky before_, after_;
    QElapsedTimer age_;
};

class PresetsCommand : public QUndoCommand {
public:
    PresetsCommand(Document* doc, std::vector<scene::ParameterPreset> before, std::vector<scene::ParameterPreset> after,
                   const QString& text);
    void undo() override;
    void redo() override;

private:
    Document* doc_;
    std::vector<scene::ParameterPreset> before_, after_;
};

// The parts of a scene a structural edit may change, whole; meshes are only
// ever appended, so they are kept as the count before and the meshes added.
struct SceneParts {
    std::vector<scene::Object> objects;
    std::vector<scene::Material> materials;
    std::vector<scene::Light> lights;
    std::vector<scene::Camera> cameras;
    std::vector<scene::CameraPath> cameraPaths;

    static SceneParts of(const scene::Scene& s);
    void applyTo(scene::Scene& s) const;
};

class SceneEditCommand : public QUndoCommand {
public:
    // The edit has already been applied to the document; the first redo() does nothing.
    SceneEditCommand(Document* doc, const QString& text, Changes changes, SceneParts before, SceneParts after,
                     std::size_t meshCountBefore, std::vector<scene::Mesh> addedMeshes);
    void undo() override;
    void redo() override;

private:
    Document* doc_;
    Changes changes_;
    SceneParts before_, after_;
    std::size_t meshCountBefore_;
    std::vector<scene::Mesh> addedMeshes_;
    bool applied_ = true;
};

} // namespace lpv::editor
