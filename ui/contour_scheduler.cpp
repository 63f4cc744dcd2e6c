#include "ui/contour_scheduler.h"

#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

namespace snaxels::ui {

ContourScheduler::ContourScheduler(std::function<std::optional<Work>()> source, QObject* parent)
    : QObject(parent), source_(std::move(source)), timer_(new QTimer(this)) {
    timer_->setSingleShot(true);
    timer_->setInterval(0);
    connect(timer_, &QTimer::timeout, this, &ContourScheduler::start);
    connect(&watcher_, &QFutureWatcher<OverlayResult>::finished, this, &ContourScheduler::onFinished);
}

ContourScheduler::~ContourScheduler() { watcher_.waitForFinished(); }

void ContourScheduler::schedule() {
    if (running_) pending_ = true;
    else if (!timer_->isActive()) timer_->start();
}

void ContourScheduler::invalidate() {
    if (running_) stale_ = pending_ = true;
}

bool ContourScheduler::busy() const { return timer_->isActive() || running_; }

void ContourScheduler::start() {
    if (running_) {
        pending_ = true;
        return;
    }
    std::optional<Work> work = source_();
    if (!work) return;
    pending_ = stale_ = false;
    running_ = true;
    watcher_.setFuture(QtConcurrent::run(std::move(*work)));
}

void ContourScheduler::onFinished() {
    running_ = false;
    const bool again = pending_, drop = stale_;
    // A result for the mesh shown is the newest the view can have, even
    // when the input moved on meanwhile; one for another mesh is not.
    if (!drop) emit ready(watcher_.result());
    if (again) start();
}

} // namespace snaxels::ui
