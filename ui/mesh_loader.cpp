#include "ui/mesh_loader.h"

#include <QtConcurrent/QtConcurrentRun>

#include "snaxels/mesh/import.h"
#include "ui/meshview.h"

namespace snaxels::ui {
namespace {

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

MeshLoader::MeshLoader(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcher<LoadResult>::finished, this, [this] {
        loading_ = false;
        emit finished(watcher_.result());
    });
}

MeshLoader::~MeshLoader() { watcher_.waitForFinished(); }

bool MeshLoader::load(const QString& spec) {
    if (loading_) return false;
    loading_ = true;
    spec_ = spec;
    watcher_.setFuture(QtConcurrent::run(loadInBackground, spec));
    return true;
}

} // namespace snaxels::ui
