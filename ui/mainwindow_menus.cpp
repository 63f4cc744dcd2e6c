// MainWindow, continued: its File, Edit, Play and View menus (Export is
// ExportActions', Style and Help window_menus').
#include "ui/mainwindow.h"

#include <QAction>
#include <QActionGroup>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QSettings>
#include <QUndoStack>

#include "ui/document.h"
#include "ui/document_controller.h"
#include "ui/export_actions.h"
#include "ui/meshview.h"
#include "ui/parabolic_search.h"
#include "ui/styleeditor.h"
#include "ui/svgpane.h"
#include "ui/timeline.h"
#include "ui/window_menus.h"

namespace snaxels::ui {
namespace {

/// View > Up Axis, in menu order.
const std::pair<const char*, glm::dvec3> kUpAxes[] = {{"+X", {1, 0, 0}}, {"-X", {-1, 0, 0}}, {"+Y", {0, 1, 0}},
                                                      {"-Y", {0, -1, 0}}, {"+Z", {0, 0, 1}}, {"-Z", {0, 0, -1}}};

} // namespace

void MainWindow::createMenus() {
    createFileMenu();
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    // Typing the style editor has not applied yet becomes a step first, so
    // Undo takes back the latest typing rather than the step before it.
    QUndoStack* stack = document_->undoStack();
    QAction* undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    disconnect(undo, &QAction::triggered, stack, &QUndoStack::undo);
    connect(undo, &QAction::triggered, this, [this, stack] {
        controller_->flush();
        stack->undo();
    });
    QAction* redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    disconnect(redo, &QAction::triggered, stack, &QUndoStack::redo);
    connect(redo, &QAction::triggered, this, [this, stack] {
        controller_->flush();
        stack->redo();
    });
    edit->addAction(undo);
    edit->addAction(redo);
    add_preferences_action(edit, this);
    add_style_menu(this, document_, styleEditor_);
    exports_->addMenu();
    QMenu* playMenu = menuBar()->addMenu(tr("&Play"));
    QAction* play = playMenu->addAction(tr("Play / Pause"), timeline_, &Timeline::togglePlay);
    play->setShortcut(Qt::Key_Space);
    QAction* next = playMenu->addAction(tr("Next Frame"), this, [this] { timeline_->step(1); });
    next->setShortcut(Qt::Key_Right);
    QAction* previous = playMenu->addAction(tr("Previous Frame"), this, [this] { timeline_->step(-1); });
    previous->setShortcut(Qt::Key_Left);
    createViewMenu();
    add_help_menu(this);
}

void MainWindow::createFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* fresh = file->addAction(tr("&New"), controller_, &DocumentController::newDocument);
    fresh->setShortcut(QKeySequence::New);
    fresh->setObjectName("newDocument");
    fresh->setToolTip(tr("A new untitled document on the default scene, with the default style"));
    auto ask = [this](const QString& title, const QString& filter) {
        const QString path = QFileDialog::getOpenFileName(this, title, QSettings().value("paths/lastDir").toString(), filter);
        if (!path.isEmpty()) QSettings().setValue("paths/lastDir", QFileInfo(path).absolutePath());
        return path;
    };
    QAction* open = file->addAction(tr("&Open…"), this, [this, ask] {
        const QString path = ask(tr("Open Mesh or Project"),
                                 tr("Meshes and projects (*.obj *.ply *.stl *.off *.gltf *.glb *.fbx *.dae *.3ds *.x "
                                    "*.blend *.snaxels);;Projects (*.snaxels);;All files (*)"));
        if (!path.isEmpty()) controller_->openFile(path);
    });
    open->setShortcut(QKeySequence::Open);
    file->addAction(tr("Open Mesh &Sequence…"), this, [this, ask] {
        const QString path = ask(tr("Open Mesh Sequence (choose any of its numbered files)"),
                                 tr("Meshes (*.obj *.ply *.stl *.off);;All files (*)"));
        if (!path.isEmpty()) controller_->openSequence(path);
    });
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    connect(controller_, &DocumentController::recentFilesChanged, this, &MainWindow::rebuildRecentMenu);
    file->addSeparator();
    QAction* save = file->addAction(tr("&Save Project"), this, [this] { controller_->saveInteractive(false); });
    save->setShortcut(QKeySequence::Save);
    QAction* saveAs = file->addAction(tr("Save Project &As…"), this, [this] { controller_->saveInteractive(true); });
    // The platform's Save As key, which some platforms leave without one.
    saveAs->setShortcut(QKeySequence(QKeySequence::SaveAs).isEmpty() ? QKeySequence(tr("Ctrl+Shift+S"))
                                                                     : QKeySequence(QKeySequence::SaveAs));
    QAction* revert = file->addAction(tr("Re&vert"), controller_, &DocumentController::revert);
    revert->setObjectName("revert");
    revert->setToolTip(tr("Read the project (or the mesh) again from its file, losing the changes since"));
    QAction* close = file->addAction(tr("&Close"), controller_, &DocumentController::closeDocument);
    close->setShortcut(QKeySequence::Close);
    close->setObjectName("closeDocument");
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
}

void MainWindow::createViewMenu() {
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    QAction* reset = viewMenu->addAction(tr("&Reset Camera"), view_, &MeshView::resetCamera);
    reset->setShortcut(Qt::Key_Home);
    reset->setObjectName("resetCamera");
    reset->setToolTip(tr("Look at the model's front from a little above and to the side"));
    QAction* selected = viewMenu->addAction(tr("Frame &Selected"), view_, &MeshView::frameSelected);
    selected->setShortcut(QKeySequence(tr("Shift+Home")));
    selected->setObjectName("frameSelected");
    selected->setToolTip(tr("Frame the objects selected in the Objects panel (all, with none selected)"));
    add_view_presets(viewMenu, document_);
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
            OrbitView v = document_->view();
            if (!scene_ || v.up == axis) return;
            // The old yaw and pitch meant the old frame: look at the front again.
            v.up = axis;
            v.yaw = kDefaultYaw;
            v.pitch = kDefaultPitch;
            document_->setView(v, tr("Up Axis %1").arg(QString::fromLatin1(name)));
        });
    }
    auto showUp = [this, ups] {
        const glm::dvec3 up = glm::normalize(document_->view().up);
        const QList<QAction*> list = ups->actions();
        for (int i = 0; i < list.size(); ++i) list[i]->setChecked(glm::length(up - kUpAxes[i].second) < 1e-9);
    };
    connect(document_, &Document::viewChanged, upMenu, showUp);
    showUp();
    viewMenu->addAction(tr("Reset &Light"), this, [this] { document_->setLight(std::nullopt); })
        ->setToolTip(tr("Back to the style's light (or the default)"));
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
    QAction* frame = viewMenu->addAction(tr("Camera Fra&me"), view_, &MeshView::setFrameShown);
    frame->setObjectName("cameraFrame");
    frame->setCheckable(true);
    frame->setToolTip(tr("Darken the 3-D view outside the drawing's frame, as the export and the SVG pane show it"));
    frame->setChecked(QSettings().value("view/frame", true).toBool());
    connect(frame, &QAction::toggled, this, [](bool on) { QSettings().setValue("view/frame", on); });
    view_->setFrameShown(frame->isChecked());
    viewMenu->addAction(tr("&Fit SVG Pane"), svgPane_, &SvgPane::fit);
    viewMenu->addSeparator();
    // Every dock can be closed and brought back from here.
    for (QDockWidget* dock : findChildren<QDockWidget*>()) viewMenu->addAction(dock->toggleViewAction());
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent)
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { controller_->openFile(path); })
            ->setToolTip(path);
    recentMenu_->setEnabled(!recent.isEmpty());
}

} // namespace snaxels::ui
