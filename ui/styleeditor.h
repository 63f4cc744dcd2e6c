#pragma once
// The XML style editor: highlighting, completion, and the style applied
// shortly after typing stops. The document it edits parses the text; the
// editor shows what that parse found (the error marked at its line and
// column, warnings listed). A style that does not parse leaves the last
// good one in force.

#include <QPlainTextEdit>
#include <QTimer>
#include <memory>
#include <optional>
#include <utility>

#include <QWidget>

#include "snaxels/style/style.h"

class QCompleter;
class QLabel;
class QStandardItemModel;

namespace snaxels::ui {

/// What the style editor can complete at a place in the text: an element's
/// name after '<', an attribute's name inside a tag (those the element
/// takes and the tag does not have yet), or an attribute's value inside its
/// quotes (the words it takes). The vocabulary is the parser's
/// (style_vocabulary()).
struct StyleCompletion {
    enum class Kind { None, Element, Attribute, Value } kind = Kind::None;
    QString prefix;        ///< what is typed of the word so far
    QStringList candidates; ///< every word that fits there, in the vocabulary's order
    QStringList summaries;  ///< what each candidate does, in a line (the vocabulary's; empty for words)
};

/// The completion at @p position (a cursor position) in @p text.
StyleCompletion style_completion_at(const QString& text, int position);

/// What the element or attribute name at @p position of @p text does, as
/// "name: summary" from the vocabulary; empty elsewhere.
QString style_summary_at(const QString& text, int position);

class StyleEditor : public QWidget {
    Q_OBJECT
  public:
    explicit StyleEditor(QWidget* parent = nullptr);

    QString text() const { return edit_->toPlainText(); }
    /// Replaces the text (a preset or a file) and applies it at once: an edit.
    void setText(const QString& text);
    /// Shows @p text, the document's (an undo, a project opened): no edit.
    void showText(const QString& text);
    /// Shows what the document's parse of the text found: @p warnings
    /// listed and marked, or @p problem, why it does not parse.
    void showCheck(const std::vector<StyleDiagnostic>& warnings, const std::optional<StyleDiagnostic>& problem);
    /// Typing not applied yet (it is applied when typing pauses).
    bool pending() const { return debounce_.isActive(); }
    /// Applies typing not applied yet at once (before a save, an undo).
    void applyPending();
    /// The parse problem shown, "LINE:COL: message", or empty.
    QString problem() const { return problem_; }
    QPlainTextEdit* editor() const { return edit_; }
    /// The completer: it pops up as an element, attribute or value is typed
    /// (and on Ctrl+Space), and Enter or Tab inserts the word chosen.
    QCompleter* completer() const { return completer_; }

    /// Ctrl+click: when @p position (in the text) is in a colour value,
    /// asks for a colour in a dialog and writes it there (one edit, applied
    /// at once); false when it is in no colour value.
    bool pickColour(int position);
    /// Writes @p value (degrees, or "file") as the <surface> element's
    /// sharp-angle, adding the element after the root's opening tag when
    /// the style has none (one edit, applied at once).
    void setSharpAngle(const QString& value);

  signals:
    /// The user's text was taken up (typing paused, or set): parsed or not,
    /// it is the document's next style text.
    void textApplied(const QString& text);

  private:
    void apply();
    /// Offers the completions at the cursor (@p forced: even before a word starts).
    void complete(bool forced);
    void insertCompletion(const QString& word);

    QCompleter* completer_;
    QStandardItemModel* completions_; ///< each word (edit role) with its summary beside it (display role)
    QPlainTextEdit* edit_;
    QLabel* status_;
    QTimer debounce_;
    QString problem_;
};

/// The colour value ("#rrggbb" or "#rgb", in quotes) around @p position
/// of @p text: where its "#" is and its length, or nothing.
std::optional<std::pair<int, int>> colour_value_at(const QString& text, int position);

/// The style text the application starts with: the visual contour in ink
/// with dashed hidden lines, and the shadow line.
QString initial_style_text();

} // namespace snaxels::ui
