#include "ui/export_actions.h"

#include <QAction>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

#include <cmath>
#include <QDesktopServices>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolButton>
#include <QUrl>

#include "snaxels/export/raster.h"
#include "snaxels/export/video.h"
#include "snaxels/style/style_edit.h"
#include "snaxels/util/atomic_file.h"
#include "ui/animation_export.h"
#include "ui/document.h"
#include "ui/document_controller.h"
#include "ui/page_setup.h"
#include "ui/preferences.h"

namespace snaxels::ui {

QString first_writable_folder(const QStringList& folders) {
    for (const QString& folder : folders) {
        const QFileInfo info(folder);
        if (!folder.isEmpty() && info.isDir() && info.isWritable()) return info.absoluteFilePath();
    }
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return QFileInfo(documents).isDir() && QFileInfo(documents).isWritable() ? documents : QDir::homePath();
}

QString suggested_save_path(const QString& meshSpec, const char* folderKey, const QString& extension,
                            const QString& projectPath) {
    const bool file = !meshSpec.isEmpty() && !meshSpec.startsWith("proc:");
    const QSettings settings;
    const QString preferred = QString(folderKey) == kExportFolder ? settings.value(kPrefExportFolder).toString() : QString();
    const QString folder = first_writable_folder({preferred, settings.value(folderKey).toString(),
                                                  projectPath.isEmpty() ? QString() : QFileInfo(projectPath).absolutePath(),
                                                  file ? QFileInfo(meshSpec).absolutePath() : QString()});
    const QString name = file               ? QFileInfo(meshSpec).completeBaseName()
                         : meshSpec.isEmpty() ? QObject::tr("untitled")
                                              : meshSpec.section(':', 1, 1);
    return QDir(folder).filePath(name + extension);
}

QString ask_save_path(QWidget* parent, const QString& meshSpec, const QString& title, const char* folderKey,
                      const QString& extension, const QString& filter, const QString& projectPath) {
    QString chosen_filter;
    QString path = QFileDialog::getSaveFileName(parent, title, suggested_save_path(meshSpec, folderKey, extension, projectPath),
                                                filter, &chosen_filter);
    if (path.isEmpty()) return path;
    if (QFileInfo(path).suffix().isEmpty()) {
        // The extension of the filter chosen ("Compressed SVG (*.svgz)"), else the first one.
        const qsizetype star = chosen_filter.indexOf("(*");
        const qsizetype close = chosen_filter.indexOf(')', star);
        path += star >= 0 && close > star ? chosen_filter.mid(star + 2, close - star - 2) : extension;
    }
    QSettings().setValue(folderKey, QFileInfo(path).absolutePath());
    return path;
}

ExportActions::ExportActions(Document* document, DocumentController* controller, QMainWindow* window)
    : QObject(window), document_(document), controller_(controller), window_(window),
      export_(new AnimationExport(this)), reveal_(new QToolButton(window)) {
    reveal_->setObjectName("revealExport");
    reveal_->setText(tr("Reveal in Folder"));
    reveal_->setAutoRaise(true);
    reveal_->hide(); // until something is exported
    connect(reveal_, &QToolButton::clicked, this, [this] {
        QDesktopServices::openUrl(QUrl::fromLocalFile(reveal_->property("folder").toString()));
    });
    window_->statusBar()->addPermanentWidget(reveal_);
    connect(export_, &AnimationExport::finished, this, [this](const QString& path) {
        reportExported(path);
        emit finished(path);
    });
    connect(export_, &AnimationExport::failed, this, [this](const QString& error) {
        if (error != AnimationExport::cancelledMessage()) return refuse(error);
        window_->statusBar()->showMessage(error, 8000); // a cancel the user asked for: no box
        emit failed(error);
    });
}

bool ExportActions::running() const { return export_->running(); }

void ExportActions::setFrame(QByteArray svg, QString problem) {
    svg_ = std::move(svg);
    problem_ = std::move(problem);
}

void ExportActions::addMenu() {
    QMenu* menu = window_->menuBar()->addMenu(tr("&Export"));
    struct Entry {
        QString text, title, extension, filter, name, shortcut, tip;
        bool frame;
    };
    const Entry entries[] = {
        {tr("&Animated SVG…"), tr("Export Animated SVG"), ".svg", tr("SVG (*.svg);;Compressed SVG (*.svgz)"),
         "exportAnimatedSvg", tr("Ctrl+E"), {}, false},
        {tr("&Lottie…"), tr("Export Lottie"), ".json", tr("Lottie JSON (*.json);;dotLottie (*.lottie)"), "exportLottie",
         tr("Ctrl+Alt+E"), {}, false},
        {tr("&Video…"), tr("Export Video"), ".mp4", tr("MP4 video (*.mp4);;WebM video (*.webm);;Animated GIF (*.gif)"),
         "exportVideo", {}, tr("The animation's frames rendered and encoded by FFmpeg, at the canvas size and the frame rate"),
         false},
        {tr("Current &Frame as SVG…"), tr("Export Frame"), ".svg", tr("SVG (*.svg)"), "exportFrame", tr("Ctrl+Shift+E"),
         {}, true},
        {tr("Current Frame as &PDF…"), tr("Export Frame as PDF"), ".pdf", tr("PDF (*.pdf)"), "exportFramePdf", {},
         tr("The drawing as vector PDF for print: its lines and fills stay paths"), true},
    };
    for (const Entry& e : entries) {
        QAction* a = menu->addAction(e.text, this, [this, e] { askAndExport(e.title, e.extension, e.filter, e.frame); });
        a->setObjectName(e.name);
        if (!e.shortcut.isEmpty()) a->setShortcut(QKeySequence(e.shortcut));
        if (!e.tip.isEmpty()) a->setToolTip(e.tip);
    }
    menu->addSeparator();
    QAction* page = menu->addAction(tr("Page &Setup…"), this, &ExportActions::askPageSetup);
    page->setObjectName("pageSetup");
    page->setToolTip(tr("The paper the drawing is made for: its size, orientation, margin, and fit, fill or scale"));
}

void ExportActions::askPageSetup() {
    controller_->flush();
    PageSetupDialog dialog(document_->style(), window_);
    if (dialog.exec() != QDialog::Accepted) return;
    const auto text = with_canvas(document_->styleText().toStdString(), dialog.attributes());
    if (!text) {
        QMessageBox::warning(window_, tr("Page Setup"),
                             tr("The style's text does not parse: fix it in the style editor first, then set the page."));
        return;
    }
    try { // a margin too wide for the paper, say: said, and nothing changes
        parse_style(*text, "page", nullptr);
    } catch (const std::exception& e) {
        QMessageBox::warning(window_, tr("Page Setup"), tr("This page cannot be drawn on: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    document_->setStyleText(QString::fromStdString(*text), tr("Page Setup"));
}

void ExportActions::askAndExport(const QString& title, const QString& extension, const QString& filter, bool frame) {
    const QString path =
        ask_save_path(window_, document_->meshSpec(), title, kExportFolder, extension, filter, document_->projectPath());
    if (path.isEmpty()) return;
    if (frame) exportFrame(path);
    else if (!is_video(output_kind_for(path.toStdString()).value_or(OutputKind::Svg)) || askVideoSettings(path))
        exportAnimation(path);
}

bool ExportActions::askVideoSettings(const QString& path) {
    QDialog dialog(window_);
    dialog.setObjectName("videoSettings");
    dialog.setWindowTitle(tr("Video Settings"));
    auto* form = new QFormLayout(&dialog);
    const int canvas = document_->style().width, tall = document_->style().height;
    auto* width = new QComboBox(&dialog);
    width->setObjectName("videoWidth");
    width->addItem(tr("The canvas: %1 x %2").arg(canvas).arg(tall), 0);
    for (const int w : {640, 1280, 1920, 3840})
        width->addItem(tr("%1 x %2").arg(w).arg(std::max(1, int(std::lround(double(tall) * w / std::max(canvas, 1))))), w);
    width->setCurrentIndex(std::max(0, width->findData(QSettings().value(kVideoWidth, 0).toInt())));
    form->addRow(tr("Size:"), width);
    const bool gif = QFileInfo(path).suffix().compare("gif", Qt::CaseInsensitive) == 0;
    auto* quality = new QSpinBox(&dialog);
    quality->setObjectName("videoCrf");
    quality->setRange(0, 51);
    quality->setValue(QSettings().value(kVideoCrf, kDefaultMp4Crf).toInt());
    quality->setToolTip(tr("FFmpeg's constant rate factor: lower is better and bigger (18 is visually lossless "
                           "for line art; 28 is half the size or less)"));
    quality->setEnabled(!gif); // a GIF's palette has no such setting
    form->addRow(tr("Quality (CRF):"), quality);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted) return false;
    QSettings().setValue(kVideoWidth, width->currentData().toInt());
    if (!gif) QSettings().setValue(kVideoCrf, quality->value());
    return true;
}

void ExportActions::reportExported(const QString& path) {
    const QFileInfo file(path);
    QSettings().setValue(kExportFolder, file.absolutePath()); // the next export's dialog starts there
    window_->statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(file.absoluteFilePath())), 15000);
    reveal_->setToolTip(tr("Show %1 in its folder").arg(QDir::toNativeSeparators(file.absolutePath())));
    reveal_->setProperty("folder", file.absolutePath());
    reveal_->show();
}

bool ExportActions::exportFrame(const QString& path) {
    if (svg_.isEmpty()) { // the first drawing has not come yet (a mesh still loading), or cannot be made: nothing is written
        const QString message =
            !problem_.isEmpty() ? problem_ : tr("Nothing to export yet: the first frame is still being drawn.");
        QMessageBox::warning(window_, tr("Export Frame"), message);
        emit failed(message);
        return false;
    }
    try {
        if (QFileInfo(path).suffix().compare("pdf", Qt::CaseInsensitive) == 0) write_pdf(path.toStdString(), svg_.toStdString());
        else write_file_atomically(path.toStdString(), svg_.toStdString());
        reportExported(path);
        emit finished(path);
        return true;
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        QMessageBox::warning(window_, tr("Export Frame"), message);
        emit failed(message);
        return false;
    }
}

void ExportActions::refuse(const QString& problem) {
    window_->statusBar()->showMessage(problem, 8000);
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Export Animation"),
                                tr("The animation was not exported: %1").arg(problem), QMessageBox::Ok, window_);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    emit failed(problem);
}

void ExportActions::exportAnimation(const QString& path) {
    if (!document_->mesh() || export_->running()) return;
    controller_->flush(); // the export writes the document, typing taken up
    AnimationJob job = document_->animationJob();
    if (!set_output(job, path.toStdString()))
        return refuse(tr("Cannot write %1: the file's extension must be one of %2.")
                          .arg(QFileInfo(path).fileName(), QString::fromStdString(output_extensions())));
    if (!job.video.empty()) {
        try {
            require_ffmpeg();
        } catch (const std::exception& e) {
            return refuse(QString::fromStdString(e.what())); // said before any work, as an export's failure is
        }
    }
    if (!job.video.empty()) { // the video settings last chosen
        job.video_width = QSettings().value(kVideoWidth, 0).toInt();
        job.video_crf = QSettings().value(kVideoCrf, -1).toInt();
    }
    export_->start(window_, path, std::move(job), document_->mesh(), document_->meshSpec().toStdString());
}

} // namespace snaxels::ui
