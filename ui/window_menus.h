#pragma once
// Menus of the main window that need no state of it: Style (presets, sharp
// edges, loading and saving style files, all edits through the style
// editor, so each is one step of the document's history) and Help (the
// bundled documents, the shortcuts read from the menus, About).

class QMainWindow;
class QMenu;
class QWidget;

namespace snaxels::ui {

class Document;
class StyleEditor;

/// Adds the Style menu to @p window's menu bar: its edits go through @p editor.
void add_style_menu(QMainWindow* window, const Document* document, StyleEditor* editor);

/// Adds to the View menu @p menu the named views (Front to Top, and the
/// axonometric ones, which turn orthographic), the Orthographic toggle and
/// the field of view: each one undo step of @p document's camera, taken
/// only while it has a mesh.
void add_view_presets(QMenu* menu, Document* document);

/// Adds Edit > Preferences to @p edit: the dialog, for @p window.
void add_preferences_action(QMenu* edit, QWidget* window);

/// Adds the Help menu to @p window's menu bar.
void add_help_menu(QMainWindow* window);

} // namespace snaxels::ui
