#include "ui/mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QPointer>
#include <QProgressDialog>
#include <atomic>
#include <utility>
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
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/util/atomic_file.h"
#include "ui/document.h"
#include "ui/meshview.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"
#include "ui/svgpane.h"
#include "ui/timeline.h"
#include "snaxels/animation/pipeline.h"

namespace snaxels::ui {
namespace {

constexpr int kMaxRecent = 8;

LoadResult loadInBackground(const QString& spec) {
    LoadResult result;
    try {
        auto mesh = std::make_shared<const LoadedMesh>(load_mesh(spec.toStdString()));
        result.scene = make_contour_scene(*mesh, spec.toStdString());
        result.geometry = std::make_shared<MeshGeometry>(mesh_geometry(result.scene->topology, display_face_budget()));
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
    : QMainWindow(parent), view_(new MeshView(this)), svgPane_(new SvgPane(this)),
      styleEditor_(new StyleEditor(this)), timeline_(new Timeline(this)), meshLabel_(new QLabel(this)),
      busy_(new QProgressBar(this)), contourLabel_(new QLabel(this)), contourTimer_(new QTimer(this)) {
    setWindowTitle("snaxels[*]");
    // The 3-D view and, beside it, the SVG the export writes for this view.
    auto* splitter = new QSplitter(this);
    splitter->addWidget(view_);
    splitter->addWidget(svgPane_);
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
        ensureParabolic(); // a style that draws parabolic curves needs them found
        scheduleContours();
    });
    document_ = new Document(styleEditor_->text(), this);
    // Every edit in a widget goes to the document, as one undo step.
    connect(styleEditor_, &StyleEditor::textApplied, this, [this](const QString& text) {
        if (!restoring_) document_->setStyleText(text);
    });
    connect(view_, &MeshView::viewEdited, this, [this] {
        if (!restoring_) document_->setView(viewState());
    });
    connect(view_, &MeshView::lightDragged, this, &MainWindow::onLightDragged);
    connect(view_, &MeshView::lightEdited, this, [this] {
        if (!restoring_) document_->setLight(light_);
    });

    // The timeline, docked below: scrubbing turns the view or the light.
    auto* timelineDock = new QDockWidget(tr("Timeline"), this);
    timelineDock->setObjectName("timelineDock");
    timelineDock->setWidget(timeline_);
    addDockWidget(Qt::BottomDockWidgetArea, timelineDock);
    connect(timeline_, &Timeline::changed, this, &MainWindow::applyFrame);
    document_->resetAnimation(timeline_->spec());
    connect(timeline_, &Timeline::specEdited, this, [this] {
        if (!restoring_) document_->setAnimation(timeline_->spec());
    });
    observeDocument();
    setAcceptDrops(true);
    busy_->setRange(0, 0); // indeterminate: importers report no progress
    busy_->setMaximumWidth(160);
    busy_->hide();
    statusBar()->addPermanentWidget(contourLabel_);
    meshLabel_->setObjectName("meshLabel");
    statusBar()->addPermanentWidget(meshLabel_);
    // Contours follow the camera: recomputed off the GUI thread shortly
    // after it stops moving, the newest request winning.
    contourTimer_->setSingleShot(true);
    contourTimer_->setInterval(30);
    connect(contourTimer_, &QTimer::timeout, this, &MainWindow::startContours);
    connect(view_, &MeshView::cameraChanged, this, &MainWindow::scheduleContours);
    connect(&contourWatcher_, &QFutureWatcher<OverlayResult>::finished, this, &MainWindow::onContoursFinished);
    statusBar()->addPermanentWidget(busy_);
    parabolicProgress_ = new QProgressBar(this);
    parabolicProgress_->setObjectName("parabolicProgress");
    parabolicProgress_->setFormat(tr("Parabolic curves %p%"));
    parabolicProgress_->setMaximumWidth(220);
    parabolicProgress_->hide();
    statusBar()->addPermanentWidget(parabolicProgress_);
    connect(&parabolicWatcher_, &QFutureWatcher<std::shared_ptr<const ParabolicResult>>::finished, this, [this] {
        parabolicProgress_->hide();
        std::shared_ptr<const ParabolicResult> result = parabolicWatcher_.result();
        const int searchedFor = std::exchange(searchFor_, -1);
        if (!scene_ || searchedFor != meshGeneration_) { // another mesh since: start over for it
            ensureParabolic();
            return;
        }
        if (!result) {
            const QString error = parabolicError_ && !parabolicError_->isEmpty()
                                      ? tr("Parabolic curves failed: %1").arg(*parabolicError_)
                                      : QString();
            if (!error.isEmpty()) statusBar()->showMessage(error, 8000);
            emit parabolicFinished(error.isEmpty() ? tr("cancelled") : error);
            return;
        }
        parabolic_ = std::move(result);
        parabolicFor_ = searchedFor;
        statusBar()->showMessage(tr("Parabolic curves: %1 curves from %2 visual events over %3 view directions, %4 s")
                                     .arg(parabolic_->curves.size())
                                     .arg(parabolic_->events)
                                     .arg(parabolic_->samples)
                                     .arg(parabolic_->ms / 1000.0, 0, 'f', 1),
                                 6000);
        emit parabolicFinished(QString());
        scheduleContours();
    });
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
        view_->setTurntable(spec.degrees_per_frame * timeline_->sourceFrame());
        if (!restoring_) document_->resetView(viewState()); // the frame's view, not an edit
    } else {
        view_->setTurntable(0.0);
    }
    scheduleContours();
}

Light MainWindow::baseLight() const {
    return light_ ? *light_ : style_.light ? *style_.light : default_light(view_->baseCamera());
}

OrbitView MainWindow::viewState() const {
    OrbitView v = view_->orbit();
    v.turntable = 0.0;
    return v;
}

void MainWindow::onLightDragged(glm::dvec3 axis_a, double angle_a, glm::dvec3 axis_b, double angle_b) {
    // The drag turns the light as it is seen at this frame; the document
    // keeps the frame-0 light, so the frame's own turn is taken off again.
    Light light = baseLight();
    const AnimationSpec spec = timeline_->spec();
    const bool turns = (spec.kind == AnimationSpec::Kind::Turntable && !light.point) ||
                       spec.kind == AnimationSpec::Kind::LightOrbit;
    const double frame_angle = turns ? glm::radians(spec.degrees_per_frame * timeline_->sourceFrame()) : 0.0;
    const glm::dvec3 y(0.0, 1.0, 0.0);
    auto turn = [&](glm::dvec3 v) {
        v = glm::rotate(v, frame_angle, y);
        v = glm::rotate(v, angle_a, glm::normalize(axis_a));
        v = glm::rotate(v, angle_b, glm::normalize(axis_b));
        return glm::rotate(v, -frame_angle, y);
    };
    if (light.point) {
        const glm::dvec3 centre = meshCentre();
        light.pos = centre + turn(light.pos - centre);
    } else {
        light.dir = glm::normalize(turn(light.dir));
    }
    light_ = light;
    scheduleContours();
}

void MainWindow::turnLight(double right, double down) {
    glm::dvec3 r, u;
    view_->camera().screen_basis(r, u);
    onLightDragged(u, right, r, down);
    emit view_->lightEdited();
}

const LoadedMesh* MainWindow::mesh() const { return document_->mesh().get(); }

glm::dvec3 MainWindow::meshCentre() const {
    const LoadedMesh* loaded = mesh();
    return loaded ? loaded->report.centre() : glm::dvec3(0.0);
}

Light MainWindow::frameLight() const {
    // As FrameDriver poses it, about the orbit's vertical axis.
    const glm::dvec3 centre = meshCentre();
    return light_at_frame(timeline_->spec(), baseLight(), timeline_->sourceFrame(), glm::dvec3(0.0, 1.0, 0.0), centre);
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

void MainWindow::exportAnimation(const QString& path, AnimationFormat format) {
    if (!document_->mesh() || exporting_) return;
    exporting_ = true;
    AnimationJob job = make_animation_job(style_, timeline_->spec(), view_->baseCamera(), light_);
    job.format = format;

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
    // A style with parabolic curves the view has not found yet: the dialog
    // shows that search first, then the frames.
    job.parabolic_progress = [guard, path, frames = job.animation.frames](int done, int total) {
        QMetaObject::invokeMethod(qApp, [guard, done, total, path, frames] {
            if (!guard) return;
            if (done < total) {
                guard->setLabelText(tr("Finding the parabolic curves for %1…").arg(QFileInfo(path).fileName()));
                guard->setRange(0, total);
                guard->setValue(done);
            } else {
                guard->setLabelText(tr("Exporting %1…").arg(QFileInfo(path).fileName()));
                guard->setRange(0, frames);
                guard->setValue(0);
            }
        }, Qt::QueuedConnection);
    };
    job.cancelled = [cancelled] { return cancelled->load(); };
    const std::shared_ptr<const LoadedMesh> mesh = document_->mesh();
    const std::string mesh_path = document_->meshSpec().toStdString();
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
            if (error != exportCancelledMessage()) { // a failure is said in a box; a cancel the user asked for is not
                auto* box = new QMessageBox(QMessageBox::Warning, tr("Export Animation"),
                                            tr("The animation was not exported: %1").arg(error), QMessageBox::Ok, this);
                box->setAttribute(Qt::WA_DeleteOnClose);
                box->open();
            }
            emit exportFailed(error);
        }
    });
    exportFuture_ = QtConcurrent::run([mesh, mesh_path, job, path]() mutable -> QString {
        try {
            // Written as the frames are made; the file appears, whole, only
            // at the end: a cancel or a failure leaves nothing.
            job.output = path.toStdString();
            run_animation(*mesh, mesh_path, job);
            return {};
        } catch (const AnimationCancelled&) {
            return exportCancelledMessage();
        } catch (const InternalError& e) {
            return QObject::tr("internal error: %1").arg(QString::fromStdString(e.what()));
        } catch (const std::exception& e) {
            return QString::fromStdString(e.what());
        }
    });
    watcher->setFuture(exportFuture_);
}

QString MainWindow::exportCancelledMessage() { return tr("Export cancelled; nothing was written"); }

bool MainWindow::contoursBusy() const { return contourTimer_->isActive() || contourWatcher_.isRunning(); }

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
    const std::shared_ptr<const LoadedMesh> mesh = document_->mesh();
    const Camera camera = view_->camera();
    const Style style = style_;
    const Light light = frameLight();
    std::optional<ClipPose> pose;
    if (const AnimationSpec spec = timeline_->spec();
        spec.kind == AnimationSpec::Kind::Clip || spec.kind == AnimationSpec::Kind::Sequence)
        pose = ClipPose{spec, timeline_->frame()}; // the driver adds the in point
    const std::shared_ptr<const ParabolicResult> parabolic = parabolicFor_ == meshGeneration_ ? parabolic_ : nullptr;
    const bool showParabolic = parabolicAction_ && parabolicAction_->isChecked();
    contourWatcher_.setFuture(QtConcurrent::run([mesh, scene, camera, style, light, pose, parabolic, showParabolic] {
        return compute_overlay(*mesh, *scene, camera, style, light, pose, parabolic, showParabolic);
    }));
}

bool MainWindow::wantsParabolic() const {
    if (parabolicAction_ && parabolicAction_->isChecked()) return true;
    return std::any_of(style_.contours.begin(), style_.contours.end(),
                       [](const ContourStyle& c) { return c.spec.kind == ContourKind::Parabolic; });
}

void MainWindow::ensureParabolic() {
    if (!scene_ || !wantsParabolic()) return;
    if (parabolic_ && parabolicFor_ == meshGeneration_) return; // found
    if (parabolicWatcher_.isRunning()) {
        // On the way; or for another mesh: stopped, and its end starts this one's.
        if (searchFor_ != meshGeneration_) parabolicCancel_->store(true);
        return;
    }
    searchFor_ = meshGeneration_;
    // The mesh as loaded: a value sharing its connectivity and pose (the
    // overlay's thread may move the scene to another pose meanwhile; the
    // rest pose never changes).
    const MeshTopology topology = scene_->rest;
    parabolicCancel_ = std::make_shared<std::atomic<bool>>(false);
    ParabolicOptions options;
    QPointer<QProgressBar> bar(parabolicProgress_);
    options.progress = [bar](int done, int total) {
        QMetaObject::invokeMethod(
            qApp,
            [bar, done, total] {
                if (!bar) return;
                bar->setRange(0, total);
                bar->setValue(done);
            },
            Qt::QueuedConnection);
    };
    options.cancelled = [cancel = parabolicCancel_] { return cancel->load(); };
    parabolicProgress_->setRange(0, 0);
    parabolicProgress_->show();
    parabolicError_ = std::make_shared<QString>(); // written by the search, read when it has finished
    parabolicWatcher_.setFuture(QtConcurrent::run([topology, options, error = parabolicError_]() -> std::shared_ptr<const ParabolicResult> {
        try {
            return cached_parabolic(topology, options);
        } catch (const ParabolicCancelled&) {
            return nullptr;
        } catch (const std::exception& e) {
            *error = QString::fromStdString(e.what());
            return nullptr;
        }
    }));
}

void MainWindow::onContoursFinished() {
    OverlayResult result = contourWatcher_.result();
    if (contoursPending_) { // the camera moved meanwhile: this result is stale
        startContours();
        return;
    }
    if (!result.error.isEmpty()) {
        statusBar()->showMessage(result.error, 8000);
        return;
    }
    if (result.geometry) view_->setPose(std::move(*result.geometry));
    view_->setRegionShading(region_shading(style_, result.light, regionsAction_->isChecked()));
    contourLoops_ = result.loops;
    contourLabel_->setText(tr("%1 loops, %2 snaxels, %3 ms").arg(result.loops).arg(result.snaxels).arg(result.ms, 0, 'f', 1));
    view_->setContours(std::move(result.strips));
    svg_ = QByteArray::fromStdString(result.svg);
    svgPane_->load(svg_);
    emit contoursUpdated();
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open Mesh or Project"), QSettings().value("paths/lastDir").toString(),
            tr("Meshes and projects (*.obj *.ply *.stl *.off *.gltf *.glb *.fbx *.dae *.3ds *.x *.blend *.snaxels);;"
               "Projects (*.snaxels);;All files (*)"));
        if (path.isEmpty()) return;
        QSettings().setValue("paths/lastDir", QFileInfo(path).absolutePath());
        openFile(path);
    });
    open->setShortcut(QKeySequence::Open);
    file->addAction(tr("Open Mesh &Sequence…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open Mesh Sequence (choose any of its numbered files)"), QSettings().value("paths/lastDir").toString(),
            tr("Meshes (*.obj *.ply *.stl *.off);;All files (*)"));
        if (path.isEmpty()) return;
        QSettings().setValue("paths/lastDir", QFileInfo(path).absolutePath());
        openSequence(path);
    });
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addSeparator();
    QAction* save = file->addAction(tr("&Save Project"), this, [this] { saveProjectInteractive(false); });
    save->setShortcut(QKeySequence::Save);
    QAction* saveAs = file->addAction(tr("Save Project &As…"), this, [this] { saveProjectInteractive(true); });
    saveAs->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);

    createStyleMenu();

    QMenu* exportMenu = menuBar()->addMenu(tr("&Export"));
    QAction* exportAnim = exportMenu->addAction(tr("&Animated SVG…"), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export Animated SVG"), QString(), tr("SVG (*.svg)"));
        if (!path.isEmpty()) exportAnimation(path);
    });
    exportAnim->setShortcut(QKeySequence(tr("Ctrl+E")));
    QAction* exportLottie = exportMenu->addAction(tr("&Lottie…"), this, [this] {
        QString path = QFileDialog::getSaveFileName(this, tr("Export Lottie"), QString(), tr("Lottie JSON (*.json)"));
        if (path.isEmpty()) return;
        if (QFileInfo(path).suffix().isEmpty()) path += ".json";
        exportAnimation(path, AnimationFormat::Lottie);
    });
    exportLottie->setObjectName("exportLottie");
    exportLottie->setShortcut(QKeySequence(tr("Ctrl+Alt+E")));
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
    viewMenu->addAction(tr("Reset &Light"), this, [this] {
        // Back to the style's light (or the default); one undo step.
        if (!light_) return;
        light_.reset();
        scheduleContours();
        emit view_->lightEdited();
    });
    regionsAction_ = viewMenu->addAction(tr("&Colour Regions"));
    regionsAction_->setCheckable(true);
    regionsAction_->setShortcut(QKeySequence(tr("Ctrl+R")));
    regionsAction_->setToolTip(tr("Colour the surface by planar-map region: shadow, lit, isophote bands, highlights"));
    regionsAction_->setChecked(QSettings().value("view/regions", false).toBool());
    connect(regionsAction_, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/regions", on);
        RegionShading shading = view_->regionShading();
        shading.enabled = on;
        view_->setRegionShading(std::move(shading));
    });
    parabolicAction_ = viewMenu->addAction(tr("&Parabolic Curves"));
    parabolicAction_->setObjectName("parabolicCurves");
    parabolicAction_->setCheckable(true);
    parabolicAction_->setShortcut(QKeySequence(tr("Ctrl+Shift+P")));
    parabolicAction_->setToolTip(tr("Draw the mesh's parabolic curves, where it turns from dome- to saddle-shaped "
                                    "(found once per mesh from visual events over all views)"));
    parabolicAction_->setChecked(QSettings().value("view/parabolic", false).toBool());
    connect(parabolicAction_, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/parabolic", on);
        ensureParabolic();
        scheduleContours();
    });
    viewMenu->addAction(tr("&Fit SVG Pane"), svgPane_, &SvgPane::fit);
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
        // Nothing of the document changes: the mesh, style and edits stay.
        QString message = result.error;
        if (pendingProject_) message = tr("%1: its mesh could not be opened: %2").arg(pendingProjectPath_, result.error);
        statusBar()->showMessage(tr("Could not open %1").arg(loadingSpec_), 8000);
        auto* box = new QMessageBox(QMessageBox::Warning, pendingProject_ ? tr("Could not open project") : tr("Could not open mesh"),
                                    message, QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        const bool wasProject = pendingProject_.has_value();
        pendingProject_.reset();
        pendingSequence_.reset();
        emit loadFailed(result.error);
        if (wasProject) emit projectFailed(message);
        return;
    }
    if (contourWatcher_.isRunning()) contoursPending_ = true; // its contours are of the old mesh
    scene_ = result.scene;
    parabolic_.reset(); // the old mesh's
    ++meshGeneration_;
    ensureParabolic();
    view_->setContours({});
    ++restoring_; // framing the new mesh is not an edit
    view_->setGeometry(std::move(*result.geometry)); // frames the camera, which schedules contours
    timeline_->setClips(scene_->clips);
    --restoring_;
    document_->resetView(viewState());
    document_->resetAnimation(timeline_->spec());
    const MeshReport& r = result.mesh->report;
    meshLabel_->setText(tr("%1 vertices, %2 faces, %3 boundary edges%4%5")
                            .arg(r.vertices)
                            .arg(r.faces)
                            .arg(r.boundary_edges)
                            .arg(r.split_vertices ? tr(", %1 vertices split").arg(r.split_vertices)
                                                  : QString())
                            .arg(scene_->rest.refinement()
                                     ? tr(" (refined to %1 faces for contours)").arg(scene_->rest.n_faces())
                                     : QString()));
    statusBar()->showMessage(tr("Loaded %1").arg(QFileInfo(loadingSpec_).fileName()), 4000);
    if (pendingProject_) {
        const Project project = std::move(*pendingProject_);
        pendingProject_.reset();
        applyProject(project, pendingProjectPath_, result.mesh);
    } else if (pendingSequence_) {
        const SequenceFiles files = std::move(*pendingSequence_);
        pendingSequence_.reset();
        AnimationSpec spec = timeline_->spec();
        spec.kind = AnimationSpec::Kind::Sequence;
        spec.pattern = files.pattern;
        spec.first_file = files.first_file;
        spec.frames = files.count;
        spec.start = 0;
        ++restoring_; // part of opening, not an edit to undo
        timeline_->setSpec(spec);
        timeline_->setSequenceFiles(files.count);
        timeline_->setFrame(0);
        --restoring_;
        document_->resetAnimation(timeline_->spec());
        document_->setMesh(loadingSpec_, result.mesh);
        statusBar()->showMessage(tr("Loaded a sequence of %1 files: %2").arg(files.count).arg(QFileInfo(QString::fromStdString(files.pattern)).fileName()), 6000);
        scheduleContours();
    } else {
        document_->setMesh(loadingSpec_, result.mesh);
        if (!loadingSpec_.startsWith("proc:")) addRecentFile(QFileInfo(loadingSpec_).absoluteFilePath());
    }
    updateTitle();
    emit meshLoaded(loadingSpec_);
    if (!document_->projectPath().isEmpty() && !document_->isModified()) emit projectOpened(document_->projectPath());
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
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openFile(path); })
            ->setToolTip(path);
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    if (parabolicCancel_) parabolicCancel_->store(true); // a search under way ends at its next step
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.first().isLocalFile()) openFile(urls.first().toLocalFile());
}

void MainWindow::openFile(const QString& path) {
    if (path.endsWith(kProjectExtension, Qt::CaseInsensitive)) openProject(path);
    else openMesh(path);
}

bool MainWindow::isModified() const { return document_->isModified(); }

QUndoStack* MainWindow::undoStack() const { return document_->undoStack(); }

QString MainWindow::projectPath() const { return document_->projectPath(); }

void MainWindow::observeDocument() {
    connect(document_, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(document_, &Document::projectPathChanged, this, &MainWindow::updateTitle);
    connect(document_->undoStack(), &QUndoStack::indexChanged, this, &MainWindow::updateTitle);
    // An undo, a redo or an opened project: the widgets follow. (Their own
    // edits come back here too, and change nothing.)
    connect(document_, &Document::styleTextChanged, this, [this](const QString& text) {
        if (styleEditor_->text() == text) return;
        ++restoring_;
        styleEditor_->setText(text, "style");
        --restoring_;
    });
    connect(document_, &Document::viewChanged, this, [this](const OrbitView& v) {
        if (viewState() == v) return;
        ++restoring_;
        view_->setOrbit(v);
        --restoring_;
    });
    connect(document_, &Document::lightChanged, this, [this](const std::optional<Light>& l) {
        light_ = l;
        scheduleContours();
    });
    connect(document_, &Document::animationChanged, this, [this](const AnimationSpec& a) {
        specAccepted_ = true;
        if (timeline_->spec() == a) return;
        ++restoring_;
        specAccepted_ = timeline_->setSpec(a);
        --restoring_;
    });
}

void MainWindow::updateTitle() {
    const QString& projectPath = document_->projectPath();
    const QString& meshSpec = document_->meshSpec();
    const QString name = !projectPath.isEmpty() ? QFileInfo(projectPath).fileName()
                         : !meshSpec.isEmpty()   ? QFileInfo(meshSpec).fileName()
                                                  : QString();
    setWindowTitle(name.isEmpty() ? tr("snaxels[*]") : tr("%1[*] — snaxels").arg(name));
    setWindowModified(isModified());
}

bool MainWindow::maybeSave() {
    if (!isModified()) return true;
    const QString name = document_->projectPath().isEmpty() ? tr("this project") : QFileInfo(document_->projectPath()).fileName();
    QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"),
                    tr("Save the changes to %1 first?").arg(name),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setInformativeText(tr("The style, camera, light and animation edits are lost otherwise."));
    box.setDefaultButton(QMessageBox::Save);
    box.setObjectName("unsavedChangesBox");
    switch (box.exec()) {
    case QMessageBox::Save: return saveProjectInteractive(false);
    case QMessageBox::Discard: return true;
    default: return false;
    }
}

bool MainWindow::saveProjectInteractive(bool ask_path) {
    if (!document_->mesh()) {
        QMessageBox::information(this, tr("Save Project"), tr("Open a mesh first: a project refers to one."));
        return false;
    }
    QString path = document_->projectPath();
    if (ask_path || path.isEmpty()) {
        path = QFileDialog::getSaveFileName(this, tr("Save Project"), QSettings().value("paths/lastDir").toString(),
                                            tr("Snaxels projects (*.snaxels)"));
        if (path.isEmpty()) return false;
        if (!path.endsWith(kProjectExtension, Qt::CaseInsensitive)) path += kProjectExtension;
    }
    return saveProject(path);
}

bool MainWindow::saveProject(const QString& path) {
    if (!document_->mesh()) return false;
    // What the widgets hold that has not reached the document yet (typing
    // not yet taken up, say) goes in first, as the edits it is.
    document_->setStyleText(styleEditor_->text());
    document_->setView(viewState());
    document_->setAnimation(timeline_->spec());
    document_->setFrame(timeline_->frame());
    try {
        document_->save(path);
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        QMessageBox::warning(this, tr("Save Project"), message);
        statusBar()->showMessage(message, 8000);
        return false;
    }
    updateTitle();
    addRecentFile(QFileInfo(path).absoluteFilePath());
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 4000);
    emit projectSaved(path);
    return true;
}

bool MainWindow::openSequence(const QString& path) {
    const std::optional<SequenceFiles> files = find_sequence(path.toStdString());
    if (!files || files->count < 2) {
        const QString message =
            files ? tr("%1: no other file of its series (the number in its name, one up or down) is there; "
                       "a sequence needs at least two")
                        .arg(QFileInfo(path).fileName())
                  : tr("%1: its name holds no frame number, so it is not part of a numbered sequence")
                        .arg(QFileInfo(path).fileName());
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Could not open sequence"), message, QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        statusBar()->showMessage(message, 8000);
        emit loadFailed(message);
        return false;
    }
    if (watcher_.isRunning()) {
        statusBar()->showMessage(tr("Still loading %1; try again when it is done").arg(loadingSpec_), 4000);
        return false;
    }
    if (!maybeSave()) return false;
    pendingSequence_ = *files;
    // The mesh is the series' first file; every frame is posed from its file.
    AnimationSpec probe;
    probe.kind = AnimationSpec::Kind::Sequence;
    probe.pattern = files->pattern;
    probe.first_file = files->first_file;
    openMesh(QString::fromStdString(sequence_file(probe, 0)));
    return true;
}

void MainWindow::openProject(const QString& path) {
    if (watcher_.isRunning()) {
        statusBar()->showMessage(tr("Still loading %1; try again when it is done").arg(loadingSpec_), 4000);
        return;
    }
    Project project;
    try {
        project = read_project(path.toStdString());
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Could not open project"), message, QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        statusBar()->showMessage(message, 8000);
        emit projectFailed(message);
        return;
    }
    if (!maybeSave()) return;
    pendingProject_ = std::move(project);
    pendingProjectPath_ = path;
    openMesh(QString::fromStdString(resolve_project_mesh(path.toStdString(), pendingProject_->mesh)));
}

void MainWindow::applyProject(const Project& p, const QString& path, std::shared_ptr<const LoadedMesh> mesh) {
    ++restoring_; // the document sets the widgets: not edits
    document_->load(p, path, loadingSpec_, std::move(mesh));
    const AnimationSpec& animation = document_->animation();
    if (animation.kind == AnimationSpec::Kind::Sequence)
        if (const auto files = find_sequence(sequence_file(animation, 0))) timeline_->setSequenceFiles(files->count);
    timeline_->setFrame(p.frame);
    --restoring_;
    addRecentFile(QFileInfo(path).absoluteFilePath());
    if (!specAccepted_) {
        const QString file = QFileInfo(path).fileName();
        const QString why = tr("%1: the mesh has no clip \"%2\"; the timeline shows a turntable")
                                .arg(file, QString::fromStdString(p.animation.clip));
        statusBar()->showMessage(why, 10000);
        document_->resetAnimation(timeline_->spec());
        document_->markModified(); // what the window shows is no longer what the file holds
    }
    updateTitle();
    scheduleContours();
}

} // namespace snaxels::ui
