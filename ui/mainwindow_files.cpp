// MainWindow, continued: opening meshes, sequences and projects, saving,
// exporting, recent files, drag-and-drop and closing.
#include "ui/mainwindow.h"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <QCloseEvent>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>

#include "snaxels/export/raster.h"
#include "snaxels/export/video.h"
#include "snaxels/util/atomic_file.h"
#include "ui/animation_export.h"
#include "ui/contour_scheduler.h"
#include "ui/document.h"
#include "ui/meshview.h"
#include "ui/parabolic_search.h"
#include "ui/styleeditor.h"
#include "ui/timeline.h"

namespace snaxels::ui {

void MainWindow::commitWidgets() {
    styleEditor_->applyPending();
    document_->setStyleText(styleEditor_->text());
    document_->setView(viewState());
    document_->setAnimation(timeline_->spec());
    document_->setFrame(timeline_->frame());
}

void MainWindow::openMesh(const QString& spec) {
    if (refuseWhileLoading()) return;
    if (!maybeSave()) return; // the mesh starts a new document
    startLoading(spec);
}

bool MainWindow::refuseWhileLoading() {
    if (!loader_->loading()) return false;
    statusBar()->showMessage(tr("Still loading %1; try again when it is done").arg(loader_->spec()), 4000);
    return true;
}

void MainWindow::startLoading(const QString& spec) {
    if (refuseWhileLoading() || !loader_->load(spec)) return;
    busy_->show();
    statusBar()->showMessage(tr("Loading %1…").arg(QFileInfo(spec).fileName()));
}

void MainWindow::onLoadFailed(const LoadResult& result) {
    // Nothing of the document changes: the mesh, style and edits stay.
    QString message = result.error;
    if (pendingProject_) message = tr("%1: its mesh could not be opened: %2").arg(pendingProjectPath_, result.error);
    statusBar()->showMessage(tr("Could not open %1").arg(loader_->spec()), 8000);
    warn(pendingProject_ ? tr("Could not open project") : tr("Could not open mesh"), message);
    const bool wasProject = pendingProject_.has_value();
    pendingProject_.reset();
    pendingSequence_.reset();
    emit loadFailed(result.error);
    if (wasProject) emit projectFailed(message);
}

void MainWindow::returnFreedMemorySoon() {
    if (!memoryTimer_) {
        memoryTimer_ = new QTimer(this);
        memoryTimer_->setSingleShot(true);
        memoryTimer_->setInterval(1000);
        connect(memoryTimer_, &QTimer::timeout, this, [this] {
            if (isLoading() || contoursBusy() || export_->running() || parabolic_->running()) return memoryTimer_->start();
#ifdef __GLIBC__
            malloc_trim(0);
#endif
        });
    }
    memoryTimer_->start();
}

void MainWindow::onLoadFinished(const LoadResult& result) {
    returnFreedMemorySoon(); // the last mesh's memory, once nothing holds it
    contours_->invalidate(); // what is under way is of the old mesh
    scene_ = result.scene;
    parabolic_->setMesh(scene_->rest);
    parabolic_->ensure();
    view_->setContours({}, view_->camera());
    ++restoring_; // framing the new mesh is not an edit
    view_->setGeometry(MeshGeometry(*result.geometry)); // frames the camera, which schedules contours
    timeline_->setClips(scene_->clips);
    timeline_->setCameras(scene_->cameras);
    --restoring_;
    document_->resetView(viewState());
    document_->resetAnimation(timeline_->spec());
    showMeshReport(*result.mesh);
    const QString spec = loader_->spec();
    statusBar()->showMessage(tr("Loaded %1").arg(QFileInfo(spec).fileName()), 4000);
    if (pendingProject_) {
        const Project project = std::move(*pendingProject_);
        pendingProject_.reset();
        applyProject(project, pendingProjectPath_, result.mesh);
    } else if (pendingSequence_) {
        const SequenceFiles files = std::move(*pendingSequence_);
        pendingSequence_.reset();
        applySequence(files, result.mesh);
    } else {
        // A new untitled document: this one's style, the mesh's own framing
        // and the animation a new mesh starts with.
        ++restoring_;
        timeline_->setSpec(initial_animation());
        timeline_->setFrame(0);
        --restoring_;
        document_->startNew(spec, result.mesh, viewState(), timeline_->spec());
        if (!spec.startsWith("proc:")) addRecentFile(QFileInfo(spec).absoluteFilePath());
    }
    updateTitle();
    emit meshLoaded(spec);
    if (!document_->projectPath().isEmpty() && !document_->isModified()) emit projectOpened(document_->projectPath());
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

void MainWindow::applySequence(const SequenceFiles& files, std::shared_ptr<const LoadedMesh> mesh) {
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
    document_->startNew(loader_->spec(), std::move(mesh), viewState(), timeline_->spec());
    statusBar()->showMessage(tr("Loaded a sequence of %1 files: %2")
                                 .arg(files.count)
                                 .arg(QFileInfo(QString::fromStdString(files.pattern)).fileName()),
                             6000);
    scheduleContours();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
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
    if (!urls.isEmpty() && urls.first().isLocalFile()) openFile(urls.first().toLocalFile());
}

bool MainWindow::exportFrame(const QString& path) {
    if (svg_.isEmpty()) { // the first drawing has not come yet (a mesh still loading), or cannot be made: nothing is written
        const QString message =
            !frameProblem_.isEmpty() ? frameProblem_ : tr("Nothing to export yet: the first frame is still being drawn.");
        QMessageBox::warning(this, tr("Export Frame"), message);
        emit exportFailed(message);
        return false;
    }
    try {
        if (QFileInfo(path).suffix().compare("pdf", Qt::CaseInsensitive) == 0) write_pdf(path.toStdString(), svg_.toStdString());
        else write_file_atomically(path.toStdString(), svg_.toStdString());
        reportExported(path);
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
    if (!document_->mesh() || export_->running()) return;
    commitWidgets(); // the export writes the document
    AnimationJob job = document_->animationJob();
    QString problem;
    if (!set_output(job, path.toStdString())) {
        problem = tr("Cannot write %1: the file's extension must be one of %2.")
                      .arg(QFileInfo(path).fileName(), QString::fromStdString(output_extensions()));
    } else if (!job.video.empty()) {
        try {
            require_ffmpeg();
        } catch (const std::exception& e) {
            problem = QString::fromStdString(e.what());
        }
    }
    if (!problem.isEmpty()) { // said before any work, as an export's failure is
        statusBar()->showMessage(problem, 8000);
        warn(tr("Export Animation"), tr("The animation was not exported: %1").arg(problem));
        emit exportFailed(problem);
        return;
    }
    export_->start(this, path, std::move(job), document_->mesh(), document_->meshSpec().toStdString());
}

void MainWindow::openFile(const QString& path) {
    if (path.endsWith(kProjectExtension, Qt::CaseInsensitive)) openProject(path);
    else openMesh(path);
}

bool MainWindow::maybeSave() {
    commitWidgets(); // typing not applied yet is an unsaved change too
    if (!isModified()) return true;
    const QString name = !document_->projectPath().isEmpty() ? QFileInfo(document_->projectPath()).fileName()
                         : document_->meshSpec().isEmpty() ? tr("this project")
                                                           : tr("the untitled project of %1").arg(QFileInfo(document_->meshSpec()).fileName());
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
        // An untitled document's project goes beside its mesh, named after it.
        const QFileInfo mesh(document_->meshSpec());
        const QString suggested = !path.isEmpty() ? path
                                  : document_->meshSpec().startsWith("proc:")
                                      ? QDir(QSettings().value("paths/lastDir").toString()).filePath("untitled.snaxels")
                                      : mesh.absoluteDir().filePath(mesh.completeBaseName() + kProjectExtension);
        path = QFileDialog::getSaveFileName(this, tr("Save Project"), suggested, tr("Snaxels projects (*.snaxels)"));
        if (path.isEmpty()) return false;
        if (!path.endsWith(kProjectExtension, Qt::CaseInsensitive)) path += kProjectExtension;
    }
    return saveProject(path);
}

bool MainWindow::saveProject(const QString& path) {
    if (!document_->mesh()) return false;
    commitWidgets();
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
        warn(tr("Could not open sequence"), message);
        statusBar()->showMessage(message, 8000);
        emit loadFailed(message);
        return false;
    }
    if (refuseWhileLoading()) return false;
    if (!maybeSave()) return false;
    pendingSequence_ = *files;
    // The mesh is the series' first file; every frame is posed from its file.
    AnimationSpec probe;
    probe.kind = AnimationSpec::Kind::Sequence;
    probe.pattern = files->pattern;
    probe.first_file = files->first_file;
    startLoading(QString::fromStdString(sequence_file(probe, 0)));
    return true;
}

void MainWindow::openProject(const QString& path) {
    if (refuseWhileLoading()) return;
    Project project;
    try {
        project = read_project(path.toStdString());
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        warn(tr("Could not open project"), message);
        statusBar()->showMessage(message, 8000);
        emit projectFailed(message);
        return;
    }
    if (!maybeSave()) return;
    pendingProject_ = std::move(project);
    pendingProjectPath_ = path;
    startLoading(QString::fromStdString(resolve_project_mesh(path.toStdString(), pendingProject_->mesh)));
}

void MainWindow::applyProject(const Project& p, const QString& path, std::shared_ptr<const LoadedMesh> mesh) {
    ++restoring_; // the document sets the widgets: not edits
    document_->load(p, path, loader_->spec(), std::move(mesh));
    const AnimationSpec& animation = document_->animation();
    if (animation.kind == AnimationSpec::Kind::Sequence)
        if (const auto files = find_sequence(sequence_file(animation, 0))) timeline_->setSequenceFiles(files->count);
    timeline_->setFrame(p.frame);
    --restoring_;
    addRecentFile(QFileInfo(path).absoluteFilePath());
    if (!specAccepted_) {
        const QString file = QFileInfo(path).fileName();
        // A clip or a camera the file no longer has.
        const bool camera = !p.animation.camera.empty() && timeline_->spec().camera != p.animation.camera;
        const QString why =
            camera ? tr("%1: the mesh file has no camera \"%2\"; the timeline shows the view's camera")
                         .arg(file, QString::fromStdString(p.animation.camera))
                   : tr("%1: the mesh has no clip \"%2\"; the timeline shows a turntable")
                         .arg(file, QString::fromStdString(p.animation.clip));
        statusBar()->showMessage(why, 10000);
        document_->resetAnimation(timeline_->spec());
        document_->markModified(); // what the window shows is no longer what the file holds
    }
    updateTitle();
    scheduleContours();
}

} // namespace snaxels::ui
