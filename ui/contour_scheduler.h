#pragma once
// When the application's contours are computed: as soon as the camera, the
// light, the style or the frame changes, off the GUI thread, one
// computation at a time. Requests made while one runs are one request,
// started when it ends: during an orbit or playback the computations follow
// each other back to back, each showing its result (the newest the view has)
// while the next one catches up, so the contours never wait for the input
// to stop. A controller beside the window (no widgets).

#include <functional>
#include <optional>

#include <QFutureWatcher>
#include <QObject>

#include "ui/contour_overlay.h"

class QTimer;

namespace snaxels::ui {

class ContourScheduler : public QObject {
    Q_OBJECT
  public:
    /// The work of one computation, made on the GUI thread from the state
    /// at its start and run off it.
    using Work = std::function<OverlayResult()>;

    /// @p source makes the work when a computation starts (nothing: there
    /// is nothing to compute).
    explicit ContourScheduler(std::function<std::optional<Work>()> source, QObject* parent = nullptr);
    ~ContourScheduler() override;

    /// A computation: at once when none runs (the requests of one pass of
    /// the event loop are one), else when the running one ends.
    void schedule();
    /// What is under way is stale (another mesh): its result is dropped.
    void invalidate();
    /// A computation is scheduled or running (a result is still to come).
    bool busy() const;

  signals:
    /// A computation's result, current when it arrives.
    void ready(const snaxels::ui::OverlayResult& result);

  private:
    void start();
    void onFinished();

    std::function<std::optional<Work>()> source_;
    QTimer* timer_;
    QFutureWatcher<OverlayResult> watcher_;
    /// From a computation's start until its end is handled: the watcher
    /// stops running when the thread ends, before its result is delivered.
    bool running_ = false;
    bool pending_ = false; ///< asked for while one was running
    bool stale_ = false;   ///< the running one's result is for another mesh
};

} // namespace snaxels::ui
