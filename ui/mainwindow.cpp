#include "ui/mainwindow.h"

#include <utility>

#include <glm/gtx/rotate_vector.hpp>

#include <QCloseEvent>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QToolButton>
#include <QUndoStack>
#include <QUrl>

#include "snaxels/util/atomic_file.h"
#include "ui/animation_export.h"
#include "ui/contour_scheduler.h"
#include "ui/document.h"
#include "ui/meshview.h"
#include "ui/objects_panel.h"
#include "ui/parabolic_search.h"
#include "ui/styleeditor.h"
#include "ui/svgpane.h"
#include "ui/timeline.h"

namespace snaxels::ui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), view_(new MeshView(this)), svgPane_(new SvgPane(this)),
      styleEditor_(new StyleEditor(this)), timeline_(new Timeline(this)), objects_(new ObjectsPanel(this)), meshLabel_(new QLabel(this)),
      busy_(new QProgressBar(this)), contourLabel_(new QLabel(this)), loader_(new MeshLoader(this)),
      contours_(new ContourScheduler([this] { return contourWork(); }, this)), parabolic_(new ParabolicSearch(this)),
      export_(new AnimationExport(this)) {
    setWindowTitle("snaxels[*]");
    // The 3-D view and, beside it, the SVG the export writes for this view.
    auto* splitter = new QSplitter(this);
    splitter->addWidget(view_);
    splitter->addWidget(svgPane_);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({600, 400});
    setCentralWidget(splitter);
    document_ = new Document(styleEditor_->text(), this);
    createDocks();
    observeDocument();
    setAcceptDrops(true);
    createStatusBar();
    connectControllers();
    createMenus();

    QSettings settings;
    resize(1400, 860); // until a saved layout says otherwise
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
    // The style editor, docked; the text it takes up is the document's style.
    auto* dock = new QDockWidget(tr("Style"), this);
    dock->setObjectName("styleDock");
    dock->setWidget(styleEditor_);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    // Every edit in a widget goes to the document, as one undo step.
    connect(styleEditor_, &StyleEditor::textApplied, this, [this](const QString& text) {
        if (!restoring_) document_->setStyleText(text);
    });
    connect(view_, &MeshView::lockedToFileCamera, this, [this] {
        statusBar()->showMessage(tr("Looking through the file's camera: choose View camera in the timeline to orbit"), 4000);
    });
    connect(view_, &MeshView::viewEdited, this, [this] {
        if (!restoring_) document_->setView(viewState());
    });
    connect(view_, &MeshView::lightDragged, this, &MainWindow::onLightDragged);
    connect(view_, &MeshView::lightEdited, this, [this] {
        if (!restoring_) document_->setLight(light_);
    });
    // The scene's parts, in a tab beside the style: a part's state is an
    // edit of the style (one undo step); a part selected is tinted in the view.
    auto* objectsDock = new QDockWidget(tr("Objects"), this);
    objectsDock->setObjectName("objectsDock");
    objects_->setObjectName("objectsPanel");
    objectsDock->setWidget(objects_);
    addDockWidget(Qt::RightDockWidgetArea, objectsDock);
    tabifyDockWidget(dock, objectsDock);
    dock->raise();
    objects_->setStyleText(document_->styleText());
    connect(objects_, &ObjectsPanel::styleEdited, this, [this](const QString& text, const QString& step) {
        if (!restoring_) document_->setStyleText(text, step);
    });
    connect(objects_, &ObjectsPanel::highlightChanged, view_, &MeshView::setHighlight);
    connect(objects_, &ObjectsPanel::notice, this, [this](const QString& m) { statusBar()->showMessage(m, 5000); });
    connect(document_, &Document::meshChanged, this, [this] {
        objects_->setMesh(document_->mesh());
        ++restoring_; // the editor re-reads its text for the new scene's parts: no edit
        styleEditor_->setSceneParts(document_->mesh() ? loaded_parts(*document_->mesh()) : nullptr);
        --restoring_;
    });
    // The timeline, docked below: scrubbing turns the view or the light.
    auto* timelineDock = new QDockWidget(tr("Timeline"), this);
    timelineDock->setObjectName("timelineDock");
    timelineDock->setWidget(timeline_);
    addDockWidget(Qt::BottomDockWidgetArea, timelineDock);
    connect(timeline_, &Timeline::changed, this, &MainWindow::applyFrame);
    connect(timeline_, &Timeline::playbackStatus, this, [this](const QString& text) {
        if (text.isEmpty()) statusBar()->clearMessage();
        else statusBar()->showMessage(text); // stays while playing
    });
    document_->resetAnimation(timeline_->spec());
    connect(timeline_, &Timeline::specEdited, this, [this] {
        if (!restoring_) document_->setAnimation(timeline_->spec());
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
    reveal_ = new QToolButton(this);
    reveal_->setObjectName("revealExport");
    reveal_->setText(tr("Reveal in Folder"));
    reveal_->setAutoRaise(true);
    reveal_->hide(); // until something is exported
    connect(reveal_, &QToolButton::clicked, this, [this] {
        QDesktopServices::openUrl(QUrl::fromLocalFile(reveal_->property("folder").toString()));
    });
    statusBar()->addPermanentWidget(reveal_);
}

void MainWindow::connectControllers() {
    connect(loader_, &MeshLoader::finished, this, [this](const LoadResult& result) {
        busy_->hide();
        if (result.mesh) onLoadFinished(result);
        else onLoadFailed(result);
    });
    // Contours follow the camera: recomputed off the GUI thread shortly
    // after it stops moving, the newest request winning.
    connect(view_, &MeshView::cameraChanged, this, &MainWindow::scheduleContours);
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
    connect(export_, &AnimationExport::finished, this, [this](const QString& path) {
        returnFreedMemorySoon();
        reportExported(path);
        emit exportFinished(path);
    });
    connect(export_, &AnimationExport::failed, this, [this](const QString& error) {
        returnFreedMemorySoon();
        statusBar()->showMessage(error, 8000);
        // A failure is said in a box; a cancel the user asked for is not.
        if (error != AnimationExport::cancelledMessage())
            warn(tr("Export Animation"), tr("The animation was not exported: %1").arg(error));
        emit exportFailed(error);
    });
}

void MainWindow::reportExported(const QString& path) {
    const QFileInfo file(path);
    QSettings().setValue(kExportFolder, file.absolutePath()); // the next export's dialog starts there
    statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(file.absoluteFilePath())), 15000);
    reveal_->setToolTip(tr("Show %1 in its folder").arg(QDir::toNativeSeparators(file.absolutePath())));
    reveal_->setProperty("folder", file.absolutePath());
    reveal_->show();
}

void MainWindow::setStartingStyle(const QString& text, const QString& source) {
    ++restoring_;
    styleEditor_->setText(text, source);
    --restoring_;
    document_->resetStyleText(styleEditor_->text());
}

void MainWindow::warn(const QString& title, const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

std::shared_ptr<const ParabolicResult> MainWindow::parabolicCurves() const { return parabolic_->curves(); }

bool MainWindow::parabolicPending() const { return parabolic_->pending(); }

bool MainWindow::contoursBusy() const { return contours_->busy(); }

bool MainWindow::isLoading() const { return loader_->loading(); }

bool MainWindow::exporting() const { return export_->running(); }

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
    // Through a file's camera the default light is placed from it where it
    // starts, as the export and snaxels-cli place it.
    if (const std::string name = timeline_->spec().camera; scene_ && !name.empty())
        for (const FileCamera& c : scene_->cameras)
            if (c.name == name) return job_light(document_->style(), c.first, light_);
    return job_light(document_->style(), view_->baseCamera(), light_);
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
    const glm::dvec3 y = glm::normalize(view_->orbit().up); // the turntable's axis
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
    return light_at_frame(timeline_->spec(), baseLight(), timeline_->sourceFrame(), glm::normalize(view_->orbit().up), centre);
}

void MainWindow::scheduleContours() {
    if (scene_) contours_->schedule();
    else timeline_->frameShown(timeline_->frame()); // nothing to compute: the frame shows as it is
}

std::optional<std::function<OverlayResult()>> MainWindow::contourWork() const {
    if (!scene_) return std::nullopt;
    const std::shared_ptr<ContourScene> scene = scene_;
    const std::shared_ptr<const LoadedMesh> mesh = document_->mesh();
    const Camera camera = view_->camera();
    const Style style = document_->style();
    const Light light = frameLight();
    std::optional<ClipPose> pose;
    if (const AnimationSpec spec = timeline_->spec();
        spec.kind == AnimationSpec::Kind::Clip || spec.kind == AnimationSpec::Kind::Sequence)
        pose = ClipPose{spec, timeline_->frame()}; // the driver adds the in point
    const std::shared_ptr<const ParabolicResult> parabolic = parabolic_->curves();
    const bool showParabolic = parabolicAction_ && parabolicAction_->isChecked();
    const int frame = timeline_->frame();
    std::optional<CameraShot> shot;
    if (const AnimationSpec spec = timeline_->spec(); !spec.camera.empty()) shot = CameraShot{spec, frame};
    // The camera the export starts from (the model's up as its up), turned
    // to the frame as the export turns it: the same arithmetic, so the pane
    // holds the export's frame to the bit. Through a file's camera the
    // view's orbit is not the camera: the shot applies the turntable.
    const Camera seen = shot ? view_->baseCamera()
                             : camera_at_frame(timeline_->spec(), view_->baseCamera(), nullptr,
                                               timeline_->sourceFrame(), meshCentre());
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
        // The frame asked for cannot be drawn (the eye inside the mesh):
        // no drawing of another frame stands in for it, in the pane, the
        // 3-D view's lines or Export Frame.
        frameProblem_ = tr("This frame cannot be drawn: %1").arg(result.error);
        svg_.clear();
        svgPane_->setProblem(frameProblem_);
        contourLoops_ = 0;
        contourLabel_->setText(tr("no contours: this frame cannot be drawn"));
        view_->setContours({}, result.camera);
        timeline_->frameShown(result.frame);
        emit contoursUpdated();
        return;
    }
    frameProblem_.clear();
    if (result.geometry) view_->setPose(std::move(*result.geometry));
    view_->setRegionShading(region_shading(document_->style(), result.light, regionsAction_->isChecked()));
    contourLoops_ = result.loops;
    contourLabel_->setText(tr("%1 loops, %2 snaxels, %3 ms").arg(result.loops).arg(result.snaxels).arg(result.ms, 0, 'f', 1));
    // Through a file's camera, the 3-D view looks through it too.
    view_->setFileCamera(timeline_->spec().camera.empty() ? std::nullopt : std::optional<Camera>(result.camera));
    view_->setContours(std::move(result.strips), result.camera);
    timeline_->frameShown(result.frame);
    svg_ = QByteArray::fromStdString(result.svg);
    svgPane_->load(svg_);
    emit contoursUpdated();
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
        objects_->setStyleText(text);
        if (styleEditor_->text() == text) return;
        ++restoring_;
        styleEditor_->setText(text, "style");
        --restoring_;
    });
    connect(document_, &Document::styleChanged, this, [this] {
        parabolic_->ensure(); // a style that draws parabolic curves needs them found
        scheduleContours();
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

} // namespace snaxels::ui
