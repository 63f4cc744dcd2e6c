#include "ui/contour_scheduler.h"

#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

namespace snaxels::ui {

ContourScheduler::ContourScheduler(std::function<std::optional<Work>()> source, QObject* parent)
    : QObject(parent), source_(std::move(source)), timer_(new QTimer(this)) {
    timer_->setSingleShot(true);
    timer_->setInterval(30);
    connect(timer_, &QTimer::timeout, this, &ContourScheduler::start);
    connect(&watcher_, &QFutureWatcher<OverlayResult>::finished, this, &ContourScheduler::onFinished);
}

ContourScheduler::~ContourScheduler() { watcher_.waitForFinished(); }

void ContourScheduler::schedule() { timer_->start(); }

void ContourScheduler::invalidate() {
    if (watcher_.isRunning()) pending_ = true;
}

bool ContourScheduler::busy() const { return timer_->isActive() || watcher_.isRunning(); }

void ContourScheduler::start() {
    if (watcher_.isRunning()) {
        pending_ = true;
        return;
    }
    std::optional<Work> work = source_();
    if (!work) return;
    pending_ = false;
    watcher_.setFuture(QtConcurrent::run(std::move(*work)));
}

void ContourScheduler::onFinished() {
    if (pending_) { // the scene changed meanwhile: this result is stale
        start();
        return;
    }
    emit ready(watcher_.result());
}

} // namespace snaxels::ui
