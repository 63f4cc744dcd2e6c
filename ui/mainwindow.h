#pragma once
// The main window: a frame of the 3-D view, the SVG pane, the style editor
// and the timeline around one Document (mesh, style, camera, light,
// animation, with its undo stack, saved as a project file); menus, recent
// files, drag-and-drop and a status bar. The work runs in controllers
// beside it, each testable without a window, on worker threads so the
// window never freezes: MeshLoader reads meshes, ContourScheduler computes
// the contours the views show, ParabolicSearch finds parabolic curves and
// AnimationExport writes animations.

#include <functional>
#include <memory>
#include <optional>

#include <QMainWindow>

#include "snaxels/animation/pipeline.h"
#include "snaxels/mesh/build.h"
#include "snaxels/project/project.h"
#include "ui/contour_overlay.h"
#include "ui/mesh_loader.h"

class QAction;
class QLabel;
class QSvgWidget;
class QTimer;
class QMenu;
class QProgressBar;
class QToolButton;
class QUndoStack;

namespace snaxels::ui {

class AnimationExport;
class ContourScheduler;
class Document;
class MeshView;
class ObjectsPanel;
class ParabolicSearch;
class StyleEditor;
class SvgPane;
class Timeline;

/// Where the dialogs for each kind of file were last (QSettings keys).
inline constexpr const char* kExportFolder = "paths/export";
inline constexpr const char* kStyleFolder = "paths/style";

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens @p spec (a file path or proc:NAME[:FACES]) as a new untitled
    /// document, after asking to save unsaved changes; it loads in the
    /// background, and the document stays as it was if it fails.
    void openMesh(const QString& spec);
    /// The style the session starts with (the command line's --style-file,
    /// read from @p source): in force, and not an edit to save or undo.
    void setStartingStyle(const QString& text, const QString& source);
    /// Opens a project (.snaxels) or a mesh, by the file's extension.
    void openFile(const QString& path);
    /// Opens the numbered series of mesh files @p path belongs to (one
    /// connectivity, one file per frame): its first file is loaded as the
    /// mesh and the timeline plays the files. False, with a message, when
    /// the name holds no frame number or the series has one file.
    bool openSequence(const QString& path);
    /// Reads the project at @p path and loads its mesh in the background;
    /// the project replaces the document once the mesh has loaded (ends with
    /// projectOpened or projectFailed; the document is untouched on failure).
    /// Asks first when the document has unsaved changes.
    void openProject(const QString& path);
    /// Saves the document as a project at @p path (atomically).
    bool saveProject(const QString& path);
    QString projectPath() const;
    /// Unsaved changes: an edit since the last save or open, or a new mesh.
    bool isModified() const;
    QUndoStack* undoStack() const;
    /// What the window edits: the project, the mesh and the undo stack.
    Document* document() const { return document_; }
    /// The light the user set by dragging (none: the style's or the default).
    const std::optional<Light>& userLight() const { return light_; }
    /// Turns the light as a Shift+drag in the view does (radians about
    /// the screen's up and right axes).
    void turnLight(double right, double down);
    const LoadedMesh* mesh() const;
    MeshView* meshView() const { return view_; }
    SvgPane* svgPane() const { return svgPane_; }
    StyleEditor* styleEditor() const { return styleEditor_; }
    Timeline* timeline() const { return timeline_; }
    ObjectsPanel* objectsPanel() const { return objects_; }
    /// View > Colour Regions.
    QAction* regionsAction() const { return regionsAction_; }
    /// View > Parabolic Curves.
    QAction* parabolicAction() const { return parabolicAction_; }
    /// The parabolic curves of the mesh, once found (null before, or while
    /// they are being found off the GUI thread).
    std::shared_ptr<const ParabolicResult> parabolicCurves() const;
    /// The view or the style asks for parabolic curves not found yet.
    bool parabolicPending() const;
    /// Contours are scheduled or being computed (a result is still to come).
    bool contoursBusy() const;
    /// Exports the timeline's animation to @p path as its extension asks
    /// (set_output: animated SVG, Lottie, compressed, or video) off the GUI
    /// thread, with a progress dialog that can cancel (nothing is written
    /// then); ends with exportFinished or exportFailed.
    void exportAnimation(const QString& path);
    /// Writes the SVG (or, for a .pdf path, the vector PDF) of the current
    /// frame to @p path (atomically).
    bool exportFrame(const QString& path);
    /// An animation export is under way (its progress dialog may not show yet).
    bool exporting() const;
    /// The SVG the pane shows: what export writes for the current view.
    const QByteArray& currentSvg() const { return svg_; }
    /// Why the current frame cannot be drawn (empty when it is drawn): the
    /// pane then holds no SVG and says this instead.
    const QString& frameProblem() const { return frameProblem_; }
    bool isLoading() const;

    /// The contours currently drawn (for tests): loops and snaxels.
    std::size_t contourLoops() const { return contourLoops_; }

  signals:
    void meshLoaded(const QString& spec);
    void loadFailed(const QString& message);
    /// New contours are on the 3-D view.
    void contoursUpdated();
    /// The parabolic curves of the loaded mesh were found (or the search failed: @p error).
    void parabolicFinished(const QString& error);
    void exportFinished(const QString& path);
    void exportFailed(const QString& message);
    void projectOpened(const QString& path);
    void projectFailed(const QString& message);
    void projectSaved(const QString& path);

  protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

  private:
    /// Once the window is idle (a second after nothing runs), gives the
    /// memory freed by a mesh replaced or an export ended back to the
    /// system: the C library keeps what its threads freed otherwise, and
    /// the window's footprint would creep up over a long session.
    void returnFreedMemorySoon();
    /// Starts reading @p spec for the document (opening a mesh, a project's
    /// mesh or a sequence's first file, which have asked about unsaved
    /// changes already).
    void startLoading(const QString& spec);
    /// True, saying so in the status bar, while a mesh is being read: one
    /// load at a time.
    bool refuseWhileLoading();
    void createDocks();
    void createStatusBar();
    void connectControllers();
    /// Asks to save unsaved changes: false when the user cancels.
    bool maybeSave();
    bool saveProjectInteractive(bool ask_path);
    /// What the widgets hold that has not reached the document yet (typing
    /// not yet taken up, say) goes in, as the edits it is.
    void commitWidgets();
    void applyProject(const Project& project, const QString& path, std::shared_ptr<const LoadedMesh> mesh);
    void applySequence(const SequenceFiles& files, std::shared_ptr<const LoadedMesh> mesh);
    void updateTitle();
    /// Shows the document's changes in the widgets.
    void observeDocument();
    /// The camera as the document keeps it (no turntable angle).
    OrbitView viewState() const;
    Light baseLight() const;
    void onLightDragged(glm::dvec3 axis_a, double angle_a, glm::dvec3 axis_b, double angle_b);
    void createMenus();
    void createExportMenu();
    void createViewMenu();
    void createStyleMenu();
    /// Style > Sharp Edges: the style's <surface sharp-angle>, asked for.
    void askSharpEdges();
    void createHelpMenu();
    /// Shows the bundled document @p name (Markdown) in a window of its own.
    void showDocument(const QString& name, const QString& title);
    void onLoadFinished(const LoadResult& result);
    void onLoadFailed(const LoadResult& result);
    void showMeshReport(const LoadedMesh& mesh);
    void scheduleContours();
    void applyFrame();
    Light frameLight() const;
    /// The middle of the mesh's bounding box (the origin without a mesh).
    glm::dvec3 meshCentre() const;
    /// The work of the next contour computation, from the window's state now.
    std::optional<std::function<OverlayResult()>> contourWork() const;
    void onContoursReady(const OverlayResult& result);
    bool wantsParabolic() const;
    /// A warning that names what failed, in a box that does not block.
    void warn(const QString& title, const QString& message);
    /// Where a save dialog for a kind of file starts: the folder last used
    /// for it (the QSettings key @p folder_key), else the mesh's, and the
    /// mesh's name with @p extension.
    QString suggestedPath(const char* folder_key, const QString& extension) const;
    /// Asks where to save a kind of file (starting at suggestedPath), and
    /// remembers the folder chosen; empty when cancelled.
    QString askSavePath(const QString& title, const char* folder_key, const QString& extension, const QString& filter);
    /// Says in the status bar that @p path was written, in full, and offers
    /// to show its folder.
    void reportExported(const QString& path);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    MeshView* view_;
    SvgPane* svgPane_;
    QByteArray svg_;
    QString frameProblem_;
    StyleEditor* styleEditor_;
    Timeline* timeline_;
    ObjectsPanel* objects_;
    QMenu* recentMenu_ = nullptr;
    QAction* regionsAction_ = nullptr;
    QAction* parabolicAction_ = nullptr;
    QProgressBar* parabolicProgress_ = nullptr;
    QToolButton* reveal_ = nullptr; ///< shows the folder of the last export
    QLabel* meshLabel_;
    QProgressBar* busy_;
    QLabel* contourLabel_;
    std::size_t contourLoops_ = 0;
    std::shared_ptr<ContourScene> scene_; ///< the loaded mesh's, posed by the contour thread

    // The document: what a project file keeps, its undo stack and state. The
    // widgets show it; their edits go to its setters.
    Document* document_ = nullptr;
    QTimer* memoryTimer_ = nullptr;
    MeshLoader* loader_;
    ContourScheduler* contours_;
    ParabolicSearch* parabolic_;
    AnimationExport* export_;
    /// The light as it is now: the document's, or one being dragged.
    std::optional<Light> light_;
    bool specAccepted_ = true; ///< the timeline took the document's last animation (its clip exists)
    int restoring_ = 0; ///< set while the document sets the widgets: not an edit
    std::optional<Project> pendingProject_;
    std::optional<SequenceFiles> pendingSequence_; ///< shown once its first file has loaded
    QString pendingProjectPath_;
};

} // namespace snaxels::ui
