#include "ui/parabolic_search.h"

#include <utility>

#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

namespace snaxels::ui {

ParabolicSearch::ParabolicSearch(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcher<std::shared_ptr<const ParabolicResult>>::finished, this,
            &ParabolicSearch::onFinished);
}

ParabolicSearch::~ParabolicSearch() {
    cancel();
    watcher_.waitForFinished();
}

void ParabolicSearch::setWanted(std::function<bool()> wanted) { wanted_ = std::move(wanted); }

void ParabolicSearch::setMesh(const MeshTopology& rest) {
    rest_ = rest;
    ++generation_;
}

void ParabolicSearch::clearMesh() {
    rest_.reset();
    ++generation_;
}

std::shared_ptr<const ParabolicResult> ParabolicSearch::curves() const {
    // The mesh's own, kept in its pose's quantities by the search.
    return rest_ ? kept_parabolic(*rest_) : nullptr;
}

bool ParabolicSearch::pending() const { return rest_ && wanted_ && wanted_() && !curves(); }

void ParabolicSearch::cancel() {
    if (cancel_) cancel_->store(true);
}

void ParabolicSearch::ensure() {
    if (!rest_ || !wanted_ || !wanted_()) return;
    if (curves()) return; // found
    if (watcher_.isRunning()) {
        // On the way; or for another mesh: stopped, and its end starts this one's.
        if (searchFor_ != generation_) cancel();
        return;
    }
    searchFor_ = generation_;
    // The mesh as loaded: a value sharing its connectivity and pose (the
    // overlay's thread may move the scene to another pose meanwhile; the
    // rest pose never changes).
    const MeshTopology topology = *rest_;
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    ParabolicOptions options;
    QPointer<ParabolicSearch> self(this);
    options.progress = [self](int done, int total) {
        QMetaObject::invokeMethod(
            self,
            [self, done, total] {
                if (self) emit self->progress(done, total);
            },
            Qt::QueuedConnection);
    };
    options.cancelled = [cancel = cancel_] { return cancel->load(); };
    error_ = std::make_shared<QString>(); // written by the search, read when it has finished
    emit started();
    watcher_.setFuture(QtConcurrent::run([topology, options, error = error_]() -> std::shared_ptr<const ParabolicResult> {
        try {
            return require_parabolic(topology, options);
        } catch (const ParabolicCancelled&) {
            return nullptr;
        } catch (const std::exception& e) {
            *error = QString::fromStdString(e.what());
            return nullptr;
        }
    }));
}

void ParabolicSearch::onFinished() {
    std::shared_ptr<const ParabolicResult> result = watcher_.result();
    const int searchedFor = std::exchange(searchFor_, -1);
    if (searchedFor != generation_) { // another mesh since: start over for it
        emit stopped();
        ensure();
        return;
    }
    if (!result) {
        emit finished(error_ && !error_->isEmpty() ? *error_ : QString(), false);
        return;
    }
    emit finished(QString(), true); // kept in the mesh's pose (curves())
}

} // namespace snaxels::ui
