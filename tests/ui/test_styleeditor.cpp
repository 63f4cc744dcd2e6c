// The style editor's completion, offscreen: what it offers at each place in
// a style document (element names after '<', the attributes an element
// takes and does not have yet, an attribute's words inside its quotes), that
// every word it offers is one the parser takes, and that typing with the
// popup inserts the word chosen. Expected words are spelled out here.
#include <QAbstractItemView>
#include <QApplication>
#include <QColorDialog>
#include <QHelpEvent>
#include <QToolTip>
#include <QTextBlock>
#include <QDir>
#include <QFile>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTimer>
#include <QCompleter>
#include <QPlainTextEdit>
#include <QTest>

#include "snaxels/style/style.h"
#include "snaxels/style/style_edit.h"
#include "ui/styleeditor.h"

using snaxels::ui::StyleCompletion;
using snaxels::ui::StyleEditor;
using snaxels::ui::style_completion_at;

namespace {

StyleCompletion at_end(const QString& text) { return style_completion_at(text, int(text.size())); }

} // namespace

class TestStyleEditor : public QObject {
    Q_OBJECT
  private slots:
    void offersWhatFitsWhereTheCursorIs() {
        const StyleCompletion element = at_end("<style version=\"1\">\n  <vis");
        QCOMPARE(element.kind, StyleCompletion::Kind::Element);
        QCOMPARE(element.prefix, QString("vis"));
        for (const char* name : {"canvas", "light", "contour", "visible", "hidden", "region", "object"})
            QVERIFY2(element.candidates.contains(name), name);

        const StyleCompletion attribute = at_end("<contour ");
        QCOMPARE(attribute.kind, StyleCompletion::Kind::Attribute);
        QCOMPARE(attribute.prefix, QString());
        QCOMPARE(attribute.candidates, (QStringList{"kind", "k", "angle", "min-length", "test", "min-derivative", "min-angle",
                                                    "threshold", "fade", "object", "material", "over"}));
        // Those already written are not offered again.
        const StyleCompletion rest = at_end("<contour kind=\"suggestive\" min-d");
        QCOMPARE(rest.kind, StyleCompletion::Kind::Attribute);
        QCOMPARE(rest.prefix, QString("min-d"));
        QVERIFY(!rest.candidates.contains("kind"));
        QVERIFY(rest.candidates.contains("min-derivative"));

        const StyleCompletion value = at_end("<contour kind=\"sug");
        QCOMPARE(value.kind, StyleCompletion::Kind::Value);
        QCOMPARE(value.prefix, QString("sug"));
        QCOMPARE(value.candidates, (QStringList{"visual", "shadow", "isophote", "gleam", "parabolic", "crease", "border",
                                                "suggestive", "material", "object", "intersection"}));
        QCOMPARE(at_end("<hidden cap=\"").candidates, (QStringList{"butt", "round", "square"}));
        QCOMPARE(at_end("<region class=\"").candidates, (QStringList{"shadow", "lit", "band", "highlight"}));

        // Nothing outside a tag, in a closing tag or comment, in a number's
        // quotes, or on an element the language does not have.
        QCOMPARE(at_end("<contour kind=\"visual\">\n  ").kind, StyleCompletion::Kind::None);
        QCOMPARE(at_end("</cont").kind, StyleCompletion::Kind::None);
        QCOMPARE(at_end("<!-- a note <").kind, StyleCompletion::Kind::Element); // '<' opens a tag even here
        QCOMPARE(at_end("<visible width=\"1").kind, StyleCompletion::Kind::None);
        QCOMPARE(at_end("<banana ").kind, StyleCompletion::Kind::None);
        QCOMPARE(at_end("<contour kind=\"visual\"").kind, StyleCompletion::Kind::None);
    }

    // Every attribute and word offered is one the parser takes: a document
    // using each parses without an "unknown attribute" warning.
    void offersOnlyWhatTheParserTakes() {
        for (const snaxels::StyleElement& e : snaxels::style_vocabulary()) {
            if (e.name == "style") continue;
            const StyleCompletion c = at_end(QString("<%1 ").arg(QString::fromStdString(e.name)));
            QCOMPARE(c.candidates.size(), qsizetype(e.attributes.size()));
            for (const snaxels::StyleAttribute& a : e.attributes) {
                for (const std::string& word : a.values) {
                    QString attrs = QString("%1=\"%2\"").arg(QString::fromStdString(a.name), QString::fromStdString(word));
                    if (e.name == "region" && a.name == "class" && (word == "band" || word == "highlight")) attrs += " k=\"0.5\"";
                    if (e.name == "contour" && a.name == "kind" && (word == "isophote" || word == "gleam")) attrs += " k=\"0.5\"";
                    if (e.name == "contour" && a.name == "over") attrs += " kind=\"visual\"";
                    if (e.name == "contour" && a.name == "test") attrs += " kind=\"suggestive\"";
                    if (e.name == "object" && a.name != "name") attrs += " name=\"Ground\"";
                    if (e.name == "region" && a.name != "class") attrs += " class=\"lit\"";
                    if (e.name == "canvas" && a.name == "orientation") attrs += " paper=\"A4\""; // it turns a paper
                    if (e.name == "canvas" && a.name == "model-units") attrs += " scale=\"1:10\""; // what scale measures
                    const QString inner = QString("<%1 %2/>").arg(QString::fromStdString(e.name), attrs);
                    // (width-by="strength" follows a suggestive contour's test.)
                    const QString kind = word == "strength" ? "suggestive" : "visual";
                    const QString doc = e.name == "visible" || e.name == "hidden"
                                            ? QString("<style version=\"1\"><contour kind=\"%2\">%1</contour></style>").arg(inner, kind)
                                            : QString("<style version=\"1\">%1</style>").arg(inner);
                    std::vector<snaxels::StyleDiagnostic> warnings;
                    try {
                        snaxels::parse_style(doc.toStdString(), "test", &warnings);
                    } catch (const std::exception& ex) {
                        QFAIL(qPrintable(doc + ": " + ex.what()));
                    }
                    QVERIFY2(warnings.empty(), qPrintable(doc));
                }
            }
        }
    }

    // Typing in the editor: the popup opens on the value's quote, narrows as
    // letters come, and Enter puts the word in; an attribute chosen comes
    // with its quotes and the cursor between them.
    void typingWithThePopupInsertsTheWord() {
        StyleEditor editor;
        editor.resize(600, 400);
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        QPlainTextEdit* edit = editor.editor();
        edit->setFocus();
        edit->moveCursor(QTextCursor::End);
        QTest::keyClicks(edit, "<contour kind=\"sug");
        QVERIFY(editor.completer()->popup()->isVisible());
        QCOMPARE(editor.completer()->currentCompletion(), QString("suggestive"));
        QTest::keyClick(editor.completer()->popup(), Qt::Key_Return);
        QVERIFY2(edit->toPlainText().endsWith("<contour kind=\"suggestive"), qPrintable(edit->toPlainText()));
        QTest::keyClicks(edit, "\" min-d");
        QVERIFY(editor.completer()->popup()->isVisible());
        QTest::keyClick(editor.completer()->popup(), Qt::Key_Return);
        QVERIFY2(edit->toPlainText().endsWith("<contour kind=\"suggestive\" min-derivative=\"\""), qPrintable(edit->toPlainText()));
        QTest::keyClicks(edit, "3");
        QVERIFY(edit->toPlainText().endsWith("min-derivative=\"3\""));
        // Past the closing quote, Ctrl+Space offers the element's other attributes at once.
        edit->moveCursor(QTextCursor::End);
        QTest::keyClicks(edit, " ");
        QTest::keyClick(edit, Qt::Key_Space, Qt::ControlModifier);
        QVERIFY(editor.completer()->popup()->isVisible());
        QCOMPARE(editor.completer()->completionCount(), 10); // k, angle, min-length, test, min-angle, threshold, fade, object, material, over
        QTest::keyClick(editor.completer()->popup(), Qt::Key_Escape);
    }

    // Every preset's lines show whole in a narrow dock: they wrap, and
    // nothing scrolls sideways.
    void presetsShowWholeInANarrowDock() {
        StyleEditor editor;
        editor.resize(320, 700);
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        const QDir presets(QString(SNAXELS_SOURCE_DIR) + "/styles");
        const QStringList files = presets.entryList({"*.xml"}, QDir::Files);
        QVERIFY(files.size() >= 8);
        for (const QString& name : files) {
            QFile f(presets.filePath(name));
            QVERIFY(f.open(QIODevice::ReadOnly));
            editor.setText(QString::fromUtf8(f.readAll()));
            QCoreApplication::processEvents();
            QCOMPARE(editor.editor()->horizontalScrollBar()->maximum(), 0);
        }
    }

    // Enter keeps the line's indentation, one step deeper after an element
    // left open.
    void autoIndents() {
        StyleEditor editor;
        QPlainTextEdit* edit = editor.editor();
        edit->setPlainText("<style version=\"1\">\n  <contour kind=\"visual\">");
        edit->setFocus();
        edit->moveCursor(QTextCursor::End);
        QTest::keyClick(edit, Qt::Key_Return);
        QTest::keyClicks(edit, "<visible width=\"2\"/>");
        QTest::keyClick(edit, Qt::Key_Return);
        QTest::keyClicks(edit, "<hidden draw=\"false\"/>");
        QCOMPARE(edit->toPlainText(), QString("<style version=\"1\">\n  <contour kind=\"visual\">\n"
                                              "    <visible width=\"2\"/>\n    <hidden draw=\"false\"/>"));
    }

    // Style > Sharp Edges writes the style's <surface sharp-angle>: added
    // after the root when the style has no <surface>, the value replaced
    // when it has one; each one undo step, applied at once, and the parser
    // reads the angle back.
    void setsTheSharpAngle() {
        StyleEditor editor;
        const QString text = "<style version=\"1\">\n  <contour kind=\"visual\"/>\n</style>\n";
        editor.setText(text);
        QSignalSpy applied(&editor, &StyleEditor::textApplied);
        editor.setSharpAngle("30");
        QCOMPARE(editor.text(), QString("<style version=\"1\">\n  <surface sharp-angle=\"30\"/>\n  <contour kind=\"visual\"/>\n</style>\n"));
        QCOMPARE(applied.count(), 1);
        auto parsed = [&] { return snaxels::parse_style(editor.text().toStdString(), "test", nullptr).surface.sharp_angle; };
        QCOMPARE(parsed(), 30.0);
        editor.setSharpAngle("file");
        QCOMPARE(editor.text(), QString("<style version=\"1\">\n  <surface sharp-angle=\"file\"/>\n  <contour kind=\"visual\"/>\n</style>\n"));
        QCOMPARE(parsed(), snaxels::kFileNormals);
        editor.editor()->undo();
        QCOMPARE(parsed(), 30.0);
        editor.editor()->undo();
        QCOMPARE(editor.text(), text);
        // A <surface> without the attribute takes it.
        editor.setText("<style>\n  <surface/>\n</style>\n");
        editor.setSharpAngle("45");
        QCOMPARE(editor.text(), QString("<style>\n  <surface sharp-angle=\"45\"/>\n</style>\n"));
        QVERIFY(!snaxels::sharp_angle_splice("not a style", "30"));
    }

    // Ctrl+click on a colour: a colour dialog, and the colour chosen is
    // written in place as one change of the text, applied at once.
    void picksAColour() {
        StyleEditor editor;
        const QString text = "<style version=\"1\">\n  <contour kind=\"visual\">\n    <visible stroke=\"#111111\" width=\"2\"/>\n"
                             "  </contour>\n</style>\n";
        editor.setText(text);
        const int at = int(text.indexOf("#111111")) + 3;
        const auto value = snaxels::ui::colour_value_at(text, at);
        QVERIFY(value && value->first == text.indexOf("#111111") && value->second == 7);
        QVERIFY(!snaxels::ui::colour_value_at(text, int(text.indexOf("width")) + 2));
        QSignalSpy applied(&editor, &StyleEditor::textApplied);
        QTimer poll;
        poll.setInterval(20);
        QObject::connect(&poll, &QTimer::timeout, [&] {
            auto* dialog = qobject_cast<QColorDialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            poll.stop();
            QCOMPARE(dialog->currentColor(), QColor("#111111"));
            dialog->setCurrentColor(QColor("#ff8800"));
            dialog->accept();
        });
        poll.start();
        QVERIFY(editor.pickColour(at));
        QCOMPARE(editor.text(), QString(text).replace("#111111", "#ff8800"));
        QCOMPARE(applied.count(), 1);
        QVERIFY(!editor.pickColour(int(text.indexOf("width")) + 2)); // no colour there: no dialog
    }

    // The gutter shows a swatch beside each line that sets a colour; a click
    // on it opens a colour dialog, and the colour chosen is written into the
    // XML as one change of the text (one undo step), applied at once.
    void swatchInTheGutterPicksAColour() {
        StyleEditor editor;
        editor.resize(420, 300);
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        const QString text = "<style version=\"1\">\n  <contour kind=\"visual\">\n    <visible stroke=\"#2f5fa8\" width=\"2\"/>\n"
                             "  </contour>\n</style>\n";
        editor.setText(text);
        QPlainTextEdit* edit = editor.editor();
        QWidget* gutter = nullptr; // the edit's child beside its viewport
        for (QWidget* child : edit->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
            if (child != edit->viewport() && child->isVisible() && child->geometry().right() <= edit->viewport()->geometry().left() + 1 &&
                child->width() > 4)
                gutter = child;
        QVERIFY(gutter);
        const QImage shown = gutter->grab().toImage();
        // The swatch of line 3 is the line's colour.
        const QRect line3 = edit->cursorRect(QTextCursor(edit->document()->findBlockByNumber(2)));
        const QPoint swatch(gutter->width() / 2, line3.center().y());
        QCOMPARE(QColor(shown.pixel(swatch * shown.devicePixelRatio())).name(), QString("#2f5fa8"));
        // Lines without a colour have none.
        const QRect line2 = edit->cursorRect(QTextCursor(edit->document()->findBlockByNumber(1)));
        QVERIFY(QColor(shown.pixel(QPoint(gutter->width() / 2, line2.center().y()) * shown.devicePixelRatio())).name() != "#2f5fa8");
        QSignalSpy applied(&editor, &StyleEditor::textApplied);
        QTimer poll;
        poll.setInterval(20);
        bool asked = false;
        QObject::connect(&poll, &QTimer::timeout, [&] {
            auto* dialog = qobject_cast<QColorDialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            poll.stop();
            asked = dialog->currentColor() == QColor("#2f5fa8");
            dialog->setCurrentColor(QColor("#aa3300"));
            dialog->accept();
        });
        poll.start();
        QTest::mouseClick(gutter, Qt::LeftButton, {}, swatch);
        QVERIFY(asked);
        QCOMPARE(editor.text(), QString(text).replace("#2f5fa8", "#aa3300"));
        QCOMPARE(applied.count(), 1);
        QVERIFY(edit->document()->isUndoAvailable());
        QTest::keyClick(edit, Qt::Key_Z, Qt::ControlModifier); // one undo takes the whole pick back
        QCOMPARE(editor.text(), text);
    }

    // Completion and hover say what each element and attribute does, in the
    // words of the vocabulary (which the style reference begins with).
    void explainsElementsAndAttributes() {
        const QString text = "<style version=\"1\">\n  <contour kind=\"visual\" k=\"0.5\">\n  </contour>\n</style>\n";
        const snaxels::StyleElement* contour = snaxels::style_element("contour");
        QVERIFY(contour);
        QCOMPARE(snaxels::ui::style_summary_at(text, int(text.indexOf("contour")) + 2),
                 "contour: " + QString::fromStdString(contour->summary));
        QCOMPARE(snaxels::ui::style_summary_at(text, int(text.indexOf("kind")) + 1), QString("kind: the contour function"));
        QVERIFY(snaxels::ui::style_summary_at(text, int(text.indexOf("visual")) + 1).isEmpty()); // a value
        QVERIFY(snaxels::ui::style_summary_at(text, int(text.indexOf("0.5"))).isEmpty());

        StyleEditor editor;
        editor.resize(420, 300);
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        editor.setText("<style version=\"1\">\n  <canvas ");
        QPlainTextEdit* edit = editor.editor();
        edit->setFocus();
        edit->moveCursor(QTextCursor::End);
        QTest::keyClick(edit, Qt::Key_Space, Qt::ControlModifier);
        QTRY_VERIFY(editor.completer()->popup()->isVisible());
        QStringList shown;
        for (int row = 0; row < editor.completer()->completionModel()->rowCount(); ++row)
            shown << editor.completer()->completionModel()->index(row, 0).data(Qt::DisplayRole).toString();
        QVERIFY2(shown.contains("margin  —  space between the mesh's bounding circle and the image edge; on paper, the page's margin"), qPrintable(shown.join(" | ")));
        QVERIFY2(shown.contains("background  —  the background fill"), qPrintable(shown.join(" | ")));
        QTest::keyClick(editor.completer()->popup(), Qt::Key_Return); // takes the word alone
        QCOMPARE(edit->toPlainText(), QString("<style version=\"1\">\n  <canvas width=\"\""));

        // Hovering the element's name shows its summary as a tooltip.
        const QRect at = edit->cursorRect(QTextCursor(edit->document()->findBlockByNumber(1)));
        QTextCursor name(edit->document()->findBlockByNumber(1));
        name.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor, 4);
        const QPoint hover = edit->cursorRect(name).center() + QPoint(2, 0);
        QHelpEvent help(QEvent::ToolTip, hover, edit->viewport()->mapToGlobal(hover));
        QApplication::sendEvent(edit->viewport(), &help);
        QTRY_VERIFY(QToolTip::isVisible());
        QCOMPARE(QToolTip::text(), "canvas: " + QString::fromStdString(snaxels::style_element("canvas")->summary));
        (void)at;
    }
};

QTEST_MAIN(TestStyleEditor)
#include "test_styleeditor.moc"
