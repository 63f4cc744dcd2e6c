#include "ui/window_menus.h"

#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QActionGroup>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>
#include <QTextBrowser>
#include <QUrl>

#include "snaxels/style/style_edit.h"
#include "snaxels/util/atomic_file.h"
#include "snaxels/version.h"
#include "ui/document.h"
#include "ui/export_actions.h"
#include "ui/preferences.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"

namespace snaxels::ui {
namespace {

/// View > Field of View: the orbit's vertical field of view, asked for in
/// degrees with the 35 mm film focal length it equals (a 24 mm high frame).
void ask_field_of_view(QWidget* parent, Document* document) {
    OrbitView view = document->view();
    const double focal = 12.0 / std::tan(0.5 * view.fov_deg * M_PI / 180.0);
    bool ok = false;
    const double fov = QInputDialog::getDouble(
        parent, QObject::tr("Field of View"),
        QObject::tr("Vertical field of view in degrees (1 to 120); now %1° (a %2 mm lens on 35 mm film).\n"
                    "Narrow flattens the perspective, wide deepens it; the view keeps its framing.")
            .arg(view.fov_deg, 0, 'f', 1)
            .arg(focal, 0, 'f', 0),
        view.fov_deg, 1.0, 120.0, 1, &ok);
    if (!ok || fov == view.fov_deg) return;
    // The distance follows, so what the view frames at the orbited point stays.
    const double before = orbit_view_height(view);
    view.fov_deg = fov;
    view.distance *= before / orbit_view_height(view);
    document->setView(view, QObject::tr("Field of View"));
}

/// Style > Sharp Edges: the style's <surface sharp-angle>, asked for.
void ask_sharp_edges(QWidget* parent, const Document* document, StyleEditor* editor) {
    const QString file = QObject::tr("From the file's normals (default)"), smooth = QObject::tr("None: smooth everywhere");
    const QStringList choices{file, QObject::tr("20°"), QObject::tr("30° (Blender's Auto Smooth)"), QObject::tr("45°"),
                              QObject::tr("60°"), smooth};
    const double now = document->style().surface.sharp_angle;
    const int current = now < 0.0 ? 0 : now >= 180.0 ? int(choices.size()) - 1 : -1;
    bool ok = false;
    QString chosen = QInputDialog::getItem(
        parent, QObject::tr("Sharp Edges"),
        QObject::tr("Edges shaded hard, with contours running along them.\nChoose, or type an angle in degrees (0 to 180):"),
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
            QMessageBox::warning(parent, QObject::tr("Sharp Edges"),
                                 QObject::tr("'%1' is not an angle from 0 to 180 degrees.").arg(chosen));
            return;
        }
        value = QString::number(angle);
    }
    editor->setSharpAngle(value);
}

/// Shows the bundled document @p name (Markdown) in a window of its own.
void show_document(QMainWindow* window, const QString& name, const QString& title) {
    const QString path = QDir(docsDirectory()).filePath(name);
    if (!QFileInfo::exists(path)) {
        auto* box = new QMessageBox(QMessageBox::Warning, title,
                                    QObject::tr("%1 is not installed (looked in %2)").arg(name, QDir::toNativeSeparators(docsDirectory())),
                                    QMessageBox::Ok, window);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        return;
    }
    auto* browser = new QTextBrowser;
    browser->setAttribute(Qt::WA_DeleteOnClose);
    browser->setWindowTitle(QObject::tr("%1 — snaxels").arg(title));
    browser->setObjectName("helpBrowser");
    browser->setOpenExternalLinks(true);
    browser->setSource(QUrl::fromLocalFile(path), QTextDocument::MarkdownResource);
    browser->resize(760, 820);
    browser->show();
}

/// The text of the style file @p path, or, saying why in the status bar, nothing.
std::optional<QString> read_style_file(QMainWindow* window, const QString& path) {
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly)) {
        window->statusBar()->showMessage(QObject::tr("Cannot read %1: %2").arg(path, in.errorString()), 6000);
        return std::nullopt;
    }
    return QString::fromUtf8(in.readAll());
}

} // namespace

void add_style_menu(QMainWindow* window, const Document* document, StyleEditor* editor) {
    QMenu* menu = window->menuBar()->addMenu(QObject::tr("&Style"));
    QMenu* presets = menu->addMenu(QObject::tr("&Presets"));
    // A preset keeps the page the document's style is on (its paper, fit or scale).
    auto apply = [document, editor](const QString& text) {
        const auto paged = with_page_of(text.toStdString(), document->styleText().toStdString());
        editor->setText(paged ? QString::fromStdString(*paged) : text);
    };
    presets->addAction(QObject::tr("Default"), editor, [apply] { apply(initial_style_text()); })
        ->setToolTip(QObject::tr("The style a new window starts with: an ink outline with dashed hidden lines, and the shadow line"));
    presets->addSeparator();
    const QDir dir(dataDirectory() + "/styles");
    for (const QFileInfo& file : dir.entryInfoList({"*.xml"}, QDir::Files, QDir::Name))
        presets->addAction(file.completeBaseName(), editor, [window, apply, path = file.absoluteFilePath()] {
            if (const auto text = read_style_file(window, path)) apply(*text);
        });
    presets->setEnabled(!presets->isEmpty());
    menu->addAction(QObject::tr("S&harp Edges…"), editor, [window, document, editor] { ask_sharp_edges(window, document, editor); })
        ->setToolTip(QObject::tr("Where the surface's edges are hard: from the file's normals, or by the angle its faces meet at"));
    menu->addAction(QObject::tr("&Load Style…"), editor, [window, editor] {
        const QString path = QFileDialog::getOpenFileName(window, QObject::tr("Load Style"),
                                                          QSettings().value(kStyleFolder).toString(), QObject::tr("Styles (*.xml)"));
        if (path.isEmpty()) return;
        QSettings().setValue(kStyleFolder, QFileInfo(path).absolutePath());
        if (const auto text = read_style_file(window, path)) editor->setText(*text);
    });
    menu->addAction(QObject::tr("&Save Style As…"), editor, [window, document, editor] {
        editor->applyPending(); // the text as typed
        const QString path = ask_save_path(window, document->meshSpec(), QObject::tr("Save Style"), kStyleFolder, ".xml",
                                           QObject::tr("Styles (*.xml)"));
        if (path.isEmpty()) return;
        try {
            write_file_atomically(path.toStdString(), document->styleText().toStdString());
            window->statusBar()->showMessage(QObject::tr("Saved %1").arg(path), 4000);
        } catch (const std::exception& e) {
            QMessageBox::warning(window, QObject::tr("Save Style"), QString::fromStdString(e.what()));
        }
    });
}

void add_view_presets(QMenu* menu, Document* document) {
    // Named views in the model's frame (its up axis and front), keeping the
    // distance and pan: one undo step each.
    const struct {
        const char* name;
        QString label;
        const char* object;
    } presets[] = {{"front", QObject::tr("&Front"), "viewFront"},
                   {"back", QObject::tr("&Back"), "viewBack"},
                   {"left", QObject::tr("&Left"), "viewLeft"},
                   {"right", QObject::tr("Ri&ght"), "viewRight"},
                   {"top", QObject::tr("&Top"), "viewTop"},
                   {"iso", QObject::tr("&Isometric"), "viewIso"},
                   {"dimetric", QObject::tr("&Dimetric (2:1)"), "viewDimetric"},
                   {"trimetric", QObject::tr("T&rimetric"), "viewTrimetric"}};
    int key = 0;
    for (const auto& p : presets) {
        const NamedView* preset = find_named_view(p.name);
        if (preset->axonometric && key == 5) menu->addSeparator();
        const QString step = QObject::tr("%1 View").arg(QString(p.label).remove('&'));
        QAction* a = menu->addAction(p.label, document, [document, preset, step] {
            if (document->mesh()) document->setView(preset_view(document->view(), *preset), step);
        });
        a->setObjectName(p.object);
        a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_1 + key++)));
        if (preset->axonometric)
            a->setToolTip(QObject::tr("An orthographic view of technical illustration: %1").arg(preset->summary));
    }
    menu->addSeparator();
    QAction* ortho = menu->addAction(QObject::tr("&Orthographic"));
    ortho->setObjectName("orthographic");
    ortho->setCheckable(true);
    ortho->setShortcut(QKeySequence(QObject::tr("Ctrl+Shift+O")));
    ortho->setToolTip(QObject::tr("Parallel projection, as technical drawings use: no perspective, parallel edges "
                                  "stay parallel (off: perspective)"));
    QObject::connect(ortho, &QAction::triggered, document, [document](bool on) {
        OrbitView v = document->view();
        if (!document->mesh() || v.orthographic == on) return;
        v.orthographic = on;
        document->setView(v, on ? QObject::tr("Orthographic") : QObject::tr("Perspective"));
    });
    auto show = [ortho, document] { ortho->setChecked(document->view().orthographic); };
    QObject::connect(document, &Document::viewChanged, ortho, show);
    show();
    QAction* fov = menu->addAction(QObject::tr("Field of &View…"), document,
                                   [menu, document] { if (document->mesh()) ask_field_of_view(menu->parentWidget(), document); });
    fov->setObjectName("fieldOfView");
    fov->setToolTip(QObject::tr("The perspective's vertical field of view (or the lens's focal length)"));
}

void add_preferences_action(QMenu* edit, QWidget* window) {
    edit->addSeparator();
    QAction* prefs = edit->addAction(QObject::tr("&Preferences…"), window, [window] {
        PreferencesDialog dialog(window);
        dialog.exec();
    });
    prefs->setObjectName("preferences");
    // The platform's key, which some platforms leave without one.
    prefs->setShortcut(QKeySequence(QKeySequence::Preferences).isEmpty() ? QKeySequence(QObject::tr("Ctrl+,"))
                                                                        : QKeySequence(QKeySequence::Preferences));
    prefs->setMenuRole(QAction::PreferencesRole);
    prefs->setToolTip(QObject::tr("The style new documents start with, their sharp edges, the model's unit and the "
                                  "export folder"));
}

void add_help_menu(QMainWindow* window) {
    QMenu* help = window->menuBar()->addMenu(QObject::tr("&Help"));
    QAction* reference = help->addAction(QObject::tr("&Style Reference"), window,
                                         [window] { show_document(window, "styles.md", QObject::tr("Style Reference")); });
    reference->setObjectName("helpStyleReference");
    reference->setShortcut(QKeySequence::HelpContents);
    help->addAction(QObject::tr("The &Application"), window,
                    [window] { show_document(window, "app.md", QObject::tr("The Application")); });
    QAction* keys = help->addAction(QObject::tr("&Keyboard Shortcuts"), window, [window] {
        // Read from the menus themselves, so the list is always the truth.
        QString text = "<table>";
        for (QAction* menu : window->menuBar()->actions())
            for (QAction* a : menu->menu() ? menu->menu()->actions() : QList<QAction*>{})
                if (!a->shortcut().isEmpty())
                    text += QString("<tr><td>%1</td><td>&nbsp;&nbsp;<b>%2</b></td></tr>")
                                .arg(QString(a->text()).remove('&'), a->shortcut().toString(QKeySequence::NativeText));
        text += QObject::tr("</table><p>In the 3-D view: drag to orbit, Shift+drag to turn the light, right or middle "
                            "drag to pan, the wheel to zoom. In the SVG pane: the wheel zooms, a drag pans, a double "
                            "click fits.</p>");
        QMessageBox box(QMessageBox::NoIcon, QObject::tr("Keyboard Shortcuts"), text, QMessageBox::Ok, window);
        box.setObjectName("shortcutsBox");
        box.exec();
    });
    keys->setObjectName("helpShortcuts");
    help->addSeparator();
    help->addAction(QObject::tr("&About snaxels"), window, [window] {
        QMessageBox::about(window, QObject::tr("About snaxels"),
                           QObject::tr("<p><b>snaxels %1</b></p><p>Vector line art from 3-D meshes, after \"Snaxels on a "
                                       "Plane\" (Karsch and Hart, NPAR 2011).</p><p>MIT licence (the LICENSE file, which "
                                       "also lists the licences of the libraries it uses: Qt under the LGPL 3, Assimp, "
                                       "OpenMesh, Embree, oneTBB, Clipper, pugixml, nlohmann/json, GLM).</p>"
                                       "<p>Documentation: %2</p>")
                               .arg(QString::fromLatin1(snaxels::version), QDir::toNativeSeparators(docsDirectory())));
    });
}

} // namespace snaxels::ui
