#include "Document.h"

#include "EditCommands.h"

#include "lpv/scene/ProjectTextures.h"
#include "lpv/scene/ValueChecks.h"

#include <QDir>
#include <QFileInfo>
#include <QUndoStack>

#include <algorithm>

namespace lpv::editor {

Document::Document(QObject* parent) : QObject(parent), undoStack_(new QUndoStack(this)) {
    connect(undoStack_, &QUndoStack::cleanChanged, this, &Document::titleChanged);
}

Document::~Document() = default;

QString Document::projectDir() const {
    return path_.isEmpty() ? QDir::currentPath() : QFileInfo(path_).absolutePath();
}

bool Document::isModified() const { return recoveredUnsaved_ || !undoStack_->isClean(); }

QString Document::displayName() const {
    return path_.isEmpty() ? tr("Untitled") : QFileInfo(path_).completeBaseName();
}

void Document::reset(scene::Project project, const QString& path, bool modified, const QString& assetsOf) {
    undoStack_->clear();
    project_ = std::move(project);
    // In memory, texture paths are absolute: they stay valid whatever folder
    // the project is saved to next (Save As); saving makes them relative again.
    // (Meshes are read into memory by loadProject, so they need no path.)
    const QString from = assetsOf.isEmpty() ? path : assetsOf;
    if (!from.isEmpty()) {
        const QDir dir = QFileInfo(from).absoluteDir();
        for (scene::Material& m : project_.scene.materials)
            for (std::string* slot : scene::textureSlots(m))
                if (!slot->empty() && QFileInfo(QString::fromStdString(*slot)).isRelative())
                    *slot = QDir::cleanPath(dir.filePath(QString::fromStdString(*slot))).toStdString();
    }
    path_ = path;
    recoveredUnsaved_ = modified;
    selection_ = {};
    emit selectionChanged(selection_);
    notifyChanged(Change::Everything);
    emit titleChanged();
}

// An edit the project reader would refuse (ValueChecks.h: a product that
// overflows, an up vector along the view) is not applied: the renderer would
// turn it into NaN and the next save would fail on it.
bool Document::refuses(const std::optional<scene::ValueProblem>& problem, const QString& what) {
    if (!problem)
        return false;
    emit editRefused(
        tr("%1, %2: %3")
            .arg(what, QString::fromStdString(problem->field), QString::fromStdString(problem->message)));
    return true;
}

void Document::setEditorView(const scene::Camera& view) {
    // Not recorded when a save would refuse it (an orbit straight down keeps +Y up).
    if (scene::checkCamera(view))
        return;
    project_.editorView = view;
    project_.editorView->name = "Editor view";
}

scene::Expected<void> Document::saveAs(const QString& path) {
    // Textures are copied into the project's assets folder and the saved copy
    // points there; the document keeps its absolute paths (see reset).
    scene::Project copy = project_;
    if (auto copied = scene::copyTexturesIntoProject(copy.scene, path.toStdString()); !copied)
        return std::unexpected(copied.error());
    // An undo after this save may bring back a texture no material uses now:
    // its copy stays until a save with nothing to undo.
    scene::SaveOptions options;
    options.collectOrphanTextures = undoStack_->count() == 0;
    auto saved = scene::saveProject(copy, path.toStdString(), options);
    if (!saved)
        return saved;
    path_ = path;
    recoveredUnsaved_ = false;
    undoStack_->setClean();
    emit titleChanged();
    emit projectSaved(path);
    return {};
}

void Document::setParameter(const std::string& key, std::optional<scene::ParameterValue> value) {
    const scene::ParameterSet& params = project_.parameters;
    std::optional<scene::ParameterValue> before;
    if (params.isSet(key))
        before = params.get(key);
    if (value && !scene::ParameterRegistry::instance().validate(key, *value, "editor"))
        return; // the inspector's widgets keep values in range; nothing else calls with bad ones
    if (before == value)
        return;
    undoStack_->push(new ParameterCommand(this, key, std::move(before), std::move(value)));
}

void Document::setAllParameters(const scene::ParameterSet& values, const QString& text) {
    if (values == project_.parameters)
        return;
    undoStack_->push(new AllParametersCommand(this, project_.parameters, values, text));
}

template <class T>
void Document::setElement(std::vector<T> scene::Scene::*member, int index, const T& after,
                          const std::optional<scene::ValueProblem>& problem, const QString& what, Changes changes,
                          const QString& text) {
    const T& before = (project_.scene.*member).at(std::size_t(index));
    if (before == after || refuses(problem, what))
        return;
    undoStack_->push(new ElementCommand<T>(this, member, index, before, after, changes, text));
}

void Document::setObject(int index, const scene::Object& object, const QString& text) {
    // A parent change alters world matrices of children: still only transforms.
    setElement(&scene::Scene::objects, index, object, scene::checkObject(object), tr("Object"), Change::Transforms,
               text);
}

void Document::setMaterial(int index, const scene::Material& material, const QString& text) {
    setElement(&scene::Scene::materials, index, material, scene::checkMaterial(material), tr("Material"),
               Change::Materials, text);
}

void Document::setLight(int index, const scene::Light& light, const QString& text) {
    setElement(&scene::Scene::lights, index, light, scene::checkLight(light), tr("Light"), Change::Lights, text);
}

void Document::setCamera(int index, const scene::Camera& camera, const QString& text) {
    setElement(&scene::Scene::cameras, index, camera, scene::checkCamera(camera), tr("Camera"), Change::Cameras,
               text);
}

void Document::setCameraPath(int index, const scene::CameraPath& path, const QString& text) {
    const scene::CameraPath& before = project_.scene.cameraPaths.at(std::size_t(index));
    if (before == path)
        return;
    for (const scene::CameraKeyframe& key : path.keyframes)
        if (refuses(scene::checkKeyframe(key), tr("Camera path key")))
            return;
    undoStack_->push(new ElementCommand<scene::CameraPath>(this, &scene::Scene::cameraPaths, index, before, path,
                                                           Change::CameraPaths, text));
}

void Document::setSky(const scene::Sky& sky, const QString& text) {
    if (sky == project_.scene.sky || refuses(scene::checkSky(sky), tr("Sky")))
        return;
    undoStack_->push(new SkyCommand(this, project_.scene.sky, sky, text));
}

void Document::savePreset(const std::string& name) {
    std::vector<scene::ParameterPreset> presets = project_.presets;
    auto it = std::find_if(presets.begin(), presets.end(), [&](const auto& p) { return p.name == name; });
    if (it != presets.end())
        it->parameters = project_.parameters;
    else
        presets.push_back({name, project_.parameters});
    undoStack_->push(new PresetsCommand(this, project_.presets, std::move(presets),
                                        tr("Save preset %1").arg(QString::fromStdString(name))));
}

void Document::applyPreset(int index) {
    const scene::ParameterPreset& preset = project_.presets.at(std::size_t(index));
    setAllParameters(preset.parameters, tr("Apply preset %1").arg(QString::fromStdString(preset.name)));
}

void Document::deletePreset(int index) {
    std::vector<scene::ParameterPreset> presets = project_.presets;
    const QString name = QString::fromStdString(presets.at(std::size_t(index)).name);
    presets.erase(presets.begin() + index);
    undoStack_->push(new PresetsCommand(this, project_.presets, std::move(presets), tr("Delete preset %1").arg(name)));
}

void Document::editScene(const QString& text, Changes changes, const std::function<void(scene::Scene&)>& edit) {
    scene::Scene& s = project_.scene;
    const std::size_t meshCount = s.meshes.size();
    SceneParts before = SceneParts::of(s);
    edit(s);
    Q_ASSERT(s.meshes.size() >= meshCount);
    std::vector<scene::Mesh> added(s.meshes.begin() + std::ptrdiff_t(meshCount), s.meshes.end());
    if (!added.empty())
        changes |= Change::Structure | Change::Geometry;
    // A selection that pointed past the end of a shrunk list is dropped.
    notifyChanged(changes);
    undoStack_->push(new SceneEditCommand(this, text, changes, std::move(before), SceneParts::of(s), meshCount,
                                          std::move(added)));
}

void Document::select(Selection selection) {
    if (selection == selection_)
        return;
    selection_ = selection;
    emit selectionChanged(selection_);
}

void Document::notifyChanged(Changes changes) {
    // Keep the selection valid after deletions and undo of additions.
    const scene::Scene& s = project_.scene;
    auto count = [&](Selection::Kind k) -> std::size_t {
        switch (k) {
        case Selection::Kind::Object: return s.objects.size();
        case Selection::Kind::Light: return s.lights.size();
        case Selection::Kind::Camera: return s.cameras.size();
        case Selection::Kind::CameraPath: return s.cameraPaths.size();
        case Selection::Kind::Material: return s.materials.size();
        case Selection::Kind::None: return 0;
        }
        return 0;
    };
    if (selection_.kind != Selection::Kind::None && std::size_t(selection_.index) >= count(selection_.kind))
        select({});
    emit changed(changes);
}

} // namespace lpv::editor
