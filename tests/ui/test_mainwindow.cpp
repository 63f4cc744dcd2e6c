// The main window under a real X server (xvfb-run): the default scene loads
// on a worker thread and the 3-D view shows it shaded.

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QSet>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QSvgRenderer>
#include <QMessageBox>
#include <QPushButton>
#include <QUndoStack>
#include <QComboBox>
#include <QTest>

#include "ui/mainwindow.h"
#include "ui/meshview.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"
#include "ui/svgpane.h"
#include "ui/timeline.h"

using snaxels::ui::MainWindow;

class TestMainWindow : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void showsTheDefaultSceneShaded() {
        MainWindow window;
        window.resize(900, 700);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        window.openMesh(snaxels::ui::defaultScenePath());
        QVERIFY(loaded.wait(60000));
        QCOMPARE(window.mesh()->report.vertices, std::size_t(2930));
        // The contours follow: computed off the GUI thread, then drawn.
        QVERIFY(contours.wait(30000));
        QVERIFY(window.contourLoops() > 0);
        QTest::qWait(200);

        const QImage image = window.meshView()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        QDir().mkpath(SCREENSHOT_DIR);
        image.save(QString(SCREENSHOT_DIR) + "/mainwindow-default-scene.png");
        window.grab().save(QString(SCREENSHOT_DIR) + "/mainwindow-whole.png");

        const QRgb background = image.pixel(2, 2);
        qsizetype covered = 0;
        QSet<int> shades;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb p = image.pixel(x, y);
                if (p == background) continue;
                ++covered;
                shades.insert(qGray(p));
            }
        const double coverage = double(covered) / (image.width() * image.height());
        // The cow fills a good part of the view, shaded in many tones.
        QVERIFY2(coverage > 0.08, qPrintable(QString("coverage %1").arg(coverage)));
        QVERIFY2(shades.size() > 40, qPrintable(QString("%1 shades").arg(shades.size())));
        // Contour lines: the visual contour in red-orange over the mesh.
        qsizetype ink = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb p = image.pixel(x, y);
                ink += qRed(p) > 170 && qGreen(p) < 120 && qBlue(p) < 110;
            }
        QVERIFY2(ink > 300, qPrintable(QString("%1 contour pixels").arg(ink)));

        // The SVG pane shows the export of this view: visible and hidden
        // groups, and it renders.
        QVERIFY(window.currentSvg().contains("<g id=\"visible\">"));
        QVERIFY(window.currentSvg().contains("<g id=\"hidden\">"));
        QVERIFY(window.svgPane()->renderer()->isValid());
        const QByteArray before = window.currentSvg();

        // Orbiting the camera brings new contours.
        contours.clear();
        QTest::mousePress(window.meshView(), Qt::LeftButton, {}, QPoint(300, 300));
        QTest::mouseMove(window.meshView(), QPoint(380, 320));
        QTest::mouseRelease(window.meshView(), Qt::LeftButton, {}, QPoint(380, 320));
        QVERIFY(contours.wait(30000));
        QVERIFY(window.currentSvg() != before);

        // Editing the style redraws: the toon preset brings fills.
        QFile toon(snaxels::ui::dataDirectory() + "/styles/toon.xml");
        QVERIFY(toon.open(QIODevice::ReadOnly));
        contours.clear();
        window.styleEditor()->setText(QString::fromUtf8(toon.readAll()), "toon.xml");
        QVERIFY(contours.wait(30000));
        QVERIFY(window.currentSvg().contains("<g id=\"fills\""));
        QVERIFY(window.currentSvg().contains("#f6c86b"));
        window.grab().save(QString(SCREENSHOT_DIR) + "/mainwindow-toon.png");

        // A broken style is reported at its line and column; the last good
        // style stays in force.
        const QByteArray good = window.currentSvg();
        contours.clear();
        window.styleEditor()->editor()->setPlainText(
            "<style>\n  <contour kind=\"visual\">\n    <visible width=\"-3\"/>\n  </contour>\n</style>\n");
        QTest::qWait(800);
        QVERIFY2(window.styleEditor()->problem().startsWith("3:5: width=\"-3\""), qPrintable(window.styleEditor()->problem()));
        QCOMPARE(contours.count(), 0);
        QCOMPARE(window.currentSvg(), good);
    }

    // Scrub the timeline, export the animation and a frame; a path that
    // cannot be written is reported and leaves nothing behind.
    void scrubsAndExports() {
        MainWindow window;
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        window.openMesh(QString(SNAXELS_TEST_ASSETS) + "/spot.obj");
        QVERIFY(contours.wait(60000));
        const QByteArray first = window.currentSvg();
        window.timeline()->setFrameCount(12);
        contours.clear();
        window.timeline()->setFrame(3); // 6 degrees of turntable
        QVERIFY(contours.wait(30000));
        QVERIFY(window.currentSvg() != first);

        QTemporaryDir dir;
        QSignalSpy finished(&window, &MainWindow::exportFinished);
        QSignalSpy failed(&window, &MainWindow::exportFailed);
        const QString animated = dir.filePath("turntable.svg");
        window.exportAnimation(animated);
        QVERIFY(finished.wait(120000));
        QFile out(animated);
        QVERIFY(out.open(QIODevice::ReadOnly));
        const QByteArray svg = out.readAll();
        QVERIFY(svg.contains("<animate attributeName=\"d\""));
        QVERIFY(window.exportFrame(dir.filePath("frame.svg")));
        QVERIFY(QFile::exists(dir.filePath("frame.svg")));

        const QString nowhere = dir.filePath("missing-folder/out.svg");
        window.exportAnimation(nowhere);
        QVERIFY(failed.wait(120000));
        QVERIFY2(failed.last().first().toString().contains("does not exist"), qPrintable(failed.last().first().toString()));
        QVERIFY(!QFile::exists(nowhere));
    }

    // Loading a million faces runs off the GUI thread: the event loop never
    // stalls for 200 ms or more while the mesh loads and its contours come.
    void loadsAMillionFacesWithoutFreezing() {
        MainWindow window;
        window.resize(1000, 700);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        QElapsedTimer clock;
        qint64 last = 0, worst = 0;
        QTimer tick;
        tick.setInterval(5);
        connect(&tick, &QTimer::timeout, [&] {
            const qint64 now = clock.elapsed();
            worst = std::max(worst, now - last);
            last = now;
        });
        clock.start();
        tick.start();
        window.openMesh("proc:bumpy:1000000");
        QVERIFY(loaded.wait(180000));
        QVERIFY(contours.wait(180000));
        QTest::qWait(300);
        tick.stop();
        qInfo() << "longest event-loop stall while loading 1M faces:" << worst << "ms";
        QVERIFY2(worst < 200, qPrintable(QString("the event loop stalled for %1 ms").arg(worst)));
    }

    void reportsAFileThatFailsToLoad() {
        MainWindow window;
        window.show();
        QSignalSpy failed(&window, &MainWindow::loadFailed);
        window.openMesh(QString(SNAXELS_TEST_ASSETS) + "/bad/empty.obj");
        QVERIFY(failed.wait(30000));
        QVERIFY(failed.first().first().toString().contains("the file is empty"));
        QVERIFY(window.mesh() == nullptr);
    }
};

int main(int argc, char** argv) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    QApplication app(argc, argv);
    TestMainWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_mainwindow.moc"
