#include "ui/document.h"

#include <QUndoStack>

#include "ui/undo.h"

namespace snaxels::ui {

Document::Document(QString style_text, QObject* parent)
    : QObject(parent), undo_(new QUndoStack(this)), defaultStyle_(style_text), style_(std::move(style_text)) {
    connect(undo_, &QUndoStack::cleanChanged, this, [this] { emit modifiedChanged(isModified()); });
    try {
        parsed_ = parse_style(style_.toStdString(), "style", nullptr);
    } catch (const StyleError&) {
        parsed_ = default_style();
    }
    historyStart_ = edited();
}

AnimationJob Document::animationJob() const {
    return make_animation_job(parsed_, animation_, orbit_base_camera(view_), light_);
}

bool Document::isModified() const { return meshChanged_ || !undo_->isClean(); }

template <class T>
void Document::edit(const T& now, const T& value, const QString& text, int id, void (Document::*assign)(const T&),
                    bool mergeable) {
    if (value == now) return;
    // Pushing the step runs its redo, which makes the change.
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
    const bool was = isModified();
    meshChanged_ = changed;
    if (isModified() != was) emit modifiedChanged(isModified());
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
    setMeshChanged(false);
    emit modifiedChanged(isModified());
}

void Document::resetStyleText(const QString& text) {
    if (text != style_) assignStyle(text);
    changedOutsideHistory();
}

void Document::resetView(const OrbitView& view) {
    if (view != view_) assignView(view);
    changedOutsideHistory();
}

void Document::resetAnimation(const AnimationSpec& animation) {
    if (animation != animation_) assignAnimation(animation);
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
    undo_->setClean();
    setMeshChanged(false);
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
    projectPath_ = path;
    emit projectPathChanged(projectPath_);
    setMeshChanged(false);
    emit modifiedChanged(isModified());
}

} // namespace snaxels::ui
