#include "ui/document.h"

#include <algorithm>

#include <QFileInfo>
#include <QUndoStack>

#include "snaxels/mesh/parts.h"
#include "snaxels/style/style_edit.h"
#include "ui/undo.h"

namespace snaxels::ui {

namespace {

/// The clip of @p facts that @p name names: by name, by number, or the
/// first when empty.
const AnimationClipInfo* named_clip(const SceneFacts& facts, const std::string& name) {
    for (std::size_t i = 0; i < facts.clips.size(); ++i)
        if (facts.clips[i].name == name || (name.empty() && i == 0) || std::to_string(i) == name) return &facts.clips[i];
    return nullptr;
}

const FileCamera* named_camera(const SceneFacts& facts, const std::string& name) {
    for (const FileCamera& c : facts.cameras)
        if (c.name == name) return &c;
    return nullptr;
}

} // namespace

AnimationSpec resolve_animation(const AnimationSpec& spec, const SceneFacts& facts, bool* found) {
    AnimationSpec s = spec;
    bool all = true;
    double seconds = 0.0; // a clip's or camera move's length
    auto turntable = [&] {
        s.kind = AnimationSpec::Kind::Turntable;
        s.clip.clear();
        all = false;
    };
    if (s.kind == AnimationSpec::Kind::Clip) {
        if (const AnimationClipInfo* clip = named_clip(facts, s.clip)) s.clip = clip->name, seconds = clip->duration;
        else turntable();
    } else if (s.kind == AnimationSpec::Kind::Camera) {
        const FileCamera* camera = named_camera(facts, s.camera);
        if (camera && camera->animated()) s.clip = camera->clip, seconds = camera->clip_seconds;
        else turntable();
    } else {
        s.clip.clear(); // only clips and camera moves name one
    }
    if (s.kind != AnimationSpec::Kind::Sequence) s.pattern.clear(), s.first_file = -1;
    // The camera looked through: the file's, if it has that camera.
    if (!s.camera.empty() && !named_camera(facts, s.camera)) s.camera.clear(), all = false;
    if (s.frames <= 0 && all && (s.kind == AnimationSpec::Kind::Clip || s.kind == AnimationSpec::Kind::Camera))
        s.frames = clip_frame_count(seconds, s.fps);
    s.frames = std::max(s.frames, 1);
    if (found) *found = all;
    return s;
}

Document::Document(QString style_text, QObject* parent)
    : QObject(parent), undo_(new QUndoStack(this)), defaultStyle_(style_text), style_(std::move(style_text)),
      parsed_(default_style()) {
    connect(undo_, &QUndoStack::cleanChanged, this, &Document::updateModified);
    connect(undo_, &QUndoStack::indexChanged, this, &Document::updateModified);
    parseStyle();
    historyStart_ = edited();
    saved_ = historyStart_;
}

OrbitView Document::framingView() const { return framing_view(facts_.centre, facts_.radius); }

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
    parseStyle();
}

void Document::parseStyle() {
    warnings_.clear();
    problem_.reset();
    bool parsed = false;
    try {
        parsed_ = parse_style(style_.toStdString(), styleSource_.toStdString(), &warnings_);
        parsed = true;
        // Patterns that name no part of the scene on screen.
        if (parts_)
            for (StyleDiagnostic& w : check_parts(parsed_, *parts_)) warnings_.push_back(std::move(w));
    } catch (const StyleError& e) {
        problem_ = e.diagnostic(); // the last style that parsed stays in force, as the editor says
    }
    emit styleChecked();
    if (parsed) emit styleChanged(parsed_);
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
    setFrame(frame_); // within the new frame count
}

void Document::setMeshChanged(bool changed) {
    meshChanged_ = changed;
    updateModified();
}

void Document::setFrame(int frame) {
    frame = std::clamp(frame, 0, std::max(animation_.frames, 1) - 1);
    if (frame == frame_) return;
    frame_ = frame;
    emit frameChanged(frame_);
}

void Document::setMesh(const QString& spec, std::shared_ptr<const LoadedMesh> mesh) {
    meshSpec_ = spec;
    mesh_ = std::move(mesh);
    parts_ = mesh_ ? loaded_parts(*mesh_) : nullptr;
    emit meshChanged();
    parseStyle(); // checked against the new scene's parts
    setMeshChanged(true);
}

void Document::startNew(const QString& spec, std::shared_ptr<const LoadedMesh> mesh, const SceneFacts& facts,
                        const AnimationSpec& animation) {
    meshSpec_ = spec;
    mesh_ = std::move(mesh);
    parts_ = mesh_ ? loaded_parts(*mesh_) : nullptr;
    facts_ = facts;
    // The last scene's objects, named in the style, are not this one's.
    const auto kept = without_absent_objects(style_.toStdString(), [this](const std::string& name) {
        if (!mesh_) return false;
        return std::any_of(mesh_->objects.begin(), mesh_->objects.end(), [&](const SceneObject& o) {
            return glob_match(name, o.name) || glob_match(name, o.path);
        });
    });
    if (kept && QString::fromStdString(*kept) != style_) assignStyle(QString::fromStdString(*kept));
    else parseStyle(); // checked against the new scene's parts
    emit meshChanged();
    resetView(framingView());
    resetAnimation(resolve_animation(animation, facts_));
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
void Document::resetStyleText(const QString& text, const QString& source) {
    const bool renamed = source != styleSource_;
    styleSource_ = source;
    if (text != style_) assignStyle(text);
    else if (renamed) parseStyle(); // its diagnostics name the new source
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

QString Document::load(const Project& project, const QString& path, const QString& mesh_spec,
                       std::shared_ptr<const LoadedMesh> mesh, const SceneFacts& facts) {
    meshSpec_ = mesh_spec;
    mesh_ = std::move(mesh);
    parts_ = mesh_ ? loaded_parts(*mesh_) : nullptr;
    facts_ = facts;
    emit meshChanged();
    AnimationSpec animation = project.animation;
    if (animation.kind == AnimationSpec::Kind::Sequence) // stored relative to the project, as its mesh is
        animation.pattern = resolve_project_mesh(path.toStdString(), animation.pattern);
    bool found = true;
    const AnimationSpec resolved = resolve_animation(animation, facts_, &found);
    styleSource_ = QStringLiteral("style");
    assignStyle(project.style.empty() ? defaultStyle_ : QString::fromStdString(project.style));
    assignAnimation(resolved);
    frame_ = -1; // told to the observers whatever it was
    setFrame(project.frame);
    assignLight(project.light);
    OrbitView view = project.view;
    if (mesh_) view.centre = facts_.centre; // the view orbits the mesh, wherever the file saw it
    view.turntable = 0.0;
    assignView(view);
    startHistory();
    saved_ = edited();
    projectPath_ = path;
    emit projectPathChanged(projectPath_);
    setMeshChanged(false);
    lastModified_ = isModified();
    emit modifiedChanged(lastModified_);
    if (found) return {};
    // A clip or a camera the file no longer has: what the document shows
    // is no longer what the file holds.
    const QString file = QFileInfo(path).fileName();
    const bool camera = !animation.camera.empty() && resolved.camera != animation.camera;
    markModified();
    return camera ? tr("%1: the mesh file has no camera \"%2\"; the timeline shows the view's camera")
                        .arg(file, QString::fromStdString(animation.camera))
                  : tr("%1: the mesh has no clip \"%2\"; the timeline shows a turntable")
                        .arg(file, QString::fromStdString(animation.clip));
}

} // namespace snaxels::ui
