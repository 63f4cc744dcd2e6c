#pragma once
// The document the application edits: what a project file keeps (the mesh,
// the style's text, the camera, the user's light, the animation and its
// frame), the loaded mesh, and the undo stack its edits go on, as Tiled's
// Document is. Widgets observe it: every change (an edit, an undo or redo,
// a project opened) emits what changed, and the window passes the widgets'
// edits to its setters. It needs no window and no OpenGL.

#include <memory>
#include <optional>

#include <QObject>
#include <QString>

#include "snaxels/animation/frame_driver.h"
#include "snaxels/animation/pipeline.h"
#include "snaxels/mesh/build.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/mesh/parts.h"
#include "snaxels/project/project.h"
#include "snaxels/scene/orbit.h"
#include "snaxels/style/style.h"

class QUndoStack;

namespace snaxels::ui {

/// What a loaded file offers its document beyond the mesh: the clips and
/// cameras an animation may name, and the sphere the view frames.
struct SceneFacts {
    std::vector<AnimationClipInfo> clips;
    std::vector<FileCamera> cameras;
    glm::dvec3 centre{0.0}; ///< the drawn mesh's bounding-box centre: what the view orbits
    double radius = 1.0;    ///< half its bounding box's diagonal
};

/// @p spec as a scene with @p facts plays it: a clip or camera named by
/// number or left empty gets its name, a clip's or camera move's frame
/// count (0 or less) its length at the spec's rate, and a clip, camera
/// move or camera the scene lacks gives way to a turntable or the view's
/// camera. @p found (if given) says whether everything named was there.
AnimationSpec resolve_animation(const AnimationSpec& spec, const SceneFacts& facts, bool* found = nullptr);

class Document : public QObject {
    Q_OBJECT
  public:
    /// An empty document with @p style_text (the style a new document starts with).
    explicit Document(QString style_text, QObject* parent = nullptr);

    /// The parts of the document that edits change, each an undo step.
    struct Edited {
        QString style;
        OrbitView view;
        std::optional<Light> light;
        AnimationSpec animation;
        bool operator==(const Edited&) const = default;
    };
    Edited edited() const { return {style_, view_, light_, animation_}; }
    /// What the edited parts were where the undo history begins (a mesh
    /// or project opened, or changes that are not edits made while the
    /// history was empty): the undo stack's steps, carried out on these
    /// from the first, give edited() at the stack's index.
    const Edited& historyStart() const { return historyStart_; }
    /// Sets the edited parts to @p edited with no undo step (the start of
    /// a replay on a fresh document).
    void restore(const Edited& edited);

    QUndoStack* undoStack() const { return undo_; }

    const QString& styleText() const { return style_; }
    /// The style in force: the text's, or, while the text does not parse,
    /// the last one that did.
    const Style& style() const { return parsed_; }
    const OrbitView& view() const { return view_; }
    /// The light the user set (none: the style's light, else the default one).
    const std::optional<Light>& light() const { return light_; }
    const AnimationSpec& animation() const { return animation_; }
    /// The animation's frame shown now (0 to its frame count less one).
    int frame() const { return frame_; }
    /// The source's frame shown now: the animation's in point plus frame().
    int sourceFrame() const { return animation_.start + frame_; }
    /// How far a turntable or an orbiting light has turned at the frame shown (degrees).
    double frameDegrees() const { return animation_.degrees_per_frame * sourceFrame(); }
    /// The loaded file's clips, cameras and framing sphere.
    const SceneFacts& scene() const { return facts_; }
    /// The view that frames the mesh: its front from a little above and to
    /// the side, standing on +Y (View > Reset Camera, and a new mesh's).
    OrbitView framingView() const;
    /// The style's warnings (patterns naming no part of the scene among
    /// them), from the one parse of its text each edit makes.
    const std::vector<StyleDiagnostic>& styleWarnings() const { return warnings_; }
    /// Why the style's text does not parse (none when it does): the last
    /// style that parsed stays in force meanwhile.
    const std::optional<StyleDiagnostic>& styleProblem() const { return problem_; }
    /// The mesh loaded now: its path or proc: spec, and the mesh.
    const QString& meshSpec() const { return meshSpec_; }
    const std::shared_ptr<const LoadedMesh>& mesh() const { return mesh_; }
    /// The animation the document describes, as the export writes it (its
    /// style, camera at frame 0, light and animation; the callbacks and the
    /// output are the caller's).
    AnimationJob animationJob() const;
    /// Empty until saved or opened.
    const QString& projectPath() const { return projectPath_; }
    /// Unsaved changes: an edit since the last save or open that left the
    /// edited parts other than the file's, or a new mesh.
    bool isModified() const;

    // Edits: each is one undo step (quick successions of one kind merge into
    // one) and emits what changed; setting the value it has does nothing.
    void setStyleText(const QString& text);
    /// The style's text set as one undo step named @p step, never merged
    /// with the typing before or after it (a part hidden from the Objects panel).
    void setStyleText(const QString& text, const QString& step);
    void setView(const OrbitView& view);
    /// A camera change that is a step of its own, named @p step in the
    /// Edit menu (a named view, an up axis): never merged with a drag.
    void setView(const OrbitView& view, const QString& step);
    void setLight(const std::optional<Light>& light);
    void setAnimation(const AnimationSpec& animation);

    // Changes that are not edits (no undo step), each emitting what changed.
    /// Where playback stands (clamped to the animation's frames): saved
    /// with the project, not undone.
    void setFrame(int frame);
    /// A new mesh (the document differs from its file, if any, from now on).
    void setMesh(const QString& spec, std::shared_ptr<const LoadedMesh> mesh);
    /// A new untitled document for a mesh just opened (@p spec, @p mesh,
    /// whose file offers @p facts), framed by framingView() and starting
    /// with @p animation (resolved): this document's style stays, less the
    /// objects the mesh lacks, the user's light goes, the frame is 0, the
    /// undo history is cleared, there is no project file, and it is not
    /// modified.
    void startNew(const QString& spec, std::shared_ptr<const LoadedMesh> mesh, const SceneFacts& facts,
                  const AnimationSpec& animation);
    /// The style a session starts with (a style given on the command line,
    /// read from @p source, which its diagnostics name).
    void resetStyleText(const QString& text, const QString& source = QStringLiteral("style"));
    /// The camera framed on a new mesh.
    void resetView(const OrbitView& view);
    /// The animation a new mesh or sequence starts with.
    void resetAnimation(const AnimationSpec& animation);
    /// What the window shows is no longer what the file holds (a clip it
    /// names is missing, say).
    void markModified();

    /// The project as it would be saved at @p path: the mesh and a
    /// sequence's files relative to its folder.
    Project project(const QString& path) const;
    /// Writes the project to @p path atomically; the document is then clean
    /// and at @p path. Throws snaxels::Error (nothing changes then).
    void save(const QString& path);
    /// Replaces the document with @p project, read from @p path, whose mesh
    /// (@p mesh_spec, @p mesh, offering @p facts) has been loaded: a
    /// sequence's pattern is resolved against @p path, an empty style is
    /// the default style, the view orbits the mesh's centre, the undo
    /// history is cleared and the document is clean. Returns why the
    /// document differs from the file (a clip or camera the mesh lacks, the
    /// document then modified), or an empty string.
    QString load(const Project& project, const QString& path, const QString& mesh_spec,
                 std::shared_ptr<const LoadedMesh> mesh, const SceneFacts& facts = {});

  signals:
    void styleTextChanged(const QString& text);
    /// The style in force changed (its text parsed).
    void styleChanged(const snaxels::Style& style);
    /// The style's text was parsed (or failed to) and checked against the
    /// scene: styleWarnings() and styleProblem() are new.
    void styleChecked();
    void viewChanged(const snaxels::OrbitView& view);
    void lightChanged(const std::optional<snaxels::Light>& light);
    void animationChanged(const snaxels::AnimationSpec& animation);
    void frameChanged(int frame);
    void meshChanged();
    void projectPathChanged(const QString& path);
    void modifiedChanged(bool modified);

  private:
    /// One undo step from @p now to @p value (none if they are equal), applied by @p assign.
    template <class T>
    void edit(const T& now, const T& value, const QString& text, int id, void (Document::*assign)(const T&),
              bool mergeable = true);
    void assignStyle(const QString& text);
    /// Parses the style's text (once per change), checks it against the
    /// scene's parts, and tells the observers.
    void parseStyle();
    void assignView(const OrbitView& view);
    void assignLight(const std::optional<Light>& light);
    void assignAnimation(const AnimationSpec& animation);
    void setMeshChanged(bool changed);
    /// Emits modifiedChanged when isModified() is no longer what it last said.
    void updateModified();
    /// Clears the undo history, which now begins at the present state.
    void startHistory();
    /// A change that is not an edit: it moves the history's start while
    /// the history is empty.
    void changedOutsideHistory();

    QUndoStack* undo_;
    QString defaultStyle_;
    QString style_;
    QString styleSource_ = QStringLiteral("style"); ///< what the style's diagnostics name
    Style parsed_;
    std::vector<StyleDiagnostic> warnings_;
    std::optional<StyleDiagnostic> problem_;
    std::shared_ptr<const FaceParts> parts_; ///< the mesh's, which style patterns are checked against
    SceneFacts facts_;
    OrbitView view_;
    std::optional<Light> light_;
    AnimationSpec animation_;
    int frame_ = 0;
    QString meshSpec_;
    std::shared_ptr<const LoadedMesh> mesh_;
    QString projectPath_;
    bool meshChanged_ = false; ///< a new mesh, or a difference no undo step holds
    Edited historyStart_;
    /// The edited parts as the file holds them (or as a new document
    /// began): undone or typed back to these, nothing is left to save.
    Edited saved_;
    bool lastModified_ = false; ///< what modifiedChanged last said
};

} // namespace snaxels::ui
