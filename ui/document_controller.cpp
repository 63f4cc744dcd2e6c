#include "ui/document_controller.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

#include "ui/document.h"
#include "ui/export_actions.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"
#include "ui/timeline.h"
#include "ui/preferences.h"

namespace snaxels::ui {

AnimationSpec first_look(const SceneFacts& facts) {
    AnimationSpec spec = initial_animation();
    const FileCamera* camera = facts.cameras.empty() ? nullptr : &facts.cameras.front();
    if (camera) spec.camera = camera->name; // the picture the file composed
    if (!facts.clips.empty()) {
        // Its own animation, whole: the clip that moves its camera (which
        // moves the rest of the scene too, as the file keyed it), else the first.
        spec.kind = AnimationSpec::Kind::Clip;
        spec.clip = camera && camera->animated() ? camera->clip : facts.clips.front().name;
        spec.frames = 0;
    } else if (camera) { // a camera no clip moves: the still it frames
        spec.kind = AnimationSpec::Kind::Still;
        spec.frames = 1;
    }
    return spec; // resolved by the document (a clip's frames)
}

DocumentController::DocumentController(Document* document, QWidget* dialogParent)
    : QObject(dialogParent), document_(document), dialogParent_(dialogParent), loader_(new MeshLoader(this)) {
    connect(loader_, &MeshLoader::finished, this, [this](const LoadResult& result) {
        emit busy(false);
        if (result.mesh) onLoaded(result);
        else onLoadFailed(result);
    });
}

void DocumentController::flush() const {
    if (flush_) flush_();
}

void DocumentController::warn(const QString& title, const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, dialogParent_);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void DocumentController::openFile(const QString& path) {
    if (path.endsWith(kProjectExtension, Qt::CaseInsensitive)) openProject(path);
    else openMesh(path);
}

void DocumentController::openMesh(const QString& spec) {
    if (refuseWhileLoading()) return;
    if (!maybeSave()) return; // the mesh starts a new document
    startLoading(spec);
}

bool DocumentController::refuseWhileLoading() {
    if (!loader_->loading()) return false;
    emit status(tr("Still loading %1; try again when it is done").arg(loader_->spec()), 4000);
    return true;
}

void DocumentController::startLoading(const QString& spec) {
    if (refuseWhileLoading() || !loader_->load(spec)) return;
    emit busy(true);
    emit status(tr("Loading %1…").arg(QFileInfo(spec).fileName()), 0);
}

void DocumentController::onLoadFailed(const LoadResult& result) {
    // Nothing of the document changes: the mesh, style and edits stay.
    QString message = result.error;
    if (pendingProject_) message = tr("%1: its mesh could not be opened: %2").arg(pendingProjectPath_, result.error);
    emit status(tr("Could not open %1").arg(loader_->spec()), 8000);
    warn(pendingProject_ ? tr("Could not open project") : tr("Could not open mesh"), message);
    const bool wasProject = pendingProject_.has_value();
    pendingProject_.reset();
    pendingSequence_.reset();
    emit loadFailed(result.error);
    if (wasProject) emit projectFailed(message);
}

void DocumentController::onLoaded(const LoadResult& result) {
    emit loaded(result);
    SceneFacts facts;
    facts.clips = result.scene->clips;
    facts.cameras = result.scene->cameras;
    facts.centre = result.geometry->centre;
    facts.radius = result.geometry->radius;
    const QString spec = loader_->spec();
    emit status(tr("Loaded %1").arg(QFileInfo(spec).fileName()), 4000);
    if (pendingProject_) {
        const Project project = std::move(*pendingProject_);
        pendingProject_.reset();
        const QString notice = document_->load(project, pendingProjectPath_, spec, result.mesh, facts);
        addRecentFile(QFileInfo(pendingProjectPath_).absoluteFilePath());
        if (!notice.isEmpty()) emit status(notice, 10000);
    } else if (pendingSequence_) {
        const SequenceFiles files = std::move(*pendingSequence_);
        pendingSequence_.reset();
        AnimationSpec animation = document_->animation(); // its rate stays
        animation.kind = AnimationSpec::Kind::Sequence;
        animation.pattern = files.pattern;
        animation.first_file = files.first_file;
        animation.frames = files.count;
        animation.start = 0;
        document_->startNew(spec, result.mesh, facts, animation);
        emit status(tr("Loaded a sequence of %1 files: %2")
                        .arg(files.count)
                        .arg(QFileInfo(QString::fromStdString(files.pattern)).fileName()),
                    6000);
    } else {
        // A new untitled document: this one's style (File > New: the
        // default), the mesh's own framing and the animation a new mesh
        // starts with.
        if (std::exchange(pendingDefaultStyle_, false)) document_->resetStyleText(preferred_style_text());
        document_->startNew(spec, result.mesh, facts, first_look(facts));
        if (!document_->animation().camera.empty())
            emit status(tr("Looking through the file's camera \"%1\": choose View camera in the timeline to orbit")
                            .arg(QString::fromStdString(document_->animation().camera)),
                        8000);
        if (!spec.startsWith("proc:")) addRecentFile(QFileInfo(spec).absoluteFilePath());
    }
    emit meshLoaded(spec);
    if (!document_->projectPath().isEmpty() && !document_->isModified()) emit projectOpened(document_->projectPath());
}

bool DocumentController::maybeSave() {
    flush(); // typing not applied yet is an unsaved change too
    if (!document_->isModified()) return true;
    const QString name = !document_->projectPath().isEmpty() ? QFileInfo(document_->projectPath()).fileName()
                         : document_->meshSpec().isEmpty()
                             ? tr("this project")
                             : tr("the untitled project of %1").arg(QFileInfo(document_->meshSpec()).fileName());
    QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"), tr("Save the changes to %1 first?").arg(name),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, dialogParent_);
    box.setInformativeText(tr("The style, camera, light and animation edits are lost otherwise."));
    box.setDefaultButton(QMessageBox::Save);
    box.setObjectName("unsavedChangesBox");
    switch (box.exec()) {
    case QMessageBox::Save: return saveInteractive(false);
    case QMessageBox::Discard: return true;
    default: return false;
    }
}

bool DocumentController::saveInteractive(bool askPath) {
    if (!document_->mesh()) {
        QMessageBox::information(dialogParent_, tr("Save Project"), tr("Open a mesh first: a project refers to one."));
        return false;
    }
    QString path = document_->projectPath();
    if (askPath || path.isEmpty()) {
        // An untitled document's project goes beside its mesh, named after
        // it, where that folder can be written to (else the last folder
        // used, documents or home).
        const QFileInfo mesh(document_->meshSpec());
        const bool proc = document_->meshSpec().startsWith("proc:");
        const QString folder = first_writable_folder(
            {proc ? QString() : mesh.absolutePath(), QSettings().value("paths/lastDir").toString()});
        const QString suggested = !path.isEmpty() ? path
                                  : QDir(folder).filePath(proc ? QString("untitled") + kProjectExtension
                                                               : mesh.completeBaseName() + kProjectExtension);
        path = QFileDialog::getSaveFileName(dialogParent_, tr("Save Project"), suggested, tr("Snaxels projects (*.snaxels)"));
        if (path.isEmpty()) return false;
        if (!path.endsWith(kProjectExtension, Qt::CaseInsensitive)) path += kProjectExtension;
    }
    return save(path);
}

bool DocumentController::save(const QString& path) {
    if (!document_->mesh()) return false;
    flush();
    try {
        document_->save(path);
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        QMessageBox::warning(dialogParent_, tr("Save Project"), message);
        emit status(message, 8000);
        return false;
    }
    addRecentFile(QFileInfo(path).absoluteFilePath());
    emit status(tr("Saved %1").arg(QFileInfo(path).fileName()), 4000);
    emit projectSaved(path);
    return true;
}

bool DocumentController::openSequence(const QString& path) {
    const std::optional<SequenceFiles> files = find_sequence(path.toStdString());
    if (!files || files->count < 2) {
        const QString message =
            files ? tr("%1: no other file of its series (the number in its name, one up or down) is there; "
                       "a sequence needs at least two")
                        .arg(QFileInfo(path).fileName())
                  : tr("%1: its name holds no frame number, so it is not part of a numbered sequence")
                        .arg(QFileInfo(path).fileName());
        warn(tr("Could not open sequence"), message);
        emit status(message, 8000);
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

void DocumentController::openProject(const QString& path) { loadProject(path, true); }

void DocumentController::loadProject(const QString& path, bool ask) {
    if (refuseWhileLoading()) return;
    Project project;
    try {
        project = read_project(path.toStdString());
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        warn(tr("Could not open project"), message);
        emit status(message, 8000);
        emit projectFailed(message);
        return;
    }
    if (ask && !maybeSave()) return; // a file that cannot be read is said before asking
    pendingProject_ = std::move(project);
    pendingProjectPath_ = path;
    startLoading(QString::fromStdString(resolve_project_mesh(path.toStdString(), pendingProject_->mesh)));
}

void DocumentController::newDocument() {
    if (refuseWhileLoading() || !maybeSave()) return;
    pendingDefaultStyle_ = true;
    startLoading(defaultScenePath());
}

bool DocumentController::closeDocument() {
    if (refuseWhileLoading() || !maybeSave()) return false;
    document_->startNew(QString(), nullptr, SceneFacts{}, initial_animation());
    emit status(tr("Closed: open a mesh or a project (Ctrl+O), or drop one on the window"), 6000);
    return true;
}

bool DocumentController::revert() {
    if (refuseWhileLoading()) return false;
    const QString project = document_->projectPath(), mesh = document_->meshSpec();
    if (project.isEmpty() && mesh.isEmpty()) return false;
    flush();
    if (document_->isModified()) {
        const QString name = QFileInfo(!project.isEmpty() ? project : mesh).fileName();
        QMessageBox box(QMessageBox::Warning, tr("Revert"), tr("Revert to the saved %1?").arg(name),
                        QMessageBox::Discard | QMessageBox::Cancel, dialogParent_);
        box.setInformativeText(tr("The changes since it was last saved or opened are lost."));
        box.button(QMessageBox::Discard)->setText(tr("Revert"));
        box.setDefaultButton(QMessageBox::Cancel);
        box.setObjectName("revertBox");
        if (box.exec() != QMessageBox::Discard) return false;
    }
    if (!project.isEmpty()) loadProject(project, false);
    else startLoading(mesh);
    return true;
}

void DocumentController::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecentFiles) recent.removeLast();
    settings.setValue("recentFiles", recent);
    emit recentFilesChanged();
}

} // namespace snaxels::ui
