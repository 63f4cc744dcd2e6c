#pragma once
// The main window: the 3-D view, the SVG pane, the style editor, the
// Objects panel and the timeline around one Document (mesh, style, camera,
// light, animation and frame, with its undo stack, saved as a project
// file). The widgets show the document and hand it the user's edits; what
// is drawn, saved and exported is read from the document alone. The work
// runs in controllers beside it, each testable without a window, on
// worker threads so the window never freezes: DocumentController opens and
// saves (MeshLoader reads meshes), ContourScheduler computes the contours
// the views show, ParabolicSearch finds parabolic curves and ExportActions
// writes files (AnimationExport the animations).

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
class QTimer;
class QMenu;
class QProgressBar;
class QUndoStack;

namespace snaxels::ui {

class ContourScheduler;
class Document;
class DocumentController;
class ExportActions;
class MeshView;
class ObjectsPanel;
class ParabolicSearch;
class StyleEditor;
class SvgPane;
class Timeline;

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opening and saving, as DocumentController does them (for the command
    // line and tests).
    void openMesh(const QString& spec);
    void openFile(const QString& path);
    bool openSequence(const QString& path);
    void openProject(const QString& path);
    bool saveProject(const QString& path);
    /// The style the session starts with (the command line's --style-file,
    /// read from @p source): in force, and not an edit to save or undo.
    void setStartingStyle(const QString& text, const QString& source);
    QString projectPath() const;
    /// Unsaved changes: an edit since the last save or open, or a new mesh.
    bool isModified() const;
    QUndoStack* undoStack() const;
    /// What the window edits: the project, the mesh and the undo stack.
    Document* document() const { return document_; }
    DocumentController* documents() const { return controller_; }
    /// The light the user set (none: the style's or the default).
    const std::optional<Light>& userLight() const;
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
    /// Exports the document's animation to @p path as its extension asks
    /// (ExportActions::exportAnimation); ends with exportFinished or exportFailed.
    void exportAnimation(const QString& path);
    /// Writes the SVG (or, for a .pdf path, the vector PDF) of the current
    /// frame to @p path (atomically).
    bool exportFrame(const QString& path);
    /// An animation export is under way (its progress dialog may not show yet).
    bool exporting() const;
    /// The SVG the pane shows: what export writes for the current view.
    const QByteArray& currentSvg() const;
    /// Why the current frame cannot be drawn (empty when it is drawn): the
    /// pane then holds no SVG and says this instead.
    const QString& frameProblem() const;
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
    void createDocks();
    /// The widgets' edits go to the document, each as what it is.
    void connectEdits();
    void createStatusBar();
    void connectControllers();
    void updateTitle();
    /// Shows the document's changes in the widgets.
    void observeDocument();
    /// Shows a mesh just read (before the document takes it).
    void showLoaded(const LoadResult& result);
    /// Shows a document without a mesh (File > Close).
    void showNoMesh();
    /// The frame the document stands at, in the 3-D view and the timeline.
    void showFrame();
    /// The 3-D view's camera at the document's frame (turned by a turntable).
    Camera frameViewCamera() const;
    Light baseLight() const;
    void onLightDragged(glm::dvec3 axis_a, double angle_a, glm::dvec3 axis_b, double angle_b);
    void createMenus();
    void createFileMenu();
    void createViewMenu();
    void showMeshReport(const LoadedMesh& mesh);
    void scheduleContours();
    Light frameLight() const;
    /// The middle of the mesh's bounding box (the origin without a mesh).
    glm::dvec3 meshCentre() const;
    /// The work of the next contour computation, from the document now.
    std::optional<std::function<OverlayResult()>> contourWork() const;
    void onContoursReady(const OverlayResult& result);
    bool wantsParabolic() const;
    void rebuildRecentMenu();

    MeshView* view_;
    SvgPane* svgPane_;
    StyleEditor* styleEditor_;
    Timeline* timeline_;
    ObjectsPanel* objects_;
    QMenu* recentMenu_ = nullptr;
    QAction* regionsAction_ = nullptr;
    QAction* parabolicAction_ = nullptr;
    QProgressBar* parabolicProgress_ = nullptr;
    QLabel* meshLabel_;
    QProgressBar* busy_;
    QLabel* contourLabel_;
    std::size_t contourLoops_ = 0;
    bool framePose_ = false; ///< a file just opened on its clip: frame its first pose when drawn
    std::shared_ptr<ContourScene> scene_; ///< the loaded mesh's, posed by the contour thread

    // The document: what a project file keeps, its undo stack and state. The
    // widgets show it; their edits go to its setters.
    Document* document_ = nullptr;
    DocumentController* controller_ = nullptr;
    ExportActions* exports_ = nullptr;
    QTimer* memoryTimer_ = nullptr;
    ContourScheduler* contours_;
    ParabolicSearch* parabolic_;
    std::string sequencePattern_; ///< the sequence whose file count the timeline knows
};

} // namespace snaxels::ui
