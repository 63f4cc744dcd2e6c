#include "ui/document.h"

#include <algorithm>

#include <QUndoStack>

#include "snaxels/mesh/parts.h"
#include "snaxels/style/style_edit.h"
#include "ui/undo.h"

namespace snaxels::ui {

Document::Document(QString style_text, QObject* parent)
    : QObject(parent), undo_(new QUndoStack(this)), defaultStyle_(style_text), style_(std::move(style_text)) {
    connect(undo_, &QUndoStack::cleanChanged, this, &Document::updateModified);
    connect(undo_, &QUndoStack::indexChanged, this, &Document::updateModified);
    try {
        parsed_ = parse_style(style_.toStdString(), "style", nullptr);
    } catch (const StyleError&) {
        parsed_ = default_style();
    }
    historyStart_ = edited();
    saved_ = historyStart_;
}

AnimationJob Document::animationJob() const {
    return make_animation_job(parsed_, animation_, orbit_base_camera(view_), light_);
}

bool Document::isModified() const {
    // Away from the stack's clean index, the edited parts may still be
    // what the file holds (undone to the saved text by other steps, typed
    // back by hand): that is no change to save.
    return meshChanged_ || (!undo_->isClean() && edited() != saved_);
}

void Document::updateModified() {
    const bool modified = isModified();
    if (modified == lastModified_) return;
    lastModified_ = modified;
    emit modifiedChanged(modified);
}

template <class T>
void Document::edit(const T& now, const T& value, const QString& text, int id, void (Document::*assign)(const T&),
                    bool mergeable) {
    if (value == now) return;
    // Pushing the step runs its redo, which makes the change. (QUndoStack
    // merges no step into the one at its clean index: undoing the first
    // step after a save comes back to what was saved.)
    undo_->push(new SetValueCommand<T>(text, id, now, value, this, assign, mergeable));
}

void Document::setStyleText(const QString& text) {
    edit(style_, text, tr("Edit Style"), kUndoStyle, &Document::assignStyle);
}

void Document::setStyleText(const QString& text, const QString& step) {
    edit(style_, text, step, kUndoStyle, &Document::assignStyle, false);
}

void Document::setView(const OrbitView& view) {
    edit(view_, view, tr("Move Camera"), kUndoCamera, &Document::assignView);
}

void Document::setView(const OrbitView& view, const QString& step) {
    edit(view_, view, step, kUndoCamera, &Document::assignView, false);
}

void Document::setLight(const std::optional<Light>& light) {
    edit(light_, light, tr("Move Light"), kUndoLight, &Document::assignLight);
}

void Document::setAnimation(const AnimationSpec& animation) {
    edit(animation_, animation, tr("Change Animation"), kUndoAnimation, &Document::assignAnimation);
}

void Document::assignStyle(const QString& text) {
    style_ = text;
    emit styleTextChanged(style_);
    try {
        parsed_ = parse_style(style_.toStdString(), "style", nullptr);
    } catch (const StyleError&) {
        return; // the last style that parsed stays in force, as the editor says
    }
    emit styleChanged(parsed_);
}

void Document::assignView(const OrbitView& view) {
    view_ = view;
    emit viewChanged(view_);
}

void Document::assignLight(const std::optional<Light>& light) {
    light_ = light;
    emit lightChanged(light_);
}

void Document::assignAnimation(const AnimationSpec& animation) {
    animation_ = animation;
    emit animationChanged(animation_);
}

void Document::setMeshChanged(bool changed) {
    meshChanged_ = changed;
    updateModified();
}

void Document::setFrame(int frame) {
    if (frame == frame_) return;
    frame_ = frame;
    emit frameChanged(frame_);
}

void Document::setMesh(const QString& spec, std::shared_ptr<const LoadedMesh> mesh) {
    meshSpec_ = spec;
    mesh_ = std::move(mesh);
    emit meshChanged();
    setMeshChanged(true);
}

void Document::startNew(const QString& spec, std::shared_ptr<const LoadedMesh> mesh, const OrbitView& view,
                        const AnimationSpec& animation) {
    meshSpec_ = spec;
    mesh_ = std::move(mesh);
    // The last scene's objects, named in the style, are not this one's.
    const auto kept = without_absent_objects(style_.toStdString(), [this](const std::string& name) {
        if (!mesh_) return false;
        return std::any_of(mesh_->objects.begin(), mesh_->objects.end(), [&](const SceneObject& o) {
            return glob_match(name, o.name) || glob_match(name, o.path);
        });
    });
    if (kept && QString::fromStdString(*kept) != style_) assignStyle(QString::fromStdString(*kept));
    emit meshChanged();
    resetView(view);
    resetAnimation(animation);
    setFrame(0);
    if (light_) assignLight(std::nullopt); // the user's light was the last file's
    startHistory(); // the history belongs to its document
    if (!projectPath_.isEmpty()) {
        projectPath_.clear();
        emit projectPathChanged(projectPath_);
    }
    saved_ = edited();
    setMeshChanged(false);
    lastModified_ = isModified();
    emit modifiedChanged(lastModified_);
}

// A change that is not an edit is no difference from the file either.
void Document::resetStyleText(const QString& text) {
    if (text != style_) assignStyle(text);
    saved_.style = style_;
    changedOutsideHistory();
}

void Document::resetView(const OrbitView& view) {
    if (view != view_) assignView(view);
    saved_.view = view_;
    changedOutsideHistory();
}

void Document::resetAnimation(const AnimationSpec& animation) {
    if (animation != animation_) assignAnimation(animation);
    saved_.animation = animation_;
    changedOutsideHistory();
}

void Document::restore(const Edited& edited) {
    if (edited.style != style_) assignStyle(edited.style);
    if (edited.view != view_) assignView(edited.view);
    if (edited.light != light_) assignLight(edited.light);
    if (edited.animation != animation_) assignAnimation(edited.animation);
    changedOutsideHistory();
}

void Document::startHistory() {
    undo_->clear();
    historyStart_ = edited();
}

void Document::changedOutsideHistory() {
    if (undo_->count() == 0) historyStart_ = edited();
}

void Document::markModified() { setMeshChanged(true); }

Project Document::project(const QString& path) const {
    Project p;
    p.mesh = project_mesh_reference(path.toStdString(), meshSpec_.toStdString());
    p.view = view_;
    p.light = light_;
    p.animation = animation_;
    if (p.animation.kind == AnimationSpec::Kind::Sequence) // relative to the project, as the mesh is
        p.animation.pattern = project_mesh_reference(path.toStdString(), p.animation.pattern);
    p.frame = frame_;
    p.style = style_.toStdString();
    return p;
}

void Document::save(const QString& path) {
    write_project(path.toStdString(), project(path));
    const bool moved = path != projectPath_;
    projectPath_ = path;
    saved_ = edited();
    undo_->setClean();
    setMeshChanged(false);
    updateModified();
    if (moved) emit projectPathChanged(projectPath_);
}

void Document::load(const Project& project, const QString& path, const QString& mesh_spec,
                    std::shared_ptr<const LoadedMesh> mesh) {
    meshSpec_ = mesh_spec;
    mesh_ = std::move(mesh);
    emit meshChanged();
    AnimationSpec animation = project.animation;
    if (animation.kind == AnimationSpec::Kind::Sequence) // stored relative to the project, as its mesh is
        animation.pattern = resolve_project_mesh(path.toStdString(), animation.pattern);
    assignStyle(project.style.empty() ? defaultStyle_ : QString::fromStdString(project.style));
    assignAnimation(animation);
    frame_ = project.frame;
    emit frameChanged(frame_);
    assignLight(project.light);
    assignView(project.view);
    startHistory();
    saved_ = edited();
    projectPath_ = path;
    emit projectPathChanged(projectPath_);
    setMeshChanged(false);
    lastModified_ = isModified();
    emit modifiedChanged(lastModified_);
}

} // namespace snaxels::ui
