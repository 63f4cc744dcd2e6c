#pragma once
// Reading a mesh for the application off the GUI thread: the mesh, the
// contour scene made from it and the geometry the 3-D view draws, or the
// one-line reason it failed. One load at a time. A controller beside the
// window (no widgets).

#include <memory>

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include "snaxels/mesh/build.h"
#include "ui/contour_overlay.h"

namespace snaxels::ui {

/// What a background load produces: a mesh or the one-line reason it failed.
struct LoadResult {
    std::shared_ptr<const LoadedMesh> mesh;
    std::shared_ptr<ContourScene> scene;
    std::shared_ptr<MeshGeometry> geometry;
    QString error;
};

class MeshLoader : public QObject {
    Q_OBJECT
  public:
    explicit MeshLoader(QObject* parent = nullptr);
    ~MeshLoader() override;

    /// Starts reading @p spec (a file path or proc:NAME[:FACES]); false
    /// when a load is under way (nothing starts then).
    bool load(const QString& spec);
    /// A load is under way: from load() until finished() is emitted (the
    /// watcher stops running when the thread ends, before that).
    bool loading() const { return loading_; }
    /// The spec being read, or last read.
    const QString& spec() const { return spec_; }

  signals:
    void finished(const snaxels::ui::LoadResult& result);

  private:
    QString spec_;
    QFutureWatcher<LoadResult> watcher_;
    bool loading_ = false;
};

} // namespace snaxels::ui
