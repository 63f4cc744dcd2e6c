#pragma once
// The XML style editor: highlighting, the parse error marked at its line and
// column, warnings listed, and the style applied shortly after typing stops.
// A style that does not parse leaves the last good one in force.

#include <QPlainTextEdit>
#include <QTimer>
#include <QWidget>

#include "snaxels/style/style.h"

class QLabel;

namespace snaxels::ui {

class StyleEditor : public QWidget {
    Q_OBJECT
  public:
    explicit StyleEditor(QWidget* parent = nullptr);

    QString text() const { return edit_->toPlainText(); }
    /// Replaces the text (a preset or a file) and applies it at once.
    void setText(const QString& text, const QString& source);
    const Style& style() const { return style_; }
    /// The last parse problem, "LINE:COL: message", or empty.
    QString problem() const { return problem_; }
    QPlainTextEdit* editor() const { return edit_; }

  signals:
    /// A new style parsed and is in force.
    void styleChanged(const snaxels::Style& style);
    /// The text was taken up (typing paused, or set): parsed or not.
    void textApplied(const QString& text);

  private:
    void apply();

    QPlainTextEdit* edit_;
    QLabel* status_;
    QTimer debounce_;
    QString source_ = "style";
    Style style_;
    QString problem_;
};

/// The style text the application starts with: the visual contour in ink
/// with dashed hidden lines, and the shadow line.
QString initial_style_text();

} // namespace snaxels::ui
