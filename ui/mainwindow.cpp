#include "ui/mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QPointer>
#include <QProgressDialog>
#include <atomic>
#include <glm/gtx/rotate_vector.hpp>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFile>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QSvgRenderer>
#include <QSvgWidget>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include "core/error.h"
#include "core/mesh/import.h"
#include "core/util/atomic_file.h"
#include "ui/meshview.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"
#include "ui/timeline.h"
#include "core/animation/pipeline.h"

namespace snaxels::ui {
namespace {

constexpr int kMaxRecent = 8;

LoadResult loadInBackground(const QString& spec) {
    LoadResult result;
    try {
        auto mesh = std::make_shared<const LoadedMesh>(load_mesh(spec.toStdString()));
        result.scene = make_contour_scene(*mesh);
        result.geometry = std::make_shared<MeshGeometry>(mesh_geometry(mesh->mesh, display_face_budget()));
        result.mesh = std::move(mesh);
    } catch (const std::bad_alloc&) {
        result.error = spec + ": out of memory while loading";
    } catch (const std::exception& e) {
        result.error = QString::fromStdString(e.what());
    }
    return result;
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), view_(new MeshView(this)), svgPane_(new QSvgWidget(this)),
      styleEditor_(new StyleEditor(this)), timeline_(new Timeline(this)), meshLabel_(new QLabel(this)),
      busy_(new QProgressBar(this)), contourLabel_(new QLabel(this)), contourTimer_(new QTimer(this)) {
    setWindowTitle("snaxels");
    // The 3-D view and, beside it, the SVG the export writes for this view.
    auto* splitter = new QSplitter(this);
    splitter->addWidget(view_);
    splitter->addWidget(svgPane_);
    svgPane_->renderer()->setAspectRatioMode(Qt::KeepAspectRatio);
    svgPane_->setMinimumSize(200, 200);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({600, 400});
    setCentralWidget(splitter);

    // The style editor, docked; a style that parses applies to both views.
    style_ = styleEditor_->style();
    auto* dock = new QDockWidget(tr("Style"), this);
    dock->setObjectName("styleDock");
    dock->setWidget(styleEditor_);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    connect(styleEditor_, &StyleEditor::styleChanged, this, [this](const Style& style) {
        style_ = style;
        scheduleContours();
    });

    // The timeline, docked below: scrubbing turns the view or the light.
    auto* timelineDock = new QDockWidget(tr("Timeline"), this);
    timelineDock->setObjectName("timelineDock");
    timelineDock->setWidget(timeline_);
    addDockWidget(Qt::BottomDockWidgetArea, timelineDock);
    connect(timeline_, &Timeline::changed, this, &MainWindow::applyFrame);
    setAcceptDrops(true);
    busy_->setRange(0, 0); // indeterminate: importers report no progress
    busy_->setMaximumWidth(160);
    busy_->hide();
    statusBar()->addPermanentWidget(contourLabel_);
    statusBar()->addPermanentWidget(meshLabel_);
    // Contours follow the camera: recomputed off the GUI thread shortly
    // after it stops moving, the newest request winning.
    contourTimer_->setSingleShot(true);
    contourTimer_->setInterval(30);
    connect(contourTimer_, &QTimer::timeout, this, &MainWindow::startContours);
    connect(view_, &MeshView::cameraChanged, this, &MainWindow::scheduleContours);
    connect(&contourWatcher_, &QFutureWatcher<OverlayResult>::finished, this, &MainWindow::onContoursFinished);
    statusBar()->addPermanentWidget(busy_);
    createMenus();
    connect(&watcher_, &QFutureWatcher<LoadResult>::finished, this, &MainWindow::onLoadFinished);

    QSettings settings;
    resize(1400, 860); // until a saved layout says otherwise
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
}

MainWindow::~MainWindow() {
    *exportCancel_ = true; // an export still running stops at its next frame
    exportFuture_.waitForFinished();
    watcher_.waitForFinished();
    contourWatcher_.waitForFinished();
}

void MainWindow::applyFrame() {
    const AnimationSpec spec = timeline_->spec();
    if (spec.kind == AnimationSpec::Kind::Turntable) {
        view_->centreView(); // turntables orbit the mesh's centre, as exports do
        view_->setTurntable(spec.degrees_per_frame * timeline_->frame());
    } else {
        view_->setTurntable(0.0);
    }
    scheduleContours();
}

Light MainWindow::frameLight() const {
    // As FrameDriver poses it: the base light turned about the vertical axis.
    const AnimationSpec spec = timeline_->spec();
    const Camera base = view_->baseCamera();
    Light light = style_.light ? *style_.light : default_light(base);
    const double angle = glm::radians(spec.degrees_per_frame * timeline_->frame());
    const glm::dvec3 axis(0.0, 1.0, 0.0);
    const glm::dvec3 centre = mesh_ ? 0.5 * (mesh_->report.bbox_min + mesh_->report.bbox_max) : glm::dvec3(0.0);
    if (spec.kind == AnimationSpec::Kind::Turntable && !light.point) light.dir = glm::rotate(light.dir, angle, axis);
    if (spec.kind == AnimationSpec::Kind::LightOrbit) {
        if (light.point) light.pos = centre + glm::rotate(light.pos - centre, angle, axis);
        else light.dir = glm::rotate(light.dir, angle, axis);
    }
    return light;
}

bool MainWindow::exportFrame(const QString& path) {
    try {
        write_file_atomically(path.toStdString(), svg_.toStdString());
        statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 4000);
        emit exportFinished(path);
        return true;
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        QMessageBox::warning(this, tr("Export Frame"), message);
        emit exportFailed(message);
        return false;
    }
}

void MainWindow::exportAnimation(const QString& path) {
    if (!mesh_ || exporting_) return;
    exporting_ = true;
    AnimationJob job;
    job.animation = timeline_->spec();
    job.camera = view_->baseCamera();
    job.light = style_.light ? *style_.light : default_light(job.camera);
    job.kinds.clear();
    for (const ContourStyle& cs : style_.contours) job.kinds.push_back(cs.spec);
    if (job.kinds.empty()) job.kinds.push_back({});
    job.style = style_;
    job.engine.check_invariants = false;

    auto* dialog = new QProgressDialog(tr("Exporting %1…").arg(QFileInfo(path).fileName()), tr("Cancel"), 0,
                                       job.animation.frames, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(300);
    exportCancel_ = std::make_shared<std::atomic<bool>>(false);
    auto cancelled = exportCancel_;
    connect(dialog, &QProgressDialog::canceled, this, [cancelled] { *cancelled = true; });
    QPointer<QProgressDialog> guard(dialog);
    job.progress = [guard](int done, int) {
        QMetaObject::invokeMethod(qApp, [guard, done] {
            if (guard) guard->setValue(done);
        }, Qt::QueuedConnection);
    };
    job.cancelled = [cancelled] { return cancelled->load(); };
    const std::shared_ptr<const LoadedMesh> mesh = mesh_;
    const std::string mesh_path = loadingSpec_.toStdString();
    auto* watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcher<QString>::finished, this, [this, watcher, guard, path] {
        const QString error = watcher->result();
        watcher->deleteLater();
        if (guard) guard->close();
        exporting_ = false;
        if (error.isEmpty()) {
            statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 6000);
            emit exportFinished(path);
        } else {
            statusBar()->showMessage(error, 8000);
            emit exportFailed(error);
        }
    });
    exportFuture_ = QtConcurrent::run([mesh, mesh_path, job, path]() -> QString {
        try {
            const AnimationOutput out = run_animation(*mesh, mesh_path, job);
            write_file_atomically(path.toStdString(), out.svg); // only now: a cancel leaves nothing
            return {};
        } catch (const AnimationCancelled&) {
            return QObject::tr("Export cancelled; nothing was written");
        } catch (const std::exception& e) {
            return QString::fromStdString(e.what());
        }
    });
    watcher->setFuture(exportFuture_);
}

void MainWindow::scheduleContours() {
    if (scene_) contourTimer_->start();
}

void MainWindow::startContours() {
    if (!scene_) return;
    if (contourWatcher_.isRunning()) {
        contoursPending_ = true;
        return;
    }
    contoursPending_ = false;
    const std::shared_ptr<ContourScene> scene = scene_;
    const std::shared_ptr<const LoadedMesh> mesh = mesh_;
    const Camera camera = view_->camera();
    const Style style = style_;
    const Light light = frameLight();
    contourWatcher_.setFuture(QtConcurrent::run([mesh, scene, camera, style, light] {
        return compute_overlay(*mesh, *scene, camera, style, light);
    }));
}

void MainWindow::onContoursFinished() {
    OverlayResult result = contourWatcher_.result();
    if (contoursPending_) { // the camera moved meanwhile: this result is stale
        startContours();
        return;
    }
    contourLoops_ = result.loops;
    contourLabel_->setText(tr("%1 loops, %2 snaxels, %3 ms").arg(result.loops).arg(result.snaxels).arg(result.ms, 0, 'f', 1));
    view_->setContours(std::move(result.strips));
    svg_ = QByteArray::fromStdString(result.svg);
    svgPane_->load(svg_);
    svgPane_->renderer()->setAspectRatioMode(Qt::KeepAspectRatio); // load() resets it
    emit contoursUpdated();
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open Mesh…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open Mesh"), QSettings().value("paths/lastDir").toString(),
            tr("Meshes (*.obj *.ply *.stl *.off *.gltf *.glb *.fbx *.dae *.3ds *.x *.blend);;"
               "All files (*)"));
        if (path.isEmpty()) return;
        QSettings().setValue("paths/lastDir", QFileInfo(path).absolutePath());
        openMesh(path);
    });
    open->setShortcut(QKeySequence::Open);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    createStyleMenu();

    QMenu* exportMenu = menuBar()->addMenu(tr("&Export"));
    QAction* exportAnim = exportMenu->addAction(tr("&Animated SVG…"), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export Animated SVG"), QString(), tr("SVG (*.svg)"));
        if (!path.isEmpty()) exportAnimation(path);
    });
    exportAnim->setShortcut(QKeySequence(tr("Ctrl+E")));
    QAction* exportStill = exportMenu->addAction(tr("Current &Frame as SVG…"), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export Frame"), QString(), tr("SVG (*.svg)"));
        if (!path.isEmpty()) exportFrame(path);
    });
    exportStill->setShortcut(QKeySequence(tr("Ctrl+Shift+E")));

    QMenu* playMenu = menuBar()->addMenu(tr("&Play"));
    QAction* play = playMenu->addAction(tr("Play / Pause"), timeline_, &Timeline::togglePlay);
    play->setShortcut(Qt::Key_Space);
    QAction* next = playMenu->addAction(tr("Next Frame"), this, [this] { timeline_->step(1); });
    next->setShortcut(Qt::Key_Right);
    QAction* previous = playMenu->addAction(tr("Previous Frame"), this, [this] { timeline_->step(-1); });
    previous->setShortcut(Qt::Key_Left);

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    QAction* reset = viewMenu->addAction(tr("&Reset Camera"), view_, &MeshView::resetCamera);
    reset->setShortcut(Qt::Key_Home);
}

void MainWindow::createStyleMenu() {
    QMenu* menu = menuBar()->addMenu(tr("&Style"));
    QMenu* presets = menu->addMenu(tr("&Presets"));
    const QDir dir(dataDirectory() + "/styles");
    for (const QFileInfo& file : dir.entryInfoList({"*.xml"}, QDir::Files, QDir::Name))
        presets->addAction(file.completeBaseName(), this, [this, path = file.absoluteFilePath()] {
            QFile in(path);
            if (!in.open(QIODevice::ReadOnly)) {
                statusBar()->showMessage(tr("Cannot read %1").arg(path), 6000);
                return;
            }
            styleEditor_->setText(QString::fromUtf8(in.readAll()), path);
        });
    presets->setEnabled(!presets->isEmpty());
    menu->addAction(tr("&Load Style…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load Style"), QString(), tr("Styles (*.xml)"));
        if (path.isEmpty()) return;
        QFile in(path);
        if (!in.open(QIODevice::ReadOnly)) {
            QMessageBox::warning(this, tr("Load Style"), tr("Cannot read %1: %2").arg(path, in.errorString()));
            return;
        }
        styleEditor_->setText(QString::fromUtf8(in.readAll()), path);
    });
    menu->addAction(tr("&Save Style As…"), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save Style"), QString(), tr("Styles (*.xml)"));
        if (path.isEmpty()) return;
        try {
            write_file_atomically(path.toStdString(), styleEditor_->text().toStdString());
            statusBar()->showMessage(tr("Saved %1").arg(path), 4000);
        } catch (const std::exception& e) {
            QMessageBox::warning(this, tr("Save Style"), QString::fromStdString(e.what()));
        }
    });
}

void MainWindow::openMesh(const QString& spec) {
    if (watcher_.isRunning()) {
        statusBar()->showMessage(tr("Still loading %1; try again when it is done").arg(loadingSpec_),
                                 4000);
        return;
    }
    loadingSpec_ = spec;
    busy_->show();
    statusBar()->showMessage(tr("Loading %1…").arg(QFileInfo(spec).fileName()));
    watcher_.setFuture(QtConcurrent::run(loadInBackground, spec));
}

void MainWindow::onLoadFinished() {
    busy_->hide();
    LoadResult result = watcher_.result();
    if (!result.mesh) {
        statusBar()->showMessage(tr("Could not open %1").arg(loadingSpec_), 8000);
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Could not open mesh"), result.error,
                                    QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        emit loadFailed(result.error);
        return;
    }
    if (contourWatcher_.isRunning()) contoursPending_ = true; // its contours are of the old mesh
    mesh_ = result.mesh;
    scene_ = result.scene;
    view_->setContours({});
    view_->setGeometry(std::move(*result.geometry)); // frames the camera, which schedules contours
    const MeshReport& r = mesh_->report;
    meshLabel_->setText(tr("%1 vertices, %2 faces, %3 boundary edges%4")
                            .arg(r.vertices)
                            .arg(r.faces)
                            .arg(r.boundary_edges)
                            .arg(r.split_vertices ? tr(", %1 vertices split").arg(r.split_vertices)
                                                  : QString()));
    setWindowTitle(tr("%1 — snaxels").arg(QFileInfo(loadingSpec_).fileName()));
    statusBar()->showMessage(tr("Loaded %1").arg(QFileInfo(loadingSpec_).fileName()), 4000);
    if (!loadingSpec_.startsWith("proc:")) addRecentFile(QFileInfo(loadingSpec_).absoluteFilePath());
    emit meshLoaded(loadingSpec_);
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue("recentFiles", recent);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent)
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openMesh(path); })
            ->setToolTip(path);
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.first().isLocalFile()) openMesh(urls.first().toLocalFile());
}

} // namespace snaxels::ui
