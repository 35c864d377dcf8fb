#include "EditCommands.h"

#include "lpv/scene/ParameterRegistry.h"

namespace lpv::editor {

ParameterCommand::ParameterCommand(Document* doc, std::string key, std::optional<scene::ParameterValue> before,
                                   std::optional<scene::ParameterValue> after)
    : doc_(doc), key_(std::move(key)), before_(std::move(before)), after_(std::move(after)) {
    setText(QString("Set %1").arg(QString::fromStdString(key_)));
    age_.start();
}

void ParameterCommand::apply(const std::optional<scene::ParameterValue>& value) {
    scene::ParameterSet& params = doc_->mutableProject().parameters;
    if (value) {
        // Values reach here validated by Document::setParameter.
        [[maybe_unused]] auto ok = params.set(key_, *value, "editor");
    } else {
        params.reset(key_);
    }
    doc_->notifyChanged(Change::Parameters);
}

void ParameterCommand::undo() { apply(before_); }
void ParameterCommand::redo() { apply(after_); }

bool ParameterCommand::mergeWith(const QUndoCommand* other) {
    auto* o = dynamic_cast<const ParameterCommand*>(other);
    if (!o || o->key_ != key_ || age_.elapsed() > kMergeWindowMs)
        return false;
    after_ = o->after_;
    age_.restart();
    return true;
}

AllParametersCommand::AllParametersCommand(Document* doc, scene::ParameterSet before, scene::ParameterSet after,
                                           const QString& text)
    : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)) {}

void AllParametersCommand::undo() {
    doc_->mutableProject().parameters = before_;
    doc_->notifyChanged(Change::Parameters);
}

void AllParametersCommand::redo() {
    doc_->mutableProject().parameters = after_;
    doc_->notifyChanged(Change::Parameters);
}

SkyCommand::SkyCommand(Document* doc, scene::Sky before, scene::Sky after, const QString& text)
    : QUndoCommand(text), doc_(doc), before_(before), after_(after) {
    age_.start();
}

bool SkyCommand::mergeWith(const QUndoCommand* other) {
    auto* o = dynamic_cast<const SkyCommand*>(other);
    if (!o || o->text() != text() || age_.elapsed() > kMergeWindowMs)
        return false;
    after_ = o->after_;
    age_.restart();
    return true;
}

void SkyCommand::undo() {
    doc_->mutableProject().scene.sky = before_;
    doc_->notifyChanged(Change::Sky);
}

void SkyCommand::redo() {
    doc_->mutableProject().scene.sky = after_;
    doc_->notifyChanged(Change::Sky);
}

PresetsCommand::PresetsCommand(Document* doc, std::vector<scene::ParameterPreset> before,
                               std::vector<scene::ParameterPreset> after, const QString& text)
    : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)) {}

void PresetsCommand::undo() {
    doc_->mutableProject().presets = before_;
    doc_->notifyChanged(Change::Presets);
}

void PresetsCommand::redo() {
    doc_->mutableProject().presets = after_;
    doc_->notifyChanged(Change::Presets);
}

SceneParts SceneParts::of(const scene::Scene& s) {
    return {s.objects, s.materials, s.lights, s.cameras, s.cameraPaths};
}

void SceneParts::applyTo(scene::Scene& s) const {
    s.objects = objects;
    s.materials = materials;
    s.lights = lights;
    s.cameras = cameras;
    s.cameraPaths = cameraPaths;
}

SceneEditCommand::SceneEditCommand(Document* doc, const QString& text, Changes changes, SceneParts before,
                                   SceneParts after, std::size_t meshCountBefore, std::vector<scene::Mesh> addedMeshes)
    : QUndoCommand(text), doc_(doc), changes_(changes), before_(std::move(before)), after_(std::move(after)),
      meshCountBefore_(meshCountBefore), addedMeshes_(std::move(addedMeshes)) {}

void SceneEditCommand::undo() {
    scene::Scene& s = doc_->mutableProject().scene;
    before_.applyTo(s);
    s.meshes.resize(meshCountBefore_);
    applied_ = false;
    doc_->notifyChanged(changes_);
}

void SceneEditCommand::redo() {
    if (applied_) // pushed after the edit was made
        return;
    scene::Scene& s = doc_->mutableProject().scene;
    after_.applyTo(s);
    s.meshes.insert(s.meshes.end(), addedMeshes_.begin(), addedMeshes_.end());
    applied_ = true;
    doc_->notifyChanged(changes_);
}

} // namespace lpv::editor
