#pragma once
// The main window: the 3-D view, the SVG pane, the style editor and the
// timeline around one document (mesh, camera, light, animation, style) with
// an undo stack, saved as a project file; menus, recent files,
// drag-and-drop and a status bar. Meshes load and exports run on worker
// threads so the window never freezes.

#include <atomic>
#include <memory>
#include <optional>

#include <QFutureWatcher>
#include <QMainWindow>

#include "snaxels/animation/pipeline.h"
#include "snaxels/mesh/build.h"
#include "snaxels/project/project.h"
#include "ui/contour_overlay.h"

class QAction;
class QLabel;
class QSvgWidget;
class QTimer;
class QMenu;
class QProgressBar;
class QUndoStack;

namespace snaxels::ui {

class Document;
class MeshView;
class StyleEditor;
class SvgPane;
class Timeline;

/// What a background load produces: a mesh or the one-line reason it failed.
struct LoadResult {
    std::shared_ptr<const LoadedMesh> mesh;
    std::shared_ptr<ContourScene> scene;
    std::shared_ptr<MeshGeometry> geometry;
    QString error;
};

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Starts loading @p spec (a file path or proc:NAME[:FACES]) in the background.
    void openMesh(const QString& spec);
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
    /// View > Colour Regions.
    QAction* regionsAction() const { return regionsAction_; }
    /// View > Parabolic Curves.
    QAction* parabolicAction() const { return parabolicAction_; }
    /// The parabolic curves of the mesh, once found (null before, or while
    /// they are being found off the GUI thread).
    std::shared_ptr<const ParabolicResult> parabolicCurves() const { return parabolic_; }
    /// The view or the style asks for parabolic curves not found yet.
    /// Contours are scheduled or being computed (a result is still to come).
    bool contoursBusy() const;
    bool parabolicPending() const { return wantsParabolic() && !(parabolic_ && scene_ && parabolicFor_ == meshGeneration_); }
    /// Exports the timeline's animation as animated SVG (or Lottie) to
    /// @p path off the GUI thread, with a progress dialog that can cancel
    /// (nothing is written then); ends with exportFinished or exportFailed.
    void exportAnimation(const QString& path, AnimationFormat format = AnimationFormat::Svg);
    /// Writes the SVG of the current frame to @p path (atomically).
    bool exportFrame(const QString& path);
    /// The SVG the pane shows: what export writes for the current view.
    const QByteArray& currentSvg() const { return svg_; }
    bool isLoading() const { return watcher_.isRunning(); }

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
    static QString exportCancelledMessage();
    /// Asks to save unsaved changes: false when the user cancels.
    bool maybeSave();
    bool saveProjectInteractive(bool ask_path);
    void applyProject(const Project& project, const QString& path, std::shared_ptr<const LoadedMesh> mesh);
    void updateTitle();
    /// Shows the document's changes in the widgets.
    void observeDocument();
    /// The camera as the document keeps it (no turntable angle).
    OrbitView viewState() const;
    Light baseLight() const;
    void onLightDragged(glm::dvec3 axis_a, double angle_a, glm::dvec3 axis_b, double angle_b);
    void createMenus();
    void createStyleMenu();
    void onLoadFinished();
    void scheduleContours();
    void applyFrame();
    Light frameLight() const;
    /// The middle of the mesh's bounding box (the origin without a mesh).
    glm::dvec3 meshCentre() const;
    void startContours();
    void onContoursFinished();
    /// Finds the mesh's parabolic curves off the GUI thread (with progress in
    /// the status bar) when the view or the style asks for them.
    void ensureParabolic();
    bool wantsParabolic() const;
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    MeshView* view_;
    SvgPane* svgPane_;
    QByteArray svg_;
    StyleEditor* styleEditor_;
    Timeline* timeline_;
    bool exporting_ = false;
    std::shared_ptr<std::atomic<bool>> exportCancel_ = std::make_shared<std::atomic<bool>>(false);
    QFuture<QString> exportFuture_;
    Style style_;
    QMenu* recentMenu_ = nullptr;
    QAction* regionsAction_ = nullptr;
    QAction* parabolicAction_ = nullptr;
    QProgressBar* parabolicProgress_ = nullptr;
    std::shared_ptr<const ParabolicResult> parabolic_;
    int meshGeneration_ = 0;  ///< counts meshes loaded
    int parabolicFor_ = -1;   ///< the mesh parabolic_ belongs to
    int searchFor_ = -1;      ///< the mesh the search under way is for (-1: none)
    std::shared_ptr<std::atomic<bool>> parabolicCancel_;
    QFutureWatcher<std::shared_ptr<const ParabolicResult>> parabolicWatcher_;
    std::shared_ptr<QString> parabolicError_; ///< the running search's error, if any
    QLabel* meshLabel_;
    QProgressBar* busy_;
    QFutureWatcher<LoadResult> watcher_;
    QString loadingSpec_;
    std::shared_ptr<ContourScene> scene_;
    QLabel* contourLabel_;
    QTimer* contourTimer_;
    QFutureWatcher<OverlayResult> contourWatcher_;
    bool contoursPending_ = false;
    std::size_t contourLoops_ = 0;

    // The document: what a project file keeps, its undo stack and state. The
    // widgets show it; their edits go to its setters.
    Document* document_ = nullptr;
    /// The light as it is now: the document's, or one being dragged.
    std::optional<Light> light_;
    bool specAccepted_ = true; ///< the timeline took the document's last animation (its clip exists)
    int restoring_ = 0; ///< set while the document sets the widgets: not an edit
    std::optional<Project> pendingProject_;
    std::optional<SequenceFiles> pendingSequence_; ///< shown once its first file has loaded
    QString pendingProjectPath_;
};

} // namespace snaxels::ui
