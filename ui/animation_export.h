#pragma once
// Exporting an animation from the application: the job runs on a worker
// thread, writing the file as the frames are made (it appears, whole, only
// at the end), with a progress dialog that shows a parabolic search first
// when the style needs one and can cancel (nothing is written then). A
// controller beside the window.

#include <atomic>
#include <memory>
#include <string>

#include <QFuture>
#include <QObject>
#include <QString>

#include "snaxels/animation/pipeline.h"

class QWidget;

namespace snaxels::ui {

class AnimationExport : public QObject {
    Q_OBJECT
  public:
    explicit AnimationExport(QObject* parent = nullptr);
    /// Stops an export under way at its next frame and waits for it.
    ~AnimationExport() override;

    /// Starts writing @p job to @p path from @p mesh (read from
    /// @p mesh_path), its progress dialog over @p window; false when an
    /// export is under way (nothing starts then).
    bool start(QWidget* window, const QString& path, AnimationJob job, std::shared_ptr<const LoadedMesh> mesh,
               const std::string& mesh_path);
    bool running() const { return running_; }
    /// What failed() says when the user cancelled.
    static QString cancelledMessage();

  signals:
    void finished(const QString& path);
    /// The export ended without a file: @p message says why
    /// (cancelledMessage() when the user cancelled).
    void failed(const QString& message);

  private:
    bool running_ = false;
    std::shared_ptr<std::atomic<bool>> cancel_ = std::make_shared<std::atomic<bool>>(false);
    QFuture<QString> future_;
};

} // namespace snaxels::ui
