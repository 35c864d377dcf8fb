#pragma once
// The open project and every edit to it. Each edit is one QUndoCommand on
// the document's undo stack (EditCommands.h); views never change the project
// directly, they call a Document method and refresh on `changed`.
#include "lpv/scene/Project.h"
#include "lpv/scene/ValueChecks.h"

#include <QFlags>
#include <QObject>
#include <QString>

#include <functional>
#include <optional>
#include <string>

class QUndoStack;

namespace lpv::editor {

// What an edit touched, so each view refreshes only what it shows and the
// viewport re-uploads only what the GPU holds.
enum class Change : unsigned {
    Parameters = 1u << 0,  // the project's parameter values
    Transforms = 1u << 1,  // object transforms, visibility, names (no new geometry)
    Structure = 1u << 2,   // objects added or removed, parents changed
    Geometry = 1u << 9,    // meshes added or removed (the GPU re-uploads vertices)
    Materials = 1u << 3,
    Lights = 1u << 4,
    Cameras = 1u << 5,
    CameraPaths = 1u << 6,
    Sky = 1u << 7,
    Presets = 1u << 8,
    Everything = 0xffffu,  // a new project was opened
};
Q_DECLARE_FLAGS(Changes, Change)
Q_DECLARE_OPERATORS_FOR_FLAGS(Changes)

// What the user selected, in the outliner or by clicking in the viewport.
struct Selection {
    enum class Kind { None, Object, Light, Camera, CameraPath, Material };
    Kind kind = Kind::None;
    int index = -1;

    bool operator==(const Selection&) const = default;
    bool isObject() const { return kind == Kind::Object && index >= 0; }
};

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    const scene::Project& project() const { return project_; }
    const scene::Scene& scene() const { return project_.scene; }
    const scene::ParameterSet& parameters() const { return project_.parameters; }
    // The file the project was loaded from or last saved to; empty for a new project.
    const QString& path() const { return path_; }
    // The folder texture paths are relative to.
    QString projectDir() const;
    QUndoStack* undoStack() const { return undoStack_; }
    bool isModified() const;

    // What the user calls it (window title, questions): the file's name
    // without its extension, or "Untitled" for a project not on disk yet.
    QString displayName() const;

    // Replaces the whole project (New, Open, crash recovery): clears undo
    // history. `modified` marks it unsaved (a recovered autosave).
    // `assetsOf` is the file its relative texture paths are relative to when
    // that is not `path`: a template opened as an untitled copy (empty path)
    // still finds the textures in its own folder.
    void reset(scene::Project project, const QString& path, bool modified = false,
               const QString& assetsOf = {});
    // Atomic save (scene::saveProject); on success the document is clean and takes `path`.
    scene::Expected<void> saveAs(const QString& path);
    // The view the next save records (Project::editorView), so that the
    // project opens where the user left it. Not an edit: no undo, not "modified".
    void setEditorView(const scene::Camera& view);

    // ---- Edits: each pushes one undoable command. ----
    // nullopt resets the key to its default. Consecutive edits of one key
    // within a second (a slider drag) merge into one undo step.
    void setParameter(const std::string& key, std::optional<scene::ParameterValue> value);
    // Replaces every parameter value at once (applying a preset).
    void setAllParameters(const scene::ParameterSet& values, const QString& text);
    void setObject(int index, const scene::Object& object, const QString& text);
    void setMaterial(int index, const scene::Material& material, const QString& text);
    void setLight(int index, const scene::Light& light, const QString& text);
    void setCamera(int index, const scene::Camera& camera, const QString& text);
    void setSky(const scene::Sky& sky, const QString& text);
    void setCameraPath(int index, const scene::CameraPath& path, const QString& text);
    // Named parameter presets: save the current values under `name`
    // (replacing a preset of that name), apply one, delete one.
    void savePreset(const std::string& name);
    void applyPreset(int index);
    void deletePreset(int index);
    // A structural edit (add, delete, duplicate, import): `edit` may change
    // objects, lights, cameras, camera paths and materials freely and may
    // append meshes, but must not change or remove existing meshes.
    void editScene(const QString& text, Changes changes, const std::function<void(scene::Scene&)>& edit);

    const Selection& selection() const { return selection_; }
    void select(Selection selection);

    // ---- Used by the undo commands only. ----
    scene::Project& mutableProject() { return project_; }
    void notifyChanged(Changes changes);

signals:
    void changed(lpv::editor::Changes changes);
    void selectionChanged(const lpv::editor::Selection& selection);
    // The file path or the modified state changed (window title).
    void titleChanged();
    // A save to `path` succeeded (what is kept beside the project saves too).
    void projectSaved(const QString& path);
    // An edit was not applied: a save would refuse the value (ValueChecks.h).
    void editRefused(const QString& message);

  private:
    bool refuses(const std::optional<scene::ValueProblem>& problem, const QString& what);
    // One undoable edit of scene.*member[index], unless it changes nothing or `problem` refuses it.
    template <class T>
    void setElement(std::vector<T> scene::Scene::*member, int index, const T& after,
                    const std::optional<scene::ValueProblem>& problem, const QString& what, Changes changes,
                    const QString& text);

    scene::Project project_;
    QString path_;
    QUndoStack* undoStack_ = nullptr;
    Selection selection_;
    bool recoveredUnsaved_ = false;
};

} // namespace lpv::editor
