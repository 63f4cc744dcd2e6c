#pragma once
// Menus of the main window that need no state of it: Style (presets, sharp
// edges, loading and saving style files, all edits through the style
// editor, so each is one step of the document's history) and Help (the
// bundled documents, the shortcuts read from the menus, About).

class QMainWindow;

namespace snaxels::ui {

class Document;
class StyleEditor;

/// Adds the Style menu to @p window's menu bar: its edits go through @p editor.
void add_style_menu(QMainWindow* window, const Document* document, StyleEditor* editor);

/// Adds the Help menu to @p window's menu bar.
void add_help_menu(QMainWindow* window);

} // namespace snaxels::ui
