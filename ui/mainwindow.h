#pragma once
// The main window: the 3-D view, menus, recent files, drag-and-drop and a
// status bar with the mesh report. Meshes load on a worker thread so the
// window never freezes.

#include <atomic>
#include <memory>

#include <QFutureWatcher>
#include <QMainWindow>

#include "core/mesh/build.h"
#include "ui/contour_overlay.h"

class QLabel;
class QSvgWidget;
class QTimer;
class QMenu;
class QProgressBar;

namespace snaxels::ui {

class MeshView;
class StyleEditor;
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
    const LoadedMesh* mesh() const { return mesh_.get(); }
    MeshView* meshView() const { return view_; }
    QSvgWidget* svgPane() const { return svgPane_; }
    StyleEditor* styleEditor() const { return styleEditor_; }
    Timeline* timeline() const { return timeline_; }
    /// Exports the timeline's animation as animated SVG to @p path off the
    /// GUI thread, with a progress dialog that can cancel (nothing is
    /// written then); ends with exportFinished or exportFailed.
    void exportAnimation(const QString& path);
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
    void exportFinished(const QString& path);
    void exportFailed(const QString& message);

  protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

  private:
    void createMenus();
    void createStyleMenu();
    void onLoadFinished();
    void scheduleContours();
    void applyFrame();
    Light frameLight() const;
    void startContours();
    void onContoursFinished();
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    MeshView* view_;
    QSvgWidget* svgPane_;
    QByteArray svg_;
    StyleEditor* styleEditor_;
    Timeline* timeline_;
    bool exporting_ = false;
    std::shared_ptr<std::atomic<bool>> exportCancel_ = std::make_shared<std::atomic<bool>>(false);
    QFuture<QString> exportFuture_;
    Style style_;
    QMenu* recentMenu_ = nullptr;
    QLabel* meshLabel_;
    QProgressBar* busy_;
    QFutureWatcher<LoadResult> watcher_;
    QString loadingSpec_;
    std::shared_ptr<const LoadedMesh> mesh_;
    std::shared_ptr<ContourScene> scene_;
    QLabel* contourLabel_;
    QTimer* contourTimer_;
    QFutureWatcher<OverlayResult> contourWatcher_;
    bool contoursPending_ = false;
    std::size_t contourLoops_ = 0;
};

} // namespace snaxels::ui
