// The SVG pane on its own, offscreen: it shows the page the exported file
// shows, and nothing of the drawing past the page's edge, at any zoom and
// pan.
#include <QImage>
#include <QTest>

#include "ui/svgpane.h"

using snaxels::ui::SvgPane;

namespace {

// A 200 x 100 canvas whose red disc and blue stroke run far past its edges,
// as strokes near a drawing's border do.
const char* kSpilling = "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='100' viewBox='0 0 200 100'>"
                        "<circle cx='190' cy='50' r='120' fill='#ff0000'/>"
                        "<path d='M -300 90 L 500 90' stroke='#0000ff' stroke-width='30'/></svg>";

bool inked(QRgb c) {
    return (qRed(c) > 150 && qGreen(c) < 100 && qBlue(c) < 100) || (qBlue(c) > 150 && qRed(c) < 100 && qGreen(c) < 100);
}

} // namespace

class TestSvgPane : public QObject {
    Q_OBJECT
  private slots:
    void showsNothingPastThePage() {
        SvgPane pane;
        pane.resize(500, 400);
        QVERIFY(pane.load(kSpilling));
        int checked = 0, inkInside = 0;
        for (const double zoom : {1.0, 0.5, 2.5, 6.0}) {
            pane.fit();
            pane.zoomAt(zoom, QPointF(380, 200));
            const QImage image = pane.grab().toImage().convertToFormat(QImage::Format_RGB32);
            const QRectF page = pane.drawingRect();
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QPointF p(x + 0.5, y + 0.5);
                    // Outside the page by more than its edge line and shadow.
                    const bool outside = !page.adjusted(-4, -4, 4, 4).contains(p);
                    const bool inside = page.adjusted(2, 2, -2, -2).contains(p);
                    if (outside) {
                        ++checked;
                        QVERIFY2(!inked(image.pixel(x, y)), qPrintable(QString("zoom %1: ink at (%2, %3), outside the page %4,%5 %6x%7")
                                                                           .arg(zoom).arg(x).arg(y)
                                                                           .arg(page.x()).arg(page.y()).arg(page.width()).arg(page.height())));
                    }
                    if (inside) inkInside += inked(image.pixel(x, y));
                }
        }
        QVERIFY(checked > 100000); // the zooms leave room round the page
        QVERIFY(inkInside > 10000); // and the drawing is there inside it
    }
};

QTEST_MAIN(TestSvgPane)
#include "test_svgpane.moc"
