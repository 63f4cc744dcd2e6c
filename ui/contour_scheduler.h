#pragma once
// When the application's contours are computed: shortly after the camera,
// the light, the style or the frame stops changing, off the GUI thread, one
// computation at a time, the newest request winning (a result that a later
// request made stale is dropped and the computation runs again). A
// controller beside the window (no widgets).

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

    /// A computation soon (the requests of the next 30 ms are one).
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
    bool pending_ = false; ///< asked for while one was running
};

} // namespace snaxels::ui
