// MainWindow, continued: its menus.
#include "ui/mainwindow.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QRegularExpression>
#include <QInputDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTextBrowser>
#include <QUndoStack>
#include <QUrl>

#include "snaxels/util/atomic_file.h"
#include "snaxels/version.h"
#include "ui/document.h"
#include "ui/meshview.h"
#include "ui/parabolic_search.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"
#include "ui/svgpane.h"
#include "ui/timeline.h"

namespace snaxels::ui {
namespace {

constexpr int kMaxRecent = 8;

/// View > Up Axis, in menu order.
const std::pair<const char*, glm::dvec3> kUpAxes[] = {{"+X", {1, 0, 0}}, {"-X", {-1, 0, 0}}, {"+Y", {0, 1, 0}},
                                                      {"-Y", {0, -1, 0}}, {"+Z", {0, 0, 1}}, {"-Z", {0, 0, -1}}};

} // namespace

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open Mesh or Project"), QSettings().value("paths/lastDir").toString(),
            tr("Meshes and projects (*.obj *.ply *.stl *.off *.gltf *.glb *.fbx *.dae *.3ds *.x *.blend *.snaxels);;"
               "Projects (*.snaxels);;All files (*)"));
        if (path.isEmpty()) return;
        QSettings().setValue("paths/lastDir", QFileInfo(path).absolutePath());
        openFile(path);
    });
    open->setShortcut(QKeySequence::Open);
    file->addAction(tr("Open Mesh &Sequence…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open Mesh Sequence (choose any of its numbered files)"), QSettings().value("paths/lastDir").toString(),
            tr("Meshes (*.obj *.ply *.stl *.off);;All files (*)"));
        if (path.isEmpty()) return;
        QSettings().setValue("paths/lastDir", QFileInfo(path).absolutePath());
        openSequence(path);
    });
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addSeparator();
    QAction* save = file->addAction(tr("&Save Project"), this, [this] { saveProjectInteractive(false); });
    save->setShortcut(QKeySequence::Save);
    QAction* saveAs = file->addAction(tr("Save Project &As…"), this, [this] { saveProjectInteractive(true); });
    saveAs->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    // Typing the style editor has not applied yet becomes a step first, so
    // Undo takes back the latest typing rather than the step before it.
    QUndoStack* stack = document_->undoStack();
    QAction* undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    disconnect(undo, &QAction::triggered, stack, &QUndoStack::undo);
    connect(undo, &QAction::triggered, this, [this, stack] {
        styleEditor_->applyPending();
        stack->undo();
    });
    QAction* redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    disconnect(redo, &QAction::triggered, stack, &QUndoStack::redo);
    connect(redo, &QAction::triggered, this, [this, stack] {
        styleEditor_->applyPending();
        stack->redo();
    });
    edit->addAction(undo);
    edit->addAction(redo);

    createStyleMenu();

    createExportMenu();

    QMenu* playMenu = menuBar()->addMenu(tr("&Play"));
    QAction* play = playMenu->addAction(tr("Play / Pause"), timeline_, &Timeline::togglePlay);
    play->setShortcut(Qt::Key_Space);
    QAction* next = playMenu->addAction(tr("Next Frame"), this, [this] { timeline_->step(1); });
    next->setShortcut(Qt::Key_Right);
    QAction* previous = playMenu->addAction(tr("Previous Frame"), this, [this] { timeline_->step(-1); });
    previous->setShortcut(Qt::Key_Left);

    createViewMenu();
    createHelpMenu();
}

void MainWindow::createExportMenu() {
    QMenu* exportMenu = menuBar()->addMenu(tr("&Export"));
    QAction* exportAnim = exportMenu->addAction(tr("&Animated SVG…"), this, [this] {
        const QString path = askSavePath(tr("Export Animated SVG"), kExportFolder, ".svg",
                                         tr("SVG (*.svg);;Compressed SVG (*.svgz)"));
        if (!path.isEmpty()) exportAnimation(path);
    });
    exportAnim->setObjectName("exportAnimatedSvg");
    exportAnim->setShortcut(QKeySequence(tr("Ctrl+E")));
    QAction* exportLottie = exportMenu->addAction(tr("&Lottie…"), this, [this] {
        const QString path = askSavePath(tr("Export Lottie"), kExportFolder, ".json",
                                         tr("Lottie JSON (*.json);;dotLottie (*.lottie)"));
        if (!path.isEmpty()) exportAnimation(path);
    });
    exportLottie->setObjectName("exportLottie");
    exportLottie->setShortcut(QKeySequence(tr("Ctrl+Alt+E")));
    QAction* exportVideo = exportMenu->addAction(tr("&Video…"), this, [this] {
        const QString path = askSavePath(tr("Export Video"), kExportFolder, ".mp4",
                                         tr("MP4 video (*.mp4);;WebM video (*.webm);;Animated GIF (*.gif)"));
        if (!path.isEmpty()) exportAnimation(path);
    });
    exportVideo->setObjectName("exportVideo");
    exportVideo->setToolTip(tr("The animation's frames rendered and encoded by FFmpeg, at the canvas size and the frame rate"));
    QAction* exportStill = exportMenu->addAction(tr("Current &Frame as SVG…"), this, [this] {
        const QString path = askSavePath(tr("Export Frame"), kExportFolder, ".svg", tr("SVG (*.svg)"));
        if (!path.isEmpty()) exportFrame(path);
    });
    exportStill->setObjectName("exportFrame");
    exportStill->setShortcut(QKeySequence(tr("Ctrl+Shift+E")));
    QAction* exportPdf = exportMenu->addAction(tr("Current Frame as &PDF…"), this, [this] {
        const QString path = askSavePath(tr("Export Frame as PDF"), kExportFolder, ".pdf", tr("PDF (*.pdf)"));
        if (!path.isEmpty()) exportFrame(path);
    });
    exportPdf->setObjectName("exportFramePdf");
    exportPdf->setToolTip(tr("The drawing as vector PDF for print: its lines and fills stay paths"));
}

void MainWindow::createViewMenu() {
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    QAction* reset = viewMenu->addAction(tr("&Reset Camera"), view_, &MeshView::resetCamera);
    reset->setShortcut(Qt::Key_Home);
    reset->setToolTip(tr("Look at the model's front from a little above and to the side"));
    // Named views in the model's frame (its up axis and front), keeping the
    // distance and pan: one undo step each.
    const std::pair<QString, ViewPreset> presets[] = {{tr("&Front"), ViewPreset::Front},
                                                      {tr("&Back"), ViewPreset::Back},
                                                      {tr("&Left"), ViewPreset::Left},
                                                      {tr("Ri&ght"), ViewPreset::Right},
                                                      {tr("&Top"), ViewPreset::Top}};
    const char* presetNames[] = {"viewFront", "viewBack", "viewLeft", "viewRight", "viewTop"};
    for (int i = 0; i < 5; ++i) {
        const ViewPreset preset = presets[i].second;
        const QString step = tr("%1 View").arg(QString(presets[i].first).remove('&'));
        QAction* a = viewMenu->addAction(presets[i].first, this, [this, preset, step] {
            if (scene_) document_->setView(preset_view(viewState(), preset), step);
        });
        a->setObjectName(presetNames[i]);
        a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_1 + i)));
    }
    QMenu* upMenu = viewMenu->addMenu(tr("&Up Axis"));
    upMenu->setObjectName("upAxisMenu");
    upMenu->setToolTip(tr("The model's up axis: FBX and Collada files are turned upright on import; "
                          "OBJ, PLY and STL files stand on +Y unless you say otherwise (+Z for most scans)"));
    auto* ups = new QActionGroup(upMenu);
    ups->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional); // a project's own axis may be none of these
    for (const auto& [name, axis] : kUpAxes) {
        QAction* a = upMenu->addAction(QString::fromLatin1(name).replace('-', QChar(0x2212)));
        a->setObjectName(QStringLiteral("up") + QString::fromLatin1(name).replace('+', 'P').replace('-', 'M'));
        a->setCheckable(true);
        ups->addAction(a);
        connect(a, &QAction::triggered, this, [this, name = name, axis = axis] {
            OrbitView v = viewState();
            if (!scene_ || v.up == axis) return;
            // The old yaw and pitch meant the old frame: look at the front again.
            v.up = axis;
            v.yaw = kDefaultYaw;
            v.pitch = kDefaultPitch;
            document_->setView(v, tr("Up Axis %1").arg(QString::fromLatin1(name)));
        });
    }
    auto showUp = [this, ups] {
        const glm::dvec3 up = glm::normalize(view_->orbit().up);
        const QList<QAction*> list = ups->actions();
        for (int i = 0; i < list.size(); ++i) list[i]->setChecked(glm::length(up - kUpAxes[i].second) < 1e-9);
    };
    connect(view_, &MeshView::cameraChanged, upMenu, showUp);
    showUp();
    viewMenu->addAction(tr("Reset &Light"), this, [this] {
        // Back to the style's light (or the default); one undo step.
        if (!light_) return;
        light_.reset();
        scheduleContours();
        emit view_->lightEdited();
    });
    regionsAction_ = viewMenu->addAction(tr("&Colour Regions"));
    regionsAction_->setCheckable(true);
    regionsAction_->setShortcut(QKeySequence(tr("Ctrl+R")));
    regionsAction_->setToolTip(tr("Colour the surface by planar-map region: shadow, lit, isophote bands, highlights"));
    regionsAction_->setChecked(QSettings().value("view/regions", false).toBool());
    connect(regionsAction_, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/regions", on);
        RegionShading shading = view_->regionShading();
        shading.enabled = on;
        view_->setRegionShading(std::move(shading));
    });
    parabolicAction_ = viewMenu->addAction(tr("&Parabolic Curves"));
    parabolicAction_->setObjectName("parabolicCurves");
    parabolicAction_->setCheckable(true);
    parabolicAction_->setShortcut(QKeySequence(tr("Ctrl+Shift+P")));
    parabolicAction_->setToolTip(tr("Draw the mesh's parabolic curves, where it turns from dome- to saddle-shaped "
                                    "(found once per mesh from visual events over all views)"));
    parabolicAction_->setChecked(QSettings().value("view/parabolic", false).toBool());
    connect(parabolicAction_, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("view/parabolic", on);
        parabolic_->ensure();
        scheduleContours();
    });
    viewMenu->addAction(tr("&Fit SVG Pane"), svgPane_, &SvgPane::fit);
    viewMenu->addSeparator();
    // Every dock can be closed and brought back from here.
    for (QDockWidget* dock : findChildren<QDockWidget*>()) viewMenu->addAction(dock->toggleViewAction());
}

void MainWindow::createHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* reference = help->addAction(tr("&Style Reference"), this, [this] { showDocument("styles.md", tr("Style Reference")); });
    reference->setObjectName("helpStyleReference");
    reference->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("The &Application"), this, [this] { showDocument("app.md", tr("The Application")); });
    QAction* keys = help->addAction(tr("&Keyboard Shortcuts"), this, [this] {
        // Read from the menus themselves, so the list is always the truth.
        QString text = "<table>";
        for (QAction* menu : menuBar()->actions())
            for (QAction* a : menu->menu() ? menu->menu()->actions() : QList<QAction*>{})
                if (!a->shortcut().isEmpty())
                    text += QString("<tr><td>%1</td><td>&nbsp;&nbsp;<b>%2</b></td></tr>")
                                .arg(QString(a->text()).remove('&'), a->shortcut().toString(QKeySequence::NativeText));
        text += tr("</table><p>In the 3-D view: drag to orbit, Shift+drag to turn the light, right or middle "
                   "drag to pan, the wheel to zoom. In the SVG pane: the wheel zooms, a drag pans, a double "
                   "click fits.</p>");
        QMessageBox box(QMessageBox::NoIcon, tr("Keyboard Shortcuts"), text, QMessageBox::Ok, this);
        box.setObjectName("shortcutsBox");
        box.exec();
    });
    keys->setObjectName("helpShortcuts");
    help->addSeparator();
    help->addAction(tr("&About snaxels"), this, [this] {
        QMessageBox::about(this, tr("About snaxels"),
                           tr("<p><b>snaxels %1</b></p><p>Vector line art from 3-D meshes, after \"Snaxels on a "
                              "Plane\" (Karsch and Hart, NPAR 2011).</p><p>MIT licence (the LICENSE file, which "
                              "also lists the licences of the libraries it uses: Qt under the LGPL 3, Assimp, "
                              "OpenMesh, Embree, oneTBB, Clipper, pugixml, nlohmann/json, GLM).</p>"
                              "<p>Documentation: %2</p>")
                               .arg(QString::fromLatin1(snaxels::version), QDir::toNativeSeparators(docsDirectory())));
    });
}

void MainWindow::showDocument(const QString& name, const QString& title) {
    const QString path = QDir(docsDirectory()).filePath(name);
    if (!QFileInfo::exists(path)) {
        warn(title, tr("%1 is not installed (looked in %2)").arg(name, QDir::toNativeSeparators(docsDirectory())));
        return;
    }
    auto* browser = new QTextBrowser;
    browser->setAttribute(Qt::WA_DeleteOnClose);
    browser->setWindowTitle(tr("%1 — snaxels").arg(title));
    browser->setObjectName("helpBrowser");
    browser->setOpenExternalLinks(true);
    browser->setSource(QUrl::fromLocalFile(path), QTextDocument::MarkdownResource);
    browser->resize(760, 820);
    browser->show();
}

void MainWindow::createStyleMenu() {
    QMenu* menu = menuBar()->addMenu(tr("&Style"));
    QMenu* presets = menu->addMenu(tr("&Presets"));
    presets->addAction(tr("Default"), this, [this] { styleEditor_->setText(initial_style_text(), "default"); })
        ->setToolTip(tr("The style a new window starts with: an ink outline with dashed hidden lines, and the shadow line"));
    presets->addSeparator();
    const QDir dir(dataDirectory() + "/styles");
    for (const QFileInfo& file : dir.entryInfoList({"*.xml"}, QDir::Files, QDir::Name))
        presets->addAction(file.completeBaseName(), this, [this, path = file.absoluteFilePath()] {
            QFile in(path);
            if (!in.open(QIODevice::ReadOnly)) {
                statusBar()->showMessage(tr("Cannot read %1").arg(path), 6000);
                return;
            }
            styleEditor_->setText(QString::fromUtf8(in.readAll()), path);
        });
    presets->setEnabled(!presets->isEmpty());
    menu->addAction(tr("S&harp Edges…"), this, &MainWindow::askSharpEdges)
        ->setToolTip(tr("Where the surface's edges are hard: from the file's normals, or by the angle its faces meet at"));
    menu->addAction(tr("&Load Style…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load Style"), QSettings().value(kStyleFolder).toString(),
                                                          tr("Styles (*.xml)"));
        if (path.isEmpty()) return;
        QSettings().setValue(kStyleFolder, QFileInfo(path).absolutePath());
        QFile in(path);
        if (!in.open(QIODevice::ReadOnly)) {
            QMessageBox::warning(this, tr("Load Style"), tr("Cannot read %1: %2").arg(path, in.errorString()));
            return;
        }
        styleEditor_->setText(QString::fromUtf8(in.readAll()), path);
    });
    menu->addAction(tr("&Save Style As…"), this, [this] {
        const QString path = askSavePath(tr("Save Style"), kStyleFolder, ".xml", tr("Styles (*.xml)"));
        if (path.isEmpty()) return;
        try {
            write_file_atomically(path.toStdString(), styleEditor_->text().toStdString());
            statusBar()->showMessage(tr("Saved %1").arg(path), 4000);
        } catch (const std::exception& e) {
            QMessageBox::warning(this, tr("Save Style"), QString::fromStdString(e.what()));
        }
    });
}

void MainWindow::askSharpEdges() {
    const QString file = tr("From the file's normals (default)"), smooth = tr("None: smooth everywhere");
    const QStringList choices{file, tr("20°"), tr("30° (Blender's Auto Smooth)"), tr("45°"), tr("60°"), smooth};
    const Style& style = document_->style();
    const double now = style.surface.sharp_angle;
    const int current = now < 0.0 ? 0 : now >= 180.0 ? int(choices.size()) - 1 : -1;
    bool ok = false;
    QString chosen = QInputDialog::getItem(
        this, tr("Sharp Edges"),
        tr("Edges shaded hard, with contours running along them.\nChoose, or type an angle in degrees (0 to 180):"),
        current >= 0 ? choices : QStringList(choices) << QString::number(now), current >= 0 ? current : int(choices.size()),
        true, &ok);
    if (!ok) return;
    chosen = chosen.trimmed();
    QString value;
    if (chosen == file) value = "file";
    else if (chosen == smooth) value = "180";
    else {
        static const QRegularExpression degrees(QStringLiteral("^\\s*([0-9]+(\\.[0-9]*)?)\\s*°?"));
        // A number first (the choices say what it is after it), 0 to 180.
        const QRegularExpressionMatch m = degrees.match(chosen);
        bool number = false;
        const double angle = m.hasMatch() ? m.captured(1).toDouble(&number) : -1.0;
        if (!number || angle < 0.0 || angle > 180.0) {
            QMessageBox::warning(this, tr("Sharp Edges"), tr("'%1' is not an angle from 0 to 180 degrees.").arg(chosen));
            return;
        }
        value = QString::number(angle);
    }
    styleEditor_->setSharpAngle(value);
}

QString MainWindow::suggestedPath(const char* folder_key, const QString& extension) const {
    // The folder last used for this kind of file, else the mesh's, else home;
    // the name, the mesh's.
    const QString spec = document_->meshSpec();
    const bool file = !spec.isEmpty() && !spec.startsWith("proc:");
    QString folder = QSettings().value(folder_key).toString();
    if (folder.isEmpty() || !QFileInfo(folder).isDir()) folder = file ? QFileInfo(spec).absolutePath() : QDir::homePath();
    const QString name = file ? QFileInfo(spec).completeBaseName() : spec.isEmpty() ? tr("untitled") : spec.section(':', 1, 1);
    return QDir(folder).filePath(name + extension);
}

QString MainWindow::askSavePath(const QString& title, const char* folder_key, const QString& extension,
                                const QString& filter) {
    QString chosen_filter;
    QString path = QFileDialog::getSaveFileName(this, title, suggestedPath(folder_key, extension), filter, &chosen_filter);
    if (path.isEmpty()) return path;
    if (QFileInfo(path).suffix().isEmpty()) {
        // The extension of the filter chosen ("Compressed SVG (*.svgz)"), else the first one.
        const qsizetype star = chosen_filter.indexOf("(*");
        const qsizetype close = chosen_filter.indexOf(')', star);
        path += star >= 0 && close > star ? chosen_filter.mid(star + 2, close - star - 2) : extension;
    }
    QSettings().setValue(folder_key, QFileInfo(path).absolutePath());
    return path;
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue("recentFiles", recent);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent)
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openFile(path); })
            ->setToolTip(path);
    recentMenu_->setEnabled(!recent.isEmpty());
}

} // namespace snaxels::ui
