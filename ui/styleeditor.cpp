#include "ui/styleeditor.h"

#include <optional>

#include <QColorDialog>
#include <QMouseEvent>
#include <QAbstractItemView>
#include <QCompleter>
#include <QFontDatabase>
#include <QKeyEvent>
#include <QLabel>
#include <QScrollBar>
#include <QPainter>
#include <QStandardItemModel>
#include <QToolTip>
#include <QRegularExpression>
#include <QSyntaxHighlighter>
#include <QTextBlock>
#include <QVBoxLayout>

#include <functional>

#include "snaxels/style/style_edit.h"

namespace snaxels::ui {
namespace {

/// The completion model's role holding the word itself.
constexpr int kWordRole = Qt::UserRole + 1;

/// A colour value in quotes, "#rrggbb" or "#rgb" (captured without its quotes).
const QRegularExpression& colour_in_quotes() {
    static const QRegularExpression colour("\"(#[0-9a-fA-F]{6}|#[0-9a-fA-F]{3})\"");
    return colour;
}

class XmlHighlighter : public QSyntaxHighlighter {
  public:
    using QSyntaxHighlighter::QSyntaxHighlighter;

  protected:
    void highlightBlock(const QString& text) override {
        static const QRegularExpression tag(R"(</?[A-Za-z_][\w\-]*|/?>)");
        static const QRegularExpression attribute(R"(\b[A-Za-z_][\w\-]*(?=\s*=))");
        static const QRegularExpression value(R"("[^"]*")");
        QTextCharFormat tagFormat, attributeFormat, valueFormat, commentFormat;
        tagFormat.setForeground(QColor("#1f5fa8"));
        tagFormat.setFontWeight(QFont::Bold);
        attributeFormat.setForeground(QColor("#8a4fb0"));
        valueFormat.setForeground(QColor("#2e7d32"));
        commentFormat.setForeground(QColor("#888888"));
        for (const auto* rule : {&tag, &attribute, &value}) {
            const QTextCharFormat& format = rule == &tag ? tagFormat : rule == &attribute ? attributeFormat : valueFormat;
            for (auto it = rule->globalMatch(text); it.hasNext();) {
                const auto m = it.next();
                setFormat(int(m.capturedStart()), int(m.capturedLength()), format);
            }
        }
        // Comments, possibly spanning blocks (state 1: inside one).
        int start = previousBlockState() == 1 ? 0 : int(text.indexOf("<!--"));
        setCurrentBlockState(0);
        while (start >= 0) {
            const int end = int(text.indexOf("-->", start));
            const int length = end < 0 ? int(text.size()) - start : end - start + 3;
            if (end < 0) setCurrentBlockState(1);
            setFormat(start, length, commentFormat);
            start = end < 0 ? -1 : int(text.indexOf("<!--", start + length));
        }
    }
};

bool name_char(QChar c) { return c.isLetterOrNumber() || c == '-' || c == '_'; }

/// The text edit of the style editor: while the completer's popup is open,
/// the keys that choose or dismiss go to it (the completer hands every key
/// to the edit first, calling its handler directly); after a key is typed,
/// @p typed says which, so the editor can offer what fits.
class CompletingEdit : public QPlainTextEdit {
  public:
    CompletingEdit(QWidget* parent, QCompleter* completer, std::function<void(bool forced)> offer,
                   std::function<bool(int position)> pick_colour)
        : QPlainTextEdit(parent), completer_(completer), offer_(std::move(offer)), pick_colour_(std::move(pick_colour)),
          gutter_(new Gutter(this)) {
        setViewportMargins(gutterWidth(), 0, 0, 0);
        connect(this, &QPlainTextEdit::updateRequest, this, [this](const QRect& rect, int dy) {
            if (dy) gutter_->scroll(0, dy);
            else gutter_->update(0, rect.y(), gutter_->width(), rect.height());
        });
    }

    /// The swatch of line @p block's first colour, in gutter coordinates,
    /// where the colour's value is in the text (-1 where the line has none)
    /// and the colour.
    struct Swatch {
        QRect rect;
        int at = -1;
        QColor colour;
    };
    Swatch swatch(const QTextBlock& block) const {
        const QRegularExpressionMatch m = colour_in_quotes().match(block.text());
        if (!m.hasMatch()) return {};
        const QRectF line = blockBoundingGeometry(block).translated(contentOffset());
        const int side = std::min(fontMetrics().height() - 4, gutterWidth() - 4);
        return {QRect(2, int(line.top()) + 2, side, side), block.position() + int(m.capturedStart(1)), QColor(m.captured(1))};
    }

  protected:
    /// A colour swatch beside each line that sets a colour: the first one
    /// on the line; a click on it picks the colour in a dialog.
    class Gutter : public QWidget {
      public:
        explicit Gutter(CompletingEdit* edit) : QWidget(edit), edit_(edit) {
            setCursor(Qt::PointingHandCursor);
            setToolTip(tr("Click a swatch to pick its line's colour"));
        }

      protected:
        void paintEvent(QPaintEvent* event) override {
            QPainter painter(this);
            painter.fillRect(event->rect(), palette().window());
            for (QTextBlock block = edit_->firstVisibleBlock(); block.isValid(); block = block.next()) {
                if (edit_->blockBoundingGeometry(block).translated(edit_->contentOffset()).top() > height()) break;
                const Swatch s = edit_->swatch(block);
                if (s.at < 0) continue;
                const QRect& rect = s.rect;
                painter.fillRect(rect, s.colour);
                painter.setPen(palette().color(QPalette::Mid));
                painter.drawRect(rect.adjusted(0, 0, -1, -1));
            }
        }
        void mousePressEvent(QMouseEvent* event) override {
            for (QTextBlock block = edit_->firstVisibleBlock(); block.isValid(); block = block.next()) {
                const Swatch s = edit_->swatch(block);
                if (s.at >= 0 && s.rect.contains(event->position().toPoint())) {
                    edit_->pick_colour_(s.at);
                    return;
                }
            }
        }

      private:
        CompletingEdit* edit_;
    };

    int gutterWidth() const { return fontMetrics().height() + 4; }
    void placeGutter() {
        const QRect r = contentsRect();
        gutter_->setGeometry(r.left(), r.top(), gutterWidth(), r.height());
    }
    void resizeEvent(QResizeEvent* event) override {
        QPlainTextEdit::resizeEvent(event);
        placeGutter();
    }
    /// The gutter's width follows the font (the editor's fixed-width font
    /// is set after construction, and may be taller than the default one):
    /// the text then starts after the gutter, never under it.
    void changeEvent(QEvent* event) override {
        QPlainTextEdit::changeEvent(event);
        if (event->type() == QEvent::FontChange) {
            setViewportMargins(gutterWidth(), 0, 0, 0);
            placeGutter();
        }
    }
    /// Hovering an element's or attribute's name says what it does.
    bool viewportEvent(QEvent* event) override {
        if (event->type() == QEvent::ToolTip) {
            auto* help = static_cast<QHelpEvent*>(event);
            const QString summary = style_summary_at(toPlainText(), cursorForPosition(help->pos()).position());
            if (!summary.isEmpty()) {
                QToolTip::showText(help->globalPos(), summary, viewport());
                return true;
            }
        }
        return QPlainTextEdit::viewportEvent(event);
    }
    /// Ctrl+click on a colour value picks the colour in a dialog.
    void mousePressEvent(QMouseEvent* event) override {
        if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier) &&
            pick_colour_(cursorForPosition(event->position().toPoint()).position()))
            return;
        QPlainTextEdit::mousePressEvent(event);
    }
    void keyPressEvent(QKeyEvent* key) override {
        if (completer_->popup()->isVisible()) {
            switch (key->key()) {
            case Qt::Key_Enter:
            case Qt::Key_Return:
            case Qt::Key_Tab:
            case Qt::Key_Escape:
            case Qt::Key_Backtab: key->ignore(); return; // the completer's popup takes these
            default: break;
            }
        }
        if (key->key() == Qt::Key_Space && (key->modifiers() & Qt::ControlModifier)) {
            offer_(true);
            return;
        }
        if ((key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) && !(key->modifiers() & Qt::ShiftModifier)) {
            // A new line starts where the one before did, and one step in
            // after an element left open (<contour ...>).
            const QString line = textCursor().block().text().left(textCursor().positionInBlock());
            QString indent = line.left(int(line.size() - QString(line).remove(QRegularExpression("^\\s+")).size()));
            const QString trimmed = line.trimmed();
            if (trimmed.startsWith('<') && trimmed.endsWith('>') && !trimmed.endsWith("/>") && !trimmed.startsWith("</") &&
                !trimmed.startsWith("<?") && !trimmed.startsWith("<!") && !trimmed.contains("</"))
                indent += "  ";
            textCursor().insertText("\n" + indent);
            ensureCursorVisible();
            return;
        }
        QPlainTextEdit::keyPressEvent(key);
        const QString typed = key->text();
        if (!typed.isEmpty() && typed[0].isPrint()) offer_(typed == "<" || typed == "\"" || typed == " ");
        else if (key->key() == Qt::Key_Backspace && completer_->popup()->isVisible()) offer_(false);
    }

  private:
    QCompleter* completer_;
    std::function<void(bool)> offer_;
    std::function<bool(int)> pick_colour_;
    Gutter* gutter_;
};

} // namespace

StyleCompletion style_completion_at(const QString& text, int position) {
    StyleCompletion out;
    const QString before = text.left(std::clamp(position, 0, int(text.size())));
    const int open = int(before.lastIndexOf('<'));
    if (open < 0 || before.lastIndexOf('>') > open) return out; // not inside a tag
    const QString tag = before.mid(open + 1);
    if (tag.startsWith('/') || tag.startsWith('!') || tag.startsWith('?')) return out;
    int name_end = 0;
    while (name_end < tag.size() && name_char(tag[name_end])) ++name_end;
    if (name_end == tag.size()) { // still typing the element's name
        out.kind = StyleCompletion::Kind::Element;
        out.prefix = tag;
        for (const StyleElement& e : style_vocabulary()) {
            out.candidates << QString::fromStdString(e.name);
            out.summaries << QString::fromStdString(e.summary);
        }
        return out;
    }
    const StyleElement* element = style_element(tag.left(name_end).toStdString());
    if (!element || !tag[name_end].isSpace()) return out;
    if (tag.count('"') % 2 == 1) { // inside an attribute's value
        const int quote = int(tag.lastIndexOf('"'));
        int end = quote - 1;
        while (end >= 0 && tag[end].isSpace()) --end;
        if (end < 0 || tag[end] != '=') return out;
        --end;
        while (end >= 0 && tag[end].isSpace()) --end;
        int start = end;
        while (start >= 0 && name_char(tag[start])) --start;
        const std::string attribute = tag.mid(start + 1, end - start).toStdString();
        for (const StyleAttribute& a : element->attributes)
            if (a.name == attribute)
                for (const std::string& word : a.values) {
                    out.candidates << QString::fromStdString(word);
                    out.summaries << QString();
                }
        out.kind = out.candidates.isEmpty() ? StyleCompletion::Kind::None : StyleCompletion::Kind::Value;
        out.prefix = tag.mid(quote + 1);
        return out;
    }
    int start = int(tag.size());
    while (start > name_end && name_char(tag[start - 1])) --start;
    if (!tag[start - 1].isSpace()) return out; // right after a value's closing quote
    out.kind = StyleCompletion::Kind::Attribute;
    out.prefix = tag.mid(start);
    for (const StyleAttribute& a : element->attributes) {
        const QString name = QString::fromStdString(a.name);
        const QRegularExpression present("(^|\\s)" + QRegularExpression::escape(name) + "\\s*=");
        if (!tag.left(start).contains(present)) {
            out.candidates << name;
            out.summaries << QString::fromStdString(a.summary);
        }
    }
    return out;
}

QString style_summary_at(const QString& text, int position) {
    if (position < 0 || position >= text.size() || !name_char(text[position])) return {};
    int start = position, end = position;
    while (start > 0 && name_char(text[start - 1])) --start;
    while (end < text.size() && name_char(text[end])) ++end;
    const QString word = text.mid(start, end - start);
    // An element: its name right after '<' (or '</').
    int before = start - 1;
    if (before >= 0 && text[before] == '/') --before;
    if (before >= 0 && text[before] == '<') {
        const StyleElement* e = style_element(word.toStdString());
        return e ? word + ": " + QString::fromStdString(e->summary) : QString();
    }
    // An attribute: a name followed by '=' inside a tag, the element's
    // name being the first word after the tag's '<'.
    int after = end;
    while (after < text.size() && text[after].isSpace()) ++after;
    if (after >= text.size() || text[after] != '=') return {};
    const int open = int(text.left(start).lastIndexOf('<'));
    if (open < 0 || text.left(start).lastIndexOf('>') > open) return {};
    int name_end = open + 1;
    while (name_end < text.size() && name_char(text[name_end])) ++name_end;
    const StyleElement* e = style_element(text.mid(open + 1, name_end - open - 1).toStdString());
    if (!e) return {};
    for (const StyleAttribute& a : e->attributes)
        if (QString::fromStdString(a.name) == word) return word + ": " + QString::fromStdString(a.summary);
    return {};
}

QString initial_style_text() {
    return QStringLiteral(R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- Edit the style: the drawing updates as you type (docs/styles.md). -->
<style version="1">
  <canvas width="800" height="800" margin="32" background="#ffffff"/>
  <contour kind="visual">
    <visible stroke="#111111" width="1.5"/>
    <hidden stroke="#111111" width="1" opacity="0.55" dash="4 3" cap="butt"/>
  </contour>
  <contour kind="shadow">
    <visible stroke="#2f5fa8" width="1.5"/>
    <hidden stroke="#2f5fa8" width="1" opacity="0.55" dash="4 3" cap="butt"/>
  </contour>
</style>
)");
}

StyleEditor::StyleEditor(QWidget* parent)
    : QWidget(parent), completer_(new QCompleter(this)), completions_(new QStandardItemModel(this)) {
    edit_ = new CompletingEdit(
        this, completer_, [this](bool forced) { complete(forced); }, [this](int position) { return pickColour(position); });
    status_ = new QLabel(this);
    status_->setObjectName("styleStatus");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(edit_);
    layout->addWidget(status_);
    edit_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    // Long lines wrap at the dock's edge, so every attribute and comment
    // shows whole at any width.
    edit_->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    edit_->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    edit_->setToolTip(tr("The style (docs/styles.md): applied as you type. Ctrl+Space completes; Ctrl+click a colour "
                         "to pick it"));
    new XmlHighlighter(edit_->document());
    status_->setWordWrap(true);
    debounce_.setSingleShot(true);
    debounce_.setInterval(300);
    connect(&debounce_, &QTimer::timeout, this, &StyleEditor::apply);
    connect(edit_, &QPlainTextEdit::textChanged, this, [this] { debounce_.start(); });
    completer_->setModel(completions_);
    completer_->setCompletionRole(kWordRole); // the word; the list shows it with its summary
    completer_->setWidget(edit_);
    completer_->setCompletionMode(QCompleter::PopupCompletion);
    completer_->setCaseSensitivity(Qt::CaseInsensitive);
    connect(completer_, qOverload<const QString&>(&QCompleter::activated), this, &StyleEditor::insertCompletion);
    showText(initial_style_text());
}

void StyleEditor::complete(bool forced) {
    const QTextCursor cursor = edit_->textCursor();
    const StyleCompletion c = style_completion_at(edit_->toPlainText(), cursor.position());
    if (c.kind == StyleCompletion::Kind::None || (!forced && c.prefix.isEmpty() && c.kind != StyleCompletion::Kind::Value)) {
        completer_->popup()->hide();
        return;
    }
    completions_->clear();
    for (qsizetype i = 0; i < c.candidates.size(); ++i) {
        auto* item = new QStandardItem;
        item->setData(c.candidates[i], kWordRole);
        const QString summary = c.summaries.value(i);
        item->setData(summary.isEmpty() ? c.candidates[i] : c.candidates[i] + "  —  " + summary, Qt::DisplayRole);
        item->setData(summary, Qt::ToolTipRole);
        completions_->appendRow(item);
    }
    completer_->setCompletionPrefix(c.prefix);
    if (completer_->completionCount() == 0 ||
        (completer_->completionCount() == 1 && completer_->currentCompletion() == c.prefix)) {
        completer_->popup()->hide();
        return;
    }
    completer_->popup()->setCurrentIndex(completer_->completionModel()->index(0, 0));
    QRect rect = edit_->cursorRect();
    rect.setWidth(std::min(completer_->popup()->sizeHintForColumn(0), std::max(280, edit_->width())) +
                  completer_->popup()->verticalScrollBar()->sizeHint().width());
    completer_->complete(rect);
}

void StyleEditor::insertCompletion(const QString& word) {
    QTextCursor cursor = edit_->textCursor();
    const StyleCompletion c = style_completion_at(edit_->toPlainText(), cursor.position());
    if (c.kind == StyleCompletion::Kind::None) return;
    cursor.movePosition(QTextCursor::Left, QTextCursor::KeepAnchor, int(c.prefix.size()));
    if (c.kind == StyleCompletion::Kind::Attribute) {
        cursor.insertText(word + "=\"\"");
        cursor.movePosition(QTextCursor::Left);
        edit_->setTextCursor(cursor);
        complete(false); // the attribute's words, if it has some
        return;
    }
    cursor.insertText(word);
    edit_->setTextCursor(cursor);
}

std::optional<std::pair<int, int>> colour_value_at(const QString& text, int position) {
    // A "#rrggbb" (or #rgb) value in quotes around the position.
    for (auto it = colour_in_quotes().globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        if (position >= m.capturedStart(0) && position <= m.capturedEnd(0))
            return std::pair<int, int>(int(m.capturedStart(1)), int(m.capturedLength(1)));
    }
    return std::nullopt;
}

bool StyleEditor::pickColour(int position) {
    const auto value = colour_value_at(edit_->toPlainText(), position);
    if (!value) return false;
    const QColor current(edit_->toPlainText().mid(value->first, value->second));
    const QColor chosen = QColorDialog::getColor(current, this, tr("Pick a colour"));
    if (!chosen.isValid() || chosen == current) return true;
    QTextCursor cursor(edit_->document());
    cursor.beginEditBlock(); // one undo step
    cursor.setPosition(value->first);
    cursor.setPosition(value->first + value->second, QTextCursor::KeepAnchor);
    cursor.insertText(chosen.name(QColor::HexRgb));
    cursor.endEditBlock();
    debounce_.stop();
    apply(); // at once: one edit of the document
    return true;
}

void StyleEditor::setSharpAngle(const QString& value) {
    const std::string now = text().toStdString();
    const auto edit = sharp_angle_splice(now, value.toStdString());
    if (!edit) return;
    // Bytes of UTF-8 to the editor's characters (UTF-16).
    auto chars = [&](std::size_t bytes) { return int(QString::fromUtf8(now.data(), qsizetype(bytes)).size()); };
    QTextCursor cursor(edit_->document());
    cursor.beginEditBlock(); // one undo step
    cursor.setPosition(chars(edit->at));
    cursor.setPosition(chars(edit->at + edit->length), QTextCursor::KeepAnchor);
    cursor.insertText(QString::fromStdString(edit->text));
    cursor.endEditBlock();
    debounce_.stop();
    apply(); // at once: one edit of the document
}

void StyleEditor::applyPending() {
    if (!debounce_.isActive()) return;
    debounce_.stop();
    apply();
}

void StyleEditor::setText(const QString& text) {
    edit_->setPlainText(text);
    debounce_.stop();
    apply();
}

void StyleEditor::showText(const QString& text) {
    if (text == edit_->toPlainText()) return;
    edit_->setPlainText(text);
    debounce_.stop(); // shown, not typed: nothing to apply
}

void StyleEditor::showCheck(const std::vector<StyleDiagnostic>& warnings, const std::optional<StyleDiagnostic>& problem) {
    QList<QTextEdit::ExtraSelection> marks;
    auto mark = [&](int line, int column, const QColor& colour) {
        QTextEdit::ExtraSelection sel;
        sel.format.setBackground(colour);
        sel.format.setProperty(QTextFormat::FullWidthSelection, true);
        QTextCursor cursor(edit_->document()->findBlockByNumber(std::max(line - 1, 0)));
        cursor.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor, std::max(column - 1, 0));
        sel.cursor = cursor;
        marks.append(sel);
    };
    if (problem) {
        const StyleDiagnostic& d = *problem;
        problem_ = QString("%1:%2: %3").arg(d.line).arg(d.column).arg(QString::fromStdString(d.message));
        status_->setStyleSheet("color: #b00020");
        status_->setText(tr("%1 (the last good style stays in force)").arg(problem_));
        mark(d.line, d.column, QColor("#ffd6d6"));
    } else {
        problem_.clear();
        QStringList lines;
        for (const StyleDiagnostic& w : warnings) {
            lines << tr("%1:%2: warning: %3").arg(w.line).arg(w.column).arg(QString::fromStdString(w.message));
            mark(w.line, w.column, QColor("#fff3c4"));
        }
        status_->setStyleSheet(warnings.empty() ? "color: #2e7d32" : "color: #9a6700");
        status_->setText(warnings.empty() ? tr("Style applied.") : lines.join('\n'));
    }
    edit_->setExtraSelections(marks);
}

void StyleEditor::apply() { emit textApplied(edit_->toPlainText()); }

} // namespace snaxels::ui

