#include "ui/mainwindow.h"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <utility>

#include <glm/gtx/rotate_vector.hpp>

#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QLabel>
#include <QMimeData>
#include <QProgressBar>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>

#include "ui/contour_scheduler.h"
#include "ui/document.h"
#include "ui/document_controller.h"
#include "ui/export_actions.h"
#include "ui/meshview.h"
#include "ui/objects_panel.h"
#include "ui/parabolic_search.h"
#include "ui/styleeditor.h"
#include "ui/svgpane.h"
#include "ui/timeline.h"
#include "ui/preferences.h"

namespace snaxels::ui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), view_(new MeshView(this)), svgPane_(new SvgPane(this)), styleEditor_(new StyleEditor(this)),
      timeline_(new Timeline(this)), objects_(new ObjectsPanel(this)), meshLabel_(new QLabel(this)),
      busy_(new QProgressBar(this)), contourLabel_(new QLabel(this)),
      contours_(new ContourScheduler([this] { return contourWork(); }, this)), parabolic_(new ParabolicSearch(this)) {
    setWindowTitle("snaxels[*]");
    // The 3-D view and, beside it, the SVG the export writes for this view.
    auto* splitter = new QSplitter(this);
    splitter->addWidget(view_);
    splitter->addWidget(svgPane_);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({600, 400});
    setCentralWidget(splitter);
    styleEditor_->showText(preferred_style_text()); // Edit > Preferences' default style
    document_ = new Document(styleEditor_->text(), this);
    document_->resetAnimation(initial_animation());
    controller_ = new DocumentController(document_, this);
    controller_->setFlush([this] { // typing not yet taken up
        styleEditor_->applyPending();
        timeline_->applyPending();
    });
    createDocks();
    styleEditor_->showCheck(document_->styleWarnings(), document_->styleProblem());
    objects_->setStyle(document_->styleText(), document_->style());
    observeDocument();
    connectEdits();
    setAcceptDrops(true);
    createStatusBar();
    exports_ = new ExportActions(document_, controller_, this); // its status button after the others
    connectControllers();
    createMenus();

    QSettings settings;
    // Until a saved layout says otherwise: 1400 x 860, or the screen's room
    // where it has less (a 1280 x 800 laptop).
    const QSize room = screen() ? screen()->availableGeometry().size() : QSize(1400, 860);
    resize(std::min(1400, room.width()), std::min(860, room.height()));
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
}

MainWindow::~MainWindow() {
    // QWidget's destructor deletes the children while the connections to
    // this window still stand: the undo stack, cleared as the document
    // goes, would call updateTitle on a window that is no longer one.
    disconnect(document_->undoStack(), nullptr, this, nullptr);
    disconnect(document_, nullptr, this, nullptr);
} // the controllers stop and wait for their threads

void MainWindow::createDocks() {
    // The style editor and the scene's parts, tabbed; the timeline below.
    auto* dock = new QDockWidget(tr("Style"), this);
    dock->setObjectName("styleDock");
    dock->setWidget(styleEditor_);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    auto* objectsDock = new QDockWidget(tr("Objects"), this);
    objectsDock->setObjectName("objectsDock");
    objects_->setObjectName("objectsPanel");
    objectsDock->setWidget(objects_);
    addDockWidget(Qt::RightDockWidgetArea, objectsDock);
    tabifyDockWidget(dock, objectsDock);
    dock->raise();
    auto* timelineDock = new QDockWidget(tr("Timeline"), this);
    timelineDock->setObjectName("timelineDock");
    timelineDock->setWidget(timeline_);
    addDockWidget(Qt::BottomDockWidgetArea, timelineDock);
}

void MainWindow::connectEdits() {
    // Every edit in a widget goes to the document, as one undo step; the
    // widgets' own setters (the document shown) signal no edit.
    connect(styleEditor_, &StyleEditor::textApplied, document_, qOverload<const QString&>(&Document::setStyleText));
    connect(objects_, &ObjectsPanel::styleEdited, document_, qOverload<const QString&, const QString&>(&Document::setStyleText));
    connect(objects_, &ObjectsPanel::highlightChanged, view_, &MeshView::setHighlight);
    connect(objects_, &ObjectsPanel::notice, this, [this](const QString& m) { statusBar()->showMessage(m, 5000); });
    connect(view_, &MeshView::viewEdited, this, [this] {
        OrbitView v = view_->orbit();
        v.turntable = 0.0; // the frame's turn is the animation's, not the view's
        document_->setView(v);
    });
    connect(view_, &MeshView::lockedToFileCamera, this, [this] {
        statusBar()->showMessage(tr("Looking through the file's camera: choose View camera in the timeline to orbit"), 4000);
    });
    connect(view_, &MeshView::lightDragged, this, &MainWindow::onLightDragged);
    // Scrubbing and play move the document's frame; the settings are an edit.
    connect(timeline_, &Timeline::changed, this, [this] { document_->setFrame(timeline_->frame()); });
    connect(timeline_, &Timeline::specEdited, this, [this] { document_->setAnimation(timeline_->spec()); });
    connect(timeline_, &Timeline::playbackStatus, this, [this](const QString& text) {
        if (text.isEmpty()) statusBar()->clearMessage();
        else statusBar()->showMessage(text); // stays while playing
    });
}

void MainWindow::createStatusBar() {
    busy_->setRange(0, 0); // indeterminate: importers report no progress
    busy_->setMaximumWidth(160);
    busy_->hide();
    statusBar()->addPermanentWidget(contourLabel_);
    meshLabel_->setObjectName("meshLabel");
    statusBar()->addPermanentWidget(meshLabel_);
    statusBar()->addPermanentWidget(busy_);
    parabolicProgress_ = new QProgressBar(this);
    parabolicProgress_->setObjectName("parabolicProgress");
    parabolicProgress_->setFormat(tr("Parabolic curves %p%"));
    parabolicProgress_->setMaximumWidth(220);
    parabolicProgress_->hide();
    statusBar()->addPermanentWidget(parabolicProgress_);
}

void MainWindow::connectControllers() {
    connect(controller_, &DocumentController::busy, busy_, &QWidget::setVisible);
    connect(controller_, &DocumentController::loaded, this, &MainWindow::showLoaded);
    connect(controller_, &DocumentController::status, this, [this](const QString& text, int ms) {
        statusBar()->showMessage(text, ms);
    });
    connect(controller_, &DocumentController::meshLoaded, this, &MainWindow::meshLoaded);
    connect(controller_, &DocumentController::meshLoaded, this, [this] {
        framePose_ = document_->projectPath().isEmpty() && document_->animation().kind == AnimationSpec::Kind::Clip;
    });
    connect(controller_, &DocumentController::loadFailed, this, &MainWindow::loadFailed);
    connect(controller_, &DocumentController::projectOpened, this, &MainWindow::projectOpened);
    connect(controller_, &DocumentController::projectFailed, this, &MainWindow::projectFailed);
    connect(controller_, &DocumentController::projectSaved, this, &MainWindow::projectSaved);
    connect(exports_, &ExportActions::finished, this, [this](const QString& path) {
        returnFreedMemorySoon();
        emit exportFinished(path);
    });
    connect(exports_, &ExportActions::failed, this, [this](const QString& message) {
        returnFreedMemorySoon();
        emit exportFailed(message);
    });
    connect(contours_, &ContourScheduler::ready, this, &MainWindow::onContoursReady);
    parabolic_->setWanted([this] { return wantsParabolic(); });
    connect(parabolic_, &ParabolicSearch::started, this, [this] {
        parabolicProgress_->setRange(0, 0);
        parabolicProgress_->show();
    });
    connect(parabolic_, &ParabolicSearch::progress, this, [this](int done, int total) {
        parabolicProgress_->setRange(0, total);
        parabolicProgress_->setValue(done);
    });
    connect(parabolic_, &ParabolicSearch::stopped, parabolicProgress_, &QWidget::hide);
    connect(parabolic_, &ParabolicSearch::finished, this, [this](const QString& error, bool found) {
        parabolicProgress_->hide();
        if (!found) {
            if (!error.isEmpty()) statusBar()->showMessage(tr("Parabolic curves failed: %1").arg(error), 8000);
            emit parabolicFinished(error.isEmpty() ? tr("cancelled") : tr("Parabolic curves failed: %1").arg(error));
            return;
        }
        const std::shared_ptr<const ParabolicResult> curves = parabolic_->curves();
        statusBar()->showMessage(tr("Parabolic curves: %1 curves from %2 visual events over %3 view directions, %4 s")
                                     .arg(curves->curves.size())
                                     .arg(curves->events)
                                     .arg(curves->samples)
                                     .arg(curves->ms / 1000.0, 0, 'f', 1),
                                 6000);
        emit parabolicFinished(QString());
        scheduleContours();
    });
}

void MainWindow::observeDocument() {
    connect(document_, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(document_, &Document::projectPathChanged, this, &MainWindow::updateTitle);
    connect(document_, &Document::meshChanged, this, &MainWindow::updateTitle);
    connect(document_->undoStack(), &QUndoStack::indexChanged, this, &MainWindow::updateTitle);
    // An edit, an undo, a redo or an opened project: the widgets show it.
    connect(document_, &Document::styleTextChanged, styleEditor_, &StyleEditor::showText);
    connect(document_, &Document::styleChecked, this, [this] {
        styleEditor_->showCheck(document_->styleWarnings(), document_->styleProblem());
        objects_->setStyle(document_->styleText(), document_->style());
    });
    connect(document_, &Document::styleChanged, this, [this] {
        parabolic_->ensure(); // a style that draws parabolic curves needs them found
        scheduleContours();
    });
    connect(document_, &Document::meshChanged, this, [this] {
        objects_->setMesh(document_->mesh());
        if (!document_->mesh()) showNoMesh(); // closed
    });
    connect(document_, &Document::viewChanged, this, [this](const OrbitView& v) {
        view_->setOrbit(v); // the turntable's turn, the frame's, stays
        scheduleContours();
    });
    connect(document_, &Document::lightChanged, this, &MainWindow::scheduleContours);
    connect(document_, &Document::animationChanged, this, [this](const AnimationSpec& a) {
        if (!(timeline_->spec() == a)) timeline_->setSpec(a);
        // A sequence's file count bounds the frames its source offers.
        if (a.kind == AnimationSpec::Kind::Sequence && a.pattern != std::exchange(sequencePattern_, a.pattern))
            if (const auto files = find_sequence(sequence_file(a, 0))) timeline_->setSequenceFiles(files->count);
        showFrame();
    });
    connect(document_, &Document::frameChanged, this, &MainWindow::showFrame);
}

void MainWindow::showLoaded(const LoadResult& result) {
    returnFreedMemorySoon(); // the last mesh's memory, once nothing holds it
    contours_->invalidate(); // what is under way is of the old mesh
    scene_ = result.scene;
    parabolic_->setMesh(scene_->rest);
    parabolic_->ensure();
    view_->setContours({}, view_->camera());
    view_->setGeometry(MeshGeometry(*result.geometry));
    timeline_->setClips(scene_->clips);
    timeline_->setCameras(scene_->cameras);
    sequencePattern_.clear();
    showMeshReport(*result.mesh);
}

void MainWindow::showNoMesh() {
    contours_->invalidate();
    scene_.reset();
    parabolic_->clearMesh();
    view_->clearMesh();
    timeline_->setClips({});
    timeline_->setCameras({});
    const QString why = tr("No mesh is open: open one (Ctrl+O) or drop it on the window");
    exports_->setFrame({}, why);
    svgPane_->load({}); // no drawing of the closed document shows through
    svgPane_->setProblem(why);
    meshLabel_->clear();
    contourLabel_->clear();
    contourLoops_ = 0;
}

void MainWindow::showMeshReport(const LoadedMesh& mesh) {
    const MeshReport& r = mesh.report;
    meshLabel_->setText(tr("%1 vertices, %2 faces, %3 boundary edges%4%5")
                            .arg(r.vertices)
                            .arg(r.faces)
                            .arg(r.boundary_edges)
                            .arg(r.split_vertices ? tr(", %1 vertices split").arg(r.split_vertices) : QString())
                            .arg(scene_->rest.refinement()
                                     ? tr(" (refined to %1 faces for contours)").arg(scene_->rest.n_faces())
                                     : QString()));
}

void MainWindow::showFrame() {
    const AnimationSpec& spec = document_->animation();
    timeline_->setFrame(document_->frame());
    // Back to the view camera at once (a file camera's picture comes with its contours).
    if (spec.camera.empty()) view_->setFileCamera(std::nullopt);
    if (spec.kind == AnimationSpec::Kind::Turntable) {
        // Turntables orbit the mesh's centre, as exports do: no pan.
        if (document_->view().pan != glm::dvec3(0.0)) {
            OrbitView centred = document_->view();
            centred.pan = glm::dvec3(0.0);
            document_->resetView(centred); // the frame's view, not an edit
        }
        view_->setTurntable(document_->frameDegrees());
    } else {
        view_->setTurntable(0.0);
    }
    scheduleContours();
}

void MainWindow::setStartingStyle(const QString& text, const QString& source) { document_->resetStyleText(text, source); }

void MainWindow::openMesh(const QString& spec) { controller_->openMesh(spec); }
void MainWindow::openFile(const QString& path) { controller_->openFile(path); }
bool MainWindow::openSequence(const QString& path) { return controller_->openSequence(path); }
void MainWindow::openProject(const QString& path) { controller_->openProject(path); }
bool MainWindow::saveProject(const QString& path) { return controller_->save(path); }
void MainWindow::exportAnimation(const QString& path) { exports_->exportAnimation(path); }
bool MainWindow::exportFrame(const QString& path) { return exports_->exportFrame(path); }
bool MainWindow::exporting() const { return exports_->running(); }
const QByteArray& MainWindow::currentSvg() const { return exports_->frameSvg(); }
const QString& MainWindow::frameProblem() const { return exports_->frameProblem(); }
std::shared_ptr<const ParabolicResult> MainWindow::parabolicCurves() const { return parabolic_->curves(); }
bool MainWindow::parabolicPending() const { return parabolic_->pending(); }
bool MainWindow::contoursBusy() const { return contours_->busy(); }
bool MainWindow::isLoading() const { return controller_->loading(); }
bool MainWindow::isModified() const { return document_->isModified(); }
QUndoStack* MainWindow::undoStack() const { return document_->undoStack(); }
QString MainWindow::projectPath() const { return document_->projectPath(); }
const std::optional<Light>& MainWindow::userLight() const { return document_->light(); }
const LoadedMesh* MainWindow::mesh() const { return document_->mesh().get(); }

Light MainWindow::baseLight() const {
    // Through a file's camera the default light is placed from it where it
    // starts, as the export and snaxels-cli place it.
    for (const FileCamera& c : document_->scene().cameras)
        if (c.name == document_->animation().camera) return job_light(document_->style(), c.first, document_->light());
    return job_light(document_->style(), orbit_base_camera(document_->view()), document_->light());
}

void MainWindow::onLightDragged(glm::dvec3 axis_a, double angle_a, glm::dvec3 axis_b, double angle_b) {
    // The drag turns the light as it is seen at this frame; the document
    // keeps the frame-0 light, so the frame's own turn is taken off again.
    Light light = baseLight();
    const AnimationSpec& spec = document_->animation();
    const bool turns = (spec.kind == AnimationSpec::Kind::Turntable && !light.point) ||
                       spec.kind == AnimationSpec::Kind::LightOrbit;
    const double frame_angle = turns ? glm::radians(document_->frameDegrees()) : 0.0;
    const glm::dvec3 y = glm::normalize(document_->view().up); // the turntable's axis
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
    document_->setLight(light); // a drag's steps merge into one undo step
}

void MainWindow::turnLight(double right, double down) {
    glm::dvec3 r, u;
    view_->camera().screen_basis(r, u);
    onLightDragged(u, right, r, down);
}

glm::dvec3 MainWindow::meshCentre() const {
    const LoadedMesh* loaded = mesh();
    return loaded ? loaded->report.centre() : glm::dvec3(0.0);
}

Light MainWindow::frameLight() const {
    // As FrameDriver poses it, about the orbit's vertical axis.
    return light_at_frame(document_->animation(), baseLight(), document_->sourceFrame(),
                          glm::normalize(document_->view().up), meshCentre());
}

Camera MainWindow::frameViewCamera() const {
    OrbitView v = document_->view();
    const AnimationSpec& spec = document_->animation();
    if (spec.kind == AnimationSpec::Kind::Turntable) v.turntable = glm::radians(document_->frameDegrees());
    return orbit_camera(v);
}

void MainWindow::scheduleContours() {
    if (scene_) contours_->schedule();
    else timeline_->frameShown(document_->frame()); // nothing to compute: the frame shows as it is
}

std::optional<std::function<OverlayResult()>> MainWindow::contourWork() const {
    if (!scene_) return std::nullopt;
    const std::shared_ptr<ContourScene> scene = scene_;
    const std::shared_ptr<const LoadedMesh> mesh = document_->mesh();
    const Camera camera = frameViewCamera();
    const Style style = document_->style();
    const Light light = frameLight();
    const AnimationSpec spec = document_->animation();
    const int frame = document_->frame();
    std::optional<ClipPose> pose;
    if (spec.kind == AnimationSpec::Kind::Clip || spec.kind == AnimationSpec::Kind::Sequence)
        pose = ClipPose{spec, frame}; // the driver adds the in point
    const std::shared_ptr<const ParabolicResult> parabolic = parabolic_->curves();
    const bool showParabolic = parabolicAction_ && parabolicAction_->isChecked();
    std::optional<CameraShot> shot;
    if (!spec.camera.empty()) shot = CameraShot{spec, frame};
    // The camera the export starts from (the model's up as its up), turned
    // to the frame as the export turns it: the same arithmetic, so the pane
    // holds the export's frame to the bit. Through a file's camera the
    // view's orbit is not the camera: the shot applies the turntable.
    const Camera base = orbit_base_camera(document_->view());
    const Camera seen = shot ? base : camera_at_frame(spec, base, nullptr, document_->sourceFrame(), meshCentre());
    return [mesh, scene, camera, seen, style, light, pose, parabolic, showParabolic, frame, shot] {
        OverlayResult result = compute_overlay(*mesh, *scene, seen, style, light, pose, parabolic, showParabolic, shot);
        result.frame = frame;
        if (!shot) result.camera = camera; // the 3-D view's own: its lines are current while it has not moved
        return result;
    };
}

bool MainWindow::wantsParabolic() const {
    if (parabolicAction_ && parabolicAction_->isChecked()) return true;
    const Style& style = document_->style();
    return std::any_of(style.contours.begin(), style.contours.end(),
                       [](const ContourStyle& c) { return c.spec.kind == ContourKind::Parabolic; });
}

void MainWindow::onContoursReady(const OverlayResult& ready) {
    OverlayResult result = ready;
    if (!result.error.isEmpty()) {
        // The frame asked for cannot be drawn (the eye on a surface):
        // no drawing of another frame stands in for it, in the pane, the
        // 3-D view's lines or Export Frame.
        const QString problem = tr("This frame cannot be drawn: %1").arg(result.error);
        exports_->setFrame({}, problem);
        svgPane_->setProblem(problem);
        contourLoops_ = 0;
        contourLabel_->setText(tr("no contours: this frame cannot be drawn"));
        view_->setContours({}, result.camera);
        timeline_->frameShown(result.frame);
        emit contoursUpdated();
        return;
    }
    const bool posed = result.geometry != nullptr;
    if (posed) view_->setPose(std::move(*result.geometry));
    // A new file on its clip: framed as posed, once its first frame is (not
    // an edit), unless the user has moved the camera (or edited) meanwhile.
    if (std::exchange(framePose_, false) && posed && document_->undoStack()->count() == 0)
        document_->resetView(view_->poseFraming());
    view_->setRegionShading(region_shading(document_->style(), result.light, regionsAction_->isChecked()));
    contourLoops_ = result.loops;
    contourLabel_->setText(tr("%1 loops, %2 snaxels, %3 ms").arg(result.loops).arg(result.snaxels).arg(result.ms, 0, 'f', 1));
    // Through a file's camera, the 3-D view looks through it too.
    view_->setFileCamera(document_->animation().camera.empty() ? std::nullopt : std::optional<Camera>(result.camera));
    view_->setCanvas(result.canvas_width, result.canvas_height, document_->style().margin, document_->style().page);
    view_->setContours(std::move(result.strips), result.camera);
    timeline_->frameShown(result.frame);
    exports_->setFrame(QByteArray::fromStdString(result.svg), {});
    svgPane_->load(exports_->frameSvg());
    emit contoursUpdated();
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

void MainWindow::returnFreedMemorySoon() {
    if (!memoryTimer_) {
        memoryTimer_ = new QTimer(this);
        memoryTimer_->setSingleShot(true);
        memoryTimer_->setInterval(1000);
        connect(memoryTimer_, &QTimer::timeout, this, [this] {
            if (isLoading() || contoursBusy() || exports_->running() || parabolic_->running()) return memoryTimer_->start();
#ifdef __GLIBC__
            malloc_trim(0);
#endif
        });
    }
    memoryTimer_->start();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!controller_->maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    parabolic_->cancel(); // a search under way ends at its next step
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.first().isLocalFile()) controller_->openFile(urls.first().toLocalFile());
}

} // namespace snaxels::ui
