#pragma once
// The application's search for the loaded mesh's parabolic curves: run off
// the GUI thread when the view or the style asks for them, once per mesh,
// with progress, and cancelled when another mesh arrives or the window
// closes. A controller beside the window (no widgets), so it is tested
// without one.

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include "snaxels/mesh/topology.h"
#include "snaxels/snaxel/parabolic.h"

namespace snaxels::ui {

class ParabolicSearch : public QObject {
    Q_OBJECT
  public:
    explicit ParabolicSearch(QObject* parent = nullptr);
    ~ParabolicSearch() override;

    /// Whether the curves are wanted now (the view shows them, or the style
    /// draws them); searches start only then.
    void setWanted(std::function<bool()> wanted);
    /// A new mesh (@p rest, its pose as loaded): the curves found so far are
    /// the old mesh's; a search under way for them stops at the next ensure().
    void setMesh(const MeshTopology& rest);
    /// Finds the current mesh's curves when they are wanted, unless they
    /// are found or being found.
    void ensure();
    /// The current mesh's curves, or null until found.
    std::shared_ptr<const ParabolicResult> curves() const;
    /// No mesh (a document closed): nothing to find.
    void clearMesh();
    /// The curves are wanted and not found yet.
    bool pending() const;
    /// A search is under way.
    bool running() const { return watcher_.isRunning(); }
    /// Stops a search under way at its next step.
    void cancel();

  signals:
    /// A search started.
    void started();
    /// Progress of the running search: view steps done, in all.
    void progress(int done, int total);
    /// A search for an earlier mesh ended (the current mesh's follows).
    void stopped();
    /// The current mesh's search ended: @p found, else cancelled (@p error
    /// empty) or failed (@p error says why).
    void finished(const QString& error, bool found);

  private:
    void onFinished();

    std::function<bool()> wanted_;
    std::optional<MeshTopology> rest_;
    int generation_ = 0;  ///< counts meshes set
    int searchFor_ = -1;  ///< the mesh the search under way is for (-1: none)
    std::shared_ptr<std::atomic<bool>> cancel_;
    std::shared_ptr<QString> error_; ///< the running search's error, if any
    QFutureWatcher<std::shared_ptr<const ParabolicResult>> watcher_;
};

} // namespace snaxels::ui
