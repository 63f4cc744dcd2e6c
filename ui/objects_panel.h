#pragma once
// The Objects panel: the scene's objects and materials with their face
// counts; for each object how the style draws it (drawn, occluder only,
// hidden: its <object> elements), whether its intersection lines (where
// it meets another object or itself) are drawn, and which of the style's
// line sets take it. Choosing a state edits the style text (one undo step, saved with the
// project); selecting a row asks the 3-D view to highlight the part.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <QString>
#include <QWidget>
#include <glm/glm.hpp>

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/parts.h"
#include "snaxels/style/style.h"
#include "snaxels/style/style_edit.h"

class QTreeWidget;
class QTreeWidgetItem;

namespace snaxels::ui {

/// How the style draws an object (core's ObjectDrawing: the style's edits
/// live in snaxels/style/style_edit.h).
using ObjectState = ObjectDrawing;

/// @p style's state for an object known by @p name and @p path: hidden
/// when a hide="true" pattern matches it, else an occluder when a
/// draw="false" pattern does, else drawn.
ObjectState object_state(const Style& style, const std::string& name, const std::string& path);

/// Whether a line set of @p style draws intersection lines on object
/// @p index of @p parts.
bool draws_intersections(const Style& style, const FaceParts& parts, std::uint32_t index);

class ObjectsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ObjectsPanel(QWidget* parent = nullptr);

    /// Lists @p mesh's objects and materials (none: the panel empties).
    void setMesh(std::shared_ptr<const LoadedMesh> mesh);
    /// The document's style text and the style in force (the last that
    /// parsed, which the document keeps): the states and line sets shown
    /// follow the style; edits are made to the text.
    void setStyle(const QString& text, const Style& style);
    QTreeWidget* tree() const { return tree_; }
    /// As wide as its columns, so none hides behind a scroll bar.
    QSize sizeHint() const override;

  signals:
    /// The user chose a state: the style text that sets it.
    void styleEdited(const QString& text, const QString& step);
    /// Triangles (three corners each, in the loaded mesh's coordinates) of
    /// the part selected, to highlight; empty when nothing is selected.
    void highlightChanged(const std::vector<glm::vec3>& triangles);
    /// Something worth a line in the status bar.
    void notice(const QString& message);

  protected:
    /// Put in a dock: follows the dock's tab (dockShown).
    bool event(QEvent* event) override;

  private:
    /// The dock's tab raised (@p shown): widens the dock to the columns.
    void dockShown(bool shown);
    /// Widens the dock holding the panel to sizeHint(), up to half the window.
    void fitDock();
    void rebuild();
    /// The Lines button of object @p o's row: its outline's colour, width
    /// and hidden lines, written as the object's own line set.
    void addLinesButton(QTreeWidgetItem* item, std::size_t o);
    /// The outline object @p o has its own line set for, if any.
    std::optional<ObjectLines> linesOf(std::size_t o) const;
    /// Writes @p lines (none: as the style's other line sets draw it) for object @p o, one undo step.
    void setLines(std::size_t o, const std::optional<ObjectLines>& lines);
    void refreshStyle();
    void emitHighlight();

    QTreeWidget* tree_;
    std::shared_ptr<const LoadedMesh> mesh_;
    std::shared_ptr<const FaceParts> parts_; ///< mesh_'s parts (loaded_parts)
    QString text_;
    Style style_;
    bool updating_ = false;
};

} // namespace snaxels::ui
