#include "ui/styleeditor.h"

#include <QFontDatabase>
#include <QLabel>
#include <QRegularExpression>
#include <QSyntaxHighlighter>
#include <QTextBlock>
#include <QVBoxLayout>

namespace snaxels::ui {
namespace {

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

} // namespace

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

StyleEditor::StyleEditor(QWidget* parent) : QWidget(parent), edit_(new QPlainTextEdit(this)), status_(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(edit_);
    layout->addWidget(status_);
    edit_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    edit_->setLineWrapMode(QPlainTextEdit::NoWrap);
    new XmlHighlighter(edit_->document());
    status_->setWordWrap(true);
    debounce_.setSingleShot(true);
    debounce_.setInterval(300);
    connect(&debounce_, &QTimer::timeout, this, &StyleEditor::apply);
    connect(edit_, &QPlainTextEdit::textChanged, this, [this] { debounce_.start(); });
    setText(initial_style_text(), "style");
}

void StyleEditor::setText(const QString& text, const QString& source) {
    source_ = source;
    edit_->setPlainText(text);
    debounce_.stop();
    apply();
}

void StyleEditor::apply() {
    std::vector<StyleDiagnostic> warnings;
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
    try {
        Style style = parse_style(edit_->toPlainText().toStdString(), source_.toStdString(), &warnings);
        problem_.clear();
        QStringList lines;
        for (const StyleDiagnostic& w : warnings) {
            lines << tr("%1:%2: warning: %3").arg(w.line).arg(w.column).arg(QString::fromStdString(w.message));
            mark(w.line, w.column, QColor("#fff3c4"));
        }
        status_->setStyleSheet(warnings.empty() ? "color: #2e7d32" : "color: #9a6700");
        status_->setText(warnings.empty() ? tr("Style applied.") : lines.join('\n'));
        style_ = std::move(style);
        edit_->setExtraSelections(marks);
        emit styleChanged(style_);
    } catch (const StyleError& e) {
        const StyleDiagnostic& d = e.diagnostic();
        problem_ = QString("%1:%2: %3").arg(d.line).arg(d.column).arg(QString::fromStdString(d.message));
        status_->setStyleSheet("color: #b00020");
        status_->setText(tr("%1 (the last good style stays in force)").arg(problem_));
        mark(d.line, d.column, QColor("#ffd6d6"));
        edit_->setExtraSelections(marks);
    }
    emit textApplied(edit_->toPlainText());
}

} // namespace snaxels::ui
