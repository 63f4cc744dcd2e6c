#include "ui/animation_export.h"

#include <QApplication>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QtConcurrent/QtConcurrentRun>

namespace snaxels::ui {

AnimationExport::AnimationExport(QObject* parent) : QObject(parent) {}

AnimationExport::~AnimationExport() {
    *cancel_ = true; // an export still running stops at its next frame
    future_.waitForFinished();
}

QString AnimationExport::cancelledMessage() { return tr("Export cancelled; nothing was written"); }

bool AnimationExport::start(QWidget* window, const QString& path, AnimationJob job,
                            std::shared_ptr<const LoadedMesh> mesh, const std::string& mesh_path) {
    if (running_ || !mesh) return false;
    running_ = true;
    const QString name = QFileInfo(path).fileName();
    auto* dialog = new QProgressDialog(tr("Exporting %1…").arg(name), tr("Cancel"), 0, job.animation.frames, window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(300);
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    auto cancelled = cancel_;
    connect(dialog, &QProgressDialog::canceled, this, [cancelled] { *cancelled = true; });
    QPointer<QProgressDialog> guard(dialog);
    job.progress = [guard](int done, int) {
        QMetaObject::invokeMethod(qApp, [guard, done] {
            if (guard) guard->setValue(done);
        }, Qt::QueuedConnection);
    };
    // A style with parabolic curves the view has not found yet: the dialog
    // shows that search first, then the frames.
    job.parabolic_progress = [guard, name, frames = job.animation.frames](int done, int total) {
        QMetaObject::invokeMethod(qApp, [guard, done, total, name, frames] {
            if (!guard) return;
            if (done < total) {
                guard->setLabelText(tr("Finding the parabolic curves for %1…").arg(name));
                guard->setRange(0, total);
                guard->setValue(done);
            } else {
                guard->setLabelText(tr("Exporting %1…").arg(name));
                guard->setRange(0, frames);
                guard->setValue(0);
            }
        }, Qt::QueuedConnection);
    };
    job.cancelled = [cancelled] { return cancelled->load(); };
    auto* watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcher<QString>::finished, this, [this, watcher, guard, path] {
        const QString error = watcher->result();
        watcher->deleteLater();
        if (guard) guard->close();
        running_ = false;
        if (error.isEmpty()) emit finished(path);
        else emit failed(error);
    });
    future_ = QtConcurrent::run([mesh, mesh_path, job]() -> QString {
        try {
            run_animation(*mesh, mesh_path, job);
            return {};
        } catch (const AnimationCancelled&) {
            return cancelledMessage();
        } catch (const InternalError& e) {
            return QObject::tr("internal error: %1").arg(QString::fromStdString(e.what()));
        } catch (const std::exception& e) {
            return QString::fromStdString(e.what());
        }
    });
    watcher->setFuture(future_);
    return true;
}

} // namespace snaxels::ui
