#pragma once
// Opening, saving and closing the document, as Tiled's DocumentManager
// does for its documents: a mesh, a numbered sequence of meshes or a
// project is read off the GUI thread (MeshLoader) and replaces the
// document once its mesh has loaded, after asking about unsaved changes;
// a project is saved atomically; nothing of the document changes when
// something fails. The controller asks the user in dialogs over
// @p dialogParent and tells what happened by its signals; it holds no other
// widget, and the window shows the document it changes.

#include <functional>
#include <optional>

#include <QObject>
#include <QString>

#include "snaxels/animation/frame_driver.h"
#include "snaxels/project/project.h"
#include "ui/mesh_loader.h"

class QWidget;

namespace snaxels::ui {

class Document;
struct SceneFacts;

/// The animation a file opens on: through its first camera if it has
/// cameras; its own clip, whole, if it has clips (the one that moves that
/// camera, else the first); else, through a camera, the still it frames,
/// or the turntable a new mesh starts with.
AnimationSpec first_look(const SceneFacts& facts);

class DocumentController : public QObject {
    Q_OBJECT
  public:
    DocumentController(Document* document, QWidget* dialogParent);

    /// Edits a widget holds that have not reached the document yet (typing
    /// not yet taken up) are handed over by @p flush before the document
    /// is saved, exported or asked about.
    void setFlush(std::function<void()> flush) { flush_ = std::move(flush); }
    /// Hands the widgets' pending edits to the document (setFlush).
    void flush() const;

    /// Opens a project (.snaxels) or a mesh, by the file's extension.
    void openFile(const QString& path);
    /// Opens @p spec (a file path or proc:NAME[:FACES]) as a new untitled
    /// document, after asking to save unsaved changes.
    void openMesh(const QString& spec);
    /// Opens the numbered series of mesh files @p path belongs to: its first
    /// file is the mesh and the animation plays the files. False, with a
    /// message, when the name holds no frame number or the series has one file.
    bool openSequence(const QString& path);
    /// Reads the project at @p path and loads its mesh; the project
    /// replaces the document once the mesh has loaded (projectOpened or
    /// projectFailed; the document is untouched on failure).
    void openProject(const QString& path);
    /// Saves the document as a project at @p path (atomically); a failure is said in a box.
    bool save(const QString& path);
    /// File > Save (at the project's path, asking where when it has none)
    /// and Save As (@p askPath).
    bool saveInteractive(bool askPath);
    /// Asks to save unsaved changes: false when the user cancels.
    bool maybeSave();
    /// File > New: after asking about unsaved changes, a new untitled
    /// document on the bundled default scene, with the default style.
    void newDocument();
    /// File > Close: after asking about unsaved changes, an empty document
    /// (no mesh; the window waits for one to be opened or dropped).
    bool closeDocument();
    /// File > Revert: after the user agrees to lose the changes, the
    /// document read again from its project file, or its mesh opened anew
    /// when it has none. False when there is nothing to revert to or the
    /// user declines.
    bool revert();

    bool loading() const { return loader_->loading(); }
    /// The spec being read, or read last.
    const QString& loadingSpec() const { return loader_->spec(); }

  signals:
    /// A mesh has been read: the document takes it next (the window shows
    /// its geometry and the scene's clips and cameras first).
    void loaded(const snaxels::ui::LoadResult& result);
    /// Loading started (@p on) or ended.
    void busy(bool on);
    void meshLoaded(const QString& spec);
    void loadFailed(const QString& message);
    void projectOpened(const QString& path);
    void projectFailed(const QString& message);
    void projectSaved(const QString& path);
    /// A line for the status bar, for @p ms milliseconds (0: until replaced).
    void status(const QString& text, int ms);
    /// The recent files changed (QSettings "recentFiles").
    void recentFilesChanged();

  private:
    /// True, saying so, while a mesh is being read: one load at a time.
    bool refuseWhileLoading();
    void startLoading(const QString& spec);
    /// Reads the project at @p path and starts loading its mesh, asking
    /// about unsaved changes first when @p ask.
    void loadProject(const QString& path, bool ask);
    void onLoaded(const LoadResult& result);
    void onLoadFailed(const LoadResult& result);
    void addRecentFile(const QString& path);
    /// A warning that names what failed, in a box that does not block.
    void warn(const QString& title, const QString& message);

    Document* document_;
    QWidget* dialogParent_;
    MeshLoader* loader_;
    std::function<void()> flush_;
    std::optional<Project> pendingProject_;
    QString pendingProjectPath_;
    std::optional<SequenceFiles> pendingSequence_; ///< shown once its first file has loaded
    bool pendingDefaultStyle_ = false;              ///< File > New: the new document takes the default style
};

/// At most this many files are listed in File > Open Recent.
inline constexpr int kMaxRecentFiles = 8;

} // namespace snaxels::ui
