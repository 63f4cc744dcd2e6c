// The main window under a real X server (xvfb-run): the default scene loads
// on a worker thread and the 3-D view shows it shaded.

#include <cstdio>

#include <sys/resource.h>

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QTextStream>
#include <QFileDialog>
#include <QSpinBox>
#include <QAction>
#include <QFileInfo>
#include <QStatusBar>
#include <QToolButton>
#include <QTextBrowser>
#include <QDockWidget>
#include <QMenuBar>
#include <QSlider>
#include <QTimer>
#include <functional>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QTemporaryDir>
#include <QSet>
#include <QProgressBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QSvgRenderer>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QTextBlock>
#include <QCheckBox>
#include <QMouseEvent>
#include <algorithm>
#include <cmath>
#include <QUndoStack>
#include <QColorDialog>
#include <QComboBox>
#include <QHeaderView>
#include <QTreeWidget>
#include <QDoubleSpinBox>
#include <QInputDialog>
#include <QPainter>
#include <QPlainTextEdit>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QProcess>
#include <QMimeData>
#include <QUrl>
#include <QWheelEvent>
#include <QTest>

#include "snaxels/mesh/isolated_import.h"

#include "snaxels/mesh/parts.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/project/project.h"
#include "snaxels/scene/orbit.h"
#include "ui/document.h"
#include "ui/mainwindow.h"
#include "ui/export_actions.h"
#include "ui/mesh_loader.h"
#include "ui/meshview.h"
#include "ui/objects_panel.h"
#include "ui/preferences.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"
#include "ui/svgpane.h"
#include "ui/timeline.h"

using snaxels::ui::MainWindow;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Answers every unsaved-changes question with @p button while it lives.
struct AnswerEveryUnsavedPrompt {
    explicit AnswerEveryUnsavedPrompt(QMessageBox::StandardButton button) {
        poll.setInterval(20);
        QObject::connect(&poll, &QTimer::timeout, [this, button] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || box->objectName() != "unsavedChangesBox") return;
            ++answered;
            box->button(button)->click();
        });
        poll.start();
    }
    QTimer poll;
    int answered = 0;
};

/// Runs @p open, which shows a file dialog, and answers the dialog: taking
/// its suggestion, or cancelling. Returns the path it suggested.
QString answerFileDialog(const std::function<void()>& open, bool accept) {
    QString suggested;
    QTimer poll; // until the dialog shows
    poll.setInterval(20);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        poll.stop();
        suggested = dialog->selectedFiles().value(0);
        static_cast<QDialog*>(dialog)->done(accept ? QDialog::Accepted : QDialog::Rejected); // QFileDialog hides done()
    });
    poll.start();
    open();
    return suggested;
}

/// Answers the next unsaved-changes question with @p button once it shows.
void answerUnsavedPrompt(QMessageBox::StandardButton button, bool* asked) {
    auto* poll = new QTimer;
    poll->setInterval(20);
    QObject::connect(poll, &QTimer::timeout, [poll, button, asked] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box || box->objectName() != "unsavedChangesBox") return;
        *asked = true;
        box->button(button)->click();
        poll->deleteLater();
    });
    poll->start();
}

/// The Objects panel's row of the object called @p name, or null.
QTreeWidgetItem* objectItem(MainWindow& window, const QString& name) {
    QTreeWidgetItem* objects = window.objectsPanel()->tree()->topLevelItem(0);
    for (int i = 0; objects && i < objects->childCount(); ++i)
        if (objects->child(i)->text(0) == name) return objects->child(i);
    return nullptr;
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// Shows @p window at @p size and loads @p mesh into it; true once its
/// first contours are drawn.
/// Shows @p window at @p size and waits until it is on screen.
bool showWindow(MainWindow& window, QSize size) {
    window.resize(size);
    window.show();
    return QTest::qWaitForWindowExposed(&window);
}

/// Waits (a minute at most) until no contours are computed or due.
bool contoursSettle(const MainWindow& window) {
    for (int i = 0; i < 2400 && window.contoursBusy(); ++i) QTest::qWait(25);
    return !window.contoursBusy();
}

/// The box of the 3-D view's pixels that differ from its background (its
/// corner's colour): where the model is drawn; empty when nothing is.
QRect inkBox(const QImage& frame) {
    const QColor bg = frame.pixelColor(0, frame.height() - 1);
    QRect box;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x) {
            const QColor c = frame.pixelColor(x, y);
            if (std::abs(c.red() - bg.red()) + std::abs(c.green() - bg.green()) + std::abs(c.blue() - bg.blue()) > 30)
                box |= QRect(x, y, 1, 1);
        }
    return box;
}

bool showWithMesh(MainWindow& window, const QString& mesh, QSize size = {1000, 700}) {
    if (!showWindow(window, size)) return false;
    QSignalSpy contours(&window, &MainWindow::contoursUpdated);
    window.openMesh(mesh);
    return contours.wait(60000);
}

/// Saves @p window's document as the project @p path and opens it in
/// @p reopened (shown, then waited for until the project has opened).
bool saveAndReopen(MainWindow& window, const QString& path, MainWindow& reopened) {
    if (!window.saveProject(path) || !showWindow(reopened, {1000, 700})) return false;
    QSignalSpy opened(&reopened, &MainWindow::projectOpened);
    reopened.openFile(path);
    return opened.wait(60000);
}

/// The toon preset's text.
QString toonStyle() {
    QFile toon(snaxels::ui::dataDirectory() + "/styles/toon.xml");
    return toon.open(QIODevice::ReadOnly) ? QString::fromUtf8(toon.readAll()) : QString();
}

template <class W> W* childWithText(QWidget* parent, const QString& text) {
    for (W* w : parent->findChildren<W*>())
        if (w->text() == text) return w;
    return nullptr;
}

/// An ellipsoid (semi-axes 2, 0.8, 1 along x, y, z by default) as an OBJ
/// file: convex, so every part of its visual contour is on its outline in
/// the image, and not a solid of revolution about the orbit's axes, so the
/// outline changes as the view turns.
bool writeEllipsoid(const QString& path, glm::dvec3 semi = {2.0, 0.8, 1.0}) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return false;
    QTextStream out(&file);
    const int rings = 48, segments = 96;
    out << "v 0 " << semi.y << " 0\n";
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double theta = M_PI * i / rings, phi = 2.0 * M_PI * j / segments;
            out << "v " << semi.x * std::sin(theta) * std::cos(phi) << ' ' << semi.y * std::cos(theta) << ' '
                << semi.z * std::sin(theta) * std::sin(phi) << '\n';
        }
    out << "v 0 " << -semi.y << " 0\n";
    auto at = [&](int i, int j) { return 2 + (i - 1) * segments + (j % segments); }; // 1-based, ring i >= 1
    const int last = 2 + (rings - 1) * segments;
    for (int j = 0; j < segments; ++j) out << "f 1 " << at(1, j + 1) << ' ' << at(1, j) << '\n';
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            out << "f " << at(i, j) << ' ' << at(i, j + 1) << ' ' << at(i + 1, j + 1) << '\n';
            out << "f " << at(i, j) << ' ' << at(i + 1, j + 1) << ' ' << at(i + 1, j) << '\n';
        }
    for (int j = 0; j < segments; ++j) out << "f " << last << ' ' << at(rings - 1, j) << ' ' << at(rings - 1, j + 1) << '\n';
    return true;
}

/// The largest distance in pixels from a contour pixel (the visual
/// contour's red-orange) to the mesh's outline in @p image: the mesh's
/// pixels are those not of the background colour, its outline those of
/// them next to the background. -1 when no contour pixel shows.
double contourOffOutline(const QImage& image) {
    const QRgb background = image.pixel(2, 2);
    const int w = image.width(), h = image.height();
    auto mesh = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && image.pixel(x, y) != background; };
    std::vector<QPoint> outline, ink;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!mesh(x, y)) continue;
            if (!mesh(x - 1, y) || !mesh(x + 1, y) || !mesh(x, y - 1) || !mesh(x, y + 1)) outline.push_back({x, y});
            const QRgb p = image.pixel(x, y);
            if (qRed(p) > 170 && qGreen(p) < 120 && qBlue(p) < 110) ink.push_back({x, y});
        }
    if (ink.empty()) return -1.0;
    double worst = 0.0;
    for (const QPoint& p : ink) {
        double best = 1e9;
        for (const QPoint& q : outline) best = std::min(best, std::hypot(double(p.x() - q.x()), double(p.y() - q.y())));
        worst = std::max(worst, best);
    }
    return worst;
}

/// The window showing the horse in the toon preset, its contours drawn.
bool showHorseInToon(MainWindow& window) {
    if (!showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/horse.ply")) return false;
    QSignalSpy restyled(&window, &MainWindow::contoursUpdated);
    window.styleEditor()->setText(toonStyle());
    return restyled.wait(60000);
}

QImage paneImage(MainWindow& window) {
    return window.svgPane()->grab().toImage().convertToFormat(QImage::Format_RGB32);
}

/// Height over width of the ink in the SVG pane (the default style's
/// blue strokes; not the canvas's grey frame).
double drawnAspect(MainWindow& window) {
    const QImage image = paneImage(window);
    int x0 = image.width(), x1 = -1, y0 = image.height(), y1 = -1;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (const QRgb p = image.pixel(x, y); qBlue(p) > qRed(p) + 40) {
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
    return x1 < x0 ? 0.0 : double(y1 - y0 + 1) / double(x1 - x0 + 1);
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
  private slots:
    // Found by the robot (#41): Export Frame before the first drawing came
    // wrote an empty file and said it had exported. It now says there is
    // nothing to export yet and writes nothing.
    void exportFrameBeforeTheFirstDrawingWritesNothing() {
        MainWindow window;
        QVERIFY(showWindow(window, {900, 600}));
        QVERIFY(window.currentSvg().isEmpty()); // the default scene still loading
        QTemporaryDir dir;
        QSignalSpy failed(&window, &MainWindow::exportFailed);
        bool warned = false;
        QTimer poll; // the warning's box
        poll.setInterval(20);
        QObject::connect(&poll, &QTimer::timeout, [&] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                warned = true;
                box->accept();
            }
        });
        poll.start();
        QVERIFY(!window.exportFrame(dir.filePath("early.svg")));
        QVERIFY(warned);
        QCOMPARE(failed.size(), 1);
        QVERIFY2(failed.first().first().toString().contains("Nothing to export yet"), qPrintable(failed.first().first().toString()));
        QVERIFY(!QFile::exists(dir.filePath("early.svg")));
    }

    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        snaxels::set_mesh_importer(snaxels::importer_beside_executable()); // as the application does
    }

    void showsTheDefaultSceneShaded() {
        MainWindow window;
        QVERIFY(showWindow(window, {900, 700}));
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
        QVERIFY(window.currentSvg().contains("<g id=\"visible\""));
        QVERIFY(window.currentSvg().contains("<g id=\"hidden\""));
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
        window.styleEditor()->setText(QString::fromUtf8(toon.readAll()));
        QVERIFY(contours.wait(30000));
        QVERIFY(window.currentSvg().contains("<g id=\"fills\""));
        QVERIFY(window.currentSvg().contains("#f6c86b"));
        window.grab().save(QString(SCREENSHOT_DIR) + "/mainwindow-toon.png");

        // Region colouring: the 3-D view takes the style's lit and shadow
        // fills (shaded lightly), both present on the lit cow.
        window.regionsAction()->setChecked(true);
        QTest::qWait(200);
        const QImage regions = window.meshView()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        regions.save(QString(SCREENSHOT_DIR) + "/mainwindow-regions.png");
        auto near = [](QRgb p, QColor c, double scale) {
            return std::abs(qRed(p) - c.red() * scale) < 40 && std::abs(qGreen(p) - c.green() * scale) < 40 &&
                   std::abs(qBlue(p) - c.blue() * scale) < 40;
        };
        qsizetype lit = 0, shadow = 0;
        for (int y = 0; y < regions.height(); ++y)
            for (int x = 0; x < regions.width(); ++x) {
                const QRgb p = regions.pixel(x, y);
                lit += near(p, QColor("#f6c86b"), 0.85);
                shadow += near(p, QColor("#c0603e"), 0.85);
            }
        // Each a good part of the cow (drawn in the view's frame, the canvas fitted).
        QVERIFY2(lit > 1000 && shadow > 1000 && std::min(lit, shadow) > 0.1 * double(lit + shadow),
                 qPrintable(QString("lit %1, shadow %2 pixels").arg(lit).arg(shadow)));
        window.regionsAction()->setChecked(false);

        // A broken style is reported at its line and column; the last good
        // style stays in force.
        // (Updates still under way land first: orbits and edits may each
        // bring more than one as results come in.)
        QTRY_VERIFY_WITH_TIMEOUT(!window.contoursBusy(), 30000);
        QTest::qWait(100);
        const QByteArray good = window.currentSvg();
        contours.clear();
        window.styleEditor()->editor()->setPlainText(
            "<style>\n  <contour kind=\"visual\">\n    <visible width=\"-3\"/>\n  </contour>\n</style>\n");
        QTest::qWait(800);
        QVERIFY2(window.styleEditor()->problem().startsWith("3:5: width=\"-3\""), qPrintable(window.styleEditor()->problem()));
        QCOMPARE(contours.count(), 0);
        QCOMPARE(window.currentSvg(), good);
    }

    // View > Parabolic Curves: found off the GUI thread with progress in the
    // status bar, then drawn on the 3-D view (not in the SVG, which stays
    // the style's); a new mesh while a search runs starts one for it.
    void showsParabolicCurves() {
        MainWindow window;
        QVERIFY(showWithMesh(window, "proc:torus:20000"));
        QSignalSpy found(&window, &MainWindow::parabolicFinished);
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        const QByteArray svg = window.currentSvg();
        auto* progress = window.findChild<QProgressBar*>("parabolicProgress");
        QVERIFY(progress);
        window.parabolicAction()->setChecked(true);
        QVERIFY(progress->isVisible());
        QVERIFY(window.parabolicPending());
        QVERIFY(found.wait(120000));
        QCOMPARE(found.first().first().toString(), QString());
        QVERIFY(!progress->isVisible());
        QVERIFY(window.parabolicCurves());
        QCOMPARE(window.parabolicCurves()->curves.size(), std::size_t(2)); // the torus's two circles
        contours.clear();
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        auto green = [&] {
            const QImage image = window.meshView()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
            qsizetype n = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QRgb p = image.pixel(x, y);
                    n += qGreen(p) > 170 && qRed(p) < 120 && qBlue(p) < 170 && qGreen(p) - qRed(p) > 90;
                }
            return n;
        };
        const qsizetype on = green();
        window.meshView()->grabFramebuffer().save(QString(SCREENSHOT_DIR) + "/mainwindow-parabolic.png");
        QVERIFY2(on > 300, qPrintable(QString("%1 parabolic pixels").arg(on)));
        QCOMPARE(window.currentSvg(), svg); // the style does not draw them
        window.parabolicAction()->setChecked(false);
        contours.clear();
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QVERIFY2(green() < on / 10, qPrintable(QString("%1 parabolic pixels left").arg(green())));

        // A style that draws them draws them in the SVG too, once found.
        contours.clear();
        window.styleEditor()->setText("<style>\n  <contour kind=\"visual\"/>\n  <contour kind=\"parabolic\"/>\n</style>\n");
        QVERIFY(contours.wait(30000));
        QTRY_VERIFY_WITH_TIMEOUT(window.currentSvg().contains("#1f8a4c"), 30000);

        // Another mesh while a search runs: the search for the old one is
        // dropped and the new one's curves come. (The style edits are
        // unsaved: opening asks first; the new document keeps the style.)
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        bool asked = false;
        answerUnsavedPrompt(QMessageBox::Discard, &asked);
        window.openMesh("proc:torus:40000"); // its search starts at once
        QVERIFY(asked);
        QVERIFY(loaded.wait(60000));
        QVERIFY(window.parabolicPending());
        window.openMesh("proc:nose:20000"); // and is dropped for this one's
        QVERIFY(loaded.wait(60000));
        QTRY_VERIFY_WITH_TIMEOUT(!window.parabolicPending(), 120000);
        QVERIFY(window.parabolicCurves());
        QVERIFY(window.parabolicCurves()->curves.size() > 2);
        QSettings().setValue("view/parabolic", false);
    }

    // Scrub the timeline, export the animation and a frame; a path that
    // cannot be written is reported and leaves nothing behind.
    void scrubsAndExports() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj", {1200, 800}));
        // A coarse mesh is refined for the contours, and the status bar says so.
        const auto* meshLabel = window.findChild<QLabel*>("meshLabel");
        QVERIFY(meshLabel);
        QVERIFY2(meshLabel->text().contains("5856 faces") && meshLabel->text().contains("refined to 23792 faces"),
                 qPrintable(meshLabel->text()));
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
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

        // The outputs chosen by extension: compressed SVG, dotLottie, video, PDF.
        const QString svgz = dir.filePath("turntable.svgz");
        window.exportAnimation(svgz);
        QVERIFY(finished.wait(120000));
        QFile gz(svgz);
        QVERIFY(gz.open(QIODevice::ReadOnly));
        const QByteArray gz_bytes = gz.readAll();
        QVERIFY(gz_bytes.startsWith("\x1f\x8b")); // a gzip member
        QVERIFY(gz_bytes.size() < svg.size());
        const QString dotlottie = dir.filePath("turntable.lottie");
        window.exportAnimation(dotlottie);
        QVERIFY(finished.wait(120000));
        QFile zip(dotlottie);
        QVERIFY(zip.open(QIODevice::ReadOnly));
        const QByteArray zip_bytes = zip.readAll();
        QVERIFY(zip_bytes.startsWith("PK\x03\x04") && zip_bytes.contains("manifest.json") &&
                zip_bytes.contains("animations/turntable.json"));
        const QString video = dir.filePath("turntable.mp4");
        window.exportAnimation(video);
        QVERIFY(finished.wait(120000));
        QFile mp4(video);
        QVERIFY(mp4.open(QIODevice::ReadOnly));
        QVERIFY(mp4.read(12).mid(4, 4) == "ftyp"); // an MP4 file
        QVERIFY(window.exportFrame(dir.filePath("frame.pdf")));
        QFile pdf(dir.filePath("frame.pdf"));
        QVERIFY(pdf.open(QIODevice::ReadOnly));
        QVERIFY(pdf.read(5) == "%PDF-");
        // An extension no export writes: refused at once, nothing written.
        const QString unknown = dir.filePath("turntable.mp3");
        window.exportAnimation(unknown);
        QVERIFY(!failed.isEmpty());
        QVERIFY2(failed.last().first().toString().contains(".svg, .svgz, .json, .lottie, .mp4, .webm, .gif"),
                 qPrintable(failed.last().first().toString()));
        QVERIFY(!QFile::exists(unknown));
        for (QMessageBox* b : window.findChildren<QMessageBox*>()) b->close();
    }

    // A fault inside the tracker while the contour kinds are tracked in
    // parallel (the toon preset tracks the visual and the shadow contour)
    // ends the export with a message box naming it; nothing is written and
    // the document is as it was.
    void faultInParallelTrackingShowsAMessage() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        QFile toon(snaxels::ui::dataDirectory() + "/styles/toon.xml");
        QVERIFY(toon.open(QIODevice::ReadOnly));
        window.styleEditor()->setText(QString::fromUtf8(toon.readAll()));
        window.timeline()->setFrameCount(6);
        const int steps = window.undoStack()->count();
        const QString style = window.styleEditor()->text();
        QTemporaryDir dir;
        const QString path = dir.filePath("faulted.svg");
        QSignalSpy failed(&window, &MainWindow::exportFailed);
        qputenv("SNAXELS_FAULT", "tracker-step:3");
        window.exportAnimation(path);
        const bool reported = failed.wait(120000);
        qunsetenv("SNAXELS_FAULT");
        QVERIFY(reported);
        const QString message = failed.last().first().toString();
        QVERIFY2(message.contains("internal error") && message.contains("fault injected in the tracker"), qPrintable(message));
        QMessageBox* box = nullptr;
        for (QMessageBox* b : window.findChildren<QMessageBox*>())
            if (b->isVisible()) box = b;
        QVERIFY(box);
        QVERIFY2(box->text().contains("fault injected in the tracker"), qPrintable(box->text()));
        QVERIFY(!QFile::exists(path));
        QCOMPARE(window.undoStack()->count(), steps);
        QCOMPARE(window.styleEditor()->text(), style);
        box->close();
        // The document still works: the same export without the fault succeeds.
        QSignalSpy finished(&window, &MainWindow::exportFinished);
        window.exportAnimation(path);
        QVERIFY(finished.wait(120000));
        QVERIFY(QFile::exists(path));
    }

    // Loading a million faces runs off the GUI thread: the event loop never
    // stalls for 200 ms or more while the mesh loads and its contours come.
    void loadsAMillionFacesWithoutFreezing() {
        MainWindow window;
        QVERIFY(showWindow(window, {1000, 700}));
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

    // The user's whole round: open a mesh, edit the style and see the SVG
    // pane change, move the camera and the light, change the animation,
    // scrub, export; save the project, reopen it in a new window and get
    // the same export byte for byte.
    void endToEndProjectRoundTrip() {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath("meshes"));
        QVERIFY(QFile::copy(QString(SNAXELS_TEST_ASSETS) + "/spot.obj", dir.filePath("meshes/spot.obj")));
        QDir(dir.path()).mkpath("projects");
        const QString projectFile = dir.filePath("projects/cow.snaxels");
        QByteArray exported;
        {
            MainWindow window;
            QVERIFY(showWindow(window, {1200, 800}));
            QSignalSpy contours(&window, &MainWindow::contoursUpdated);
            window.openMesh(dir.filePath("meshes/spot.obj"));
            QVERIFY(contours.wait(60000));
            QVERIFY(!window.isModified()); // a freshly opened mesh: nothing to save yet
            const QByteArray firstSvg = window.currentSvg();
            const QImage firstPane = paneImage(window);

            // Type into the style editor: a thick blue outline, then pause.
            contours.clear();
            QPlainTextEdit* editor = window.styleEditor()->editor();
            editor->setFocus();
            editor->setPlainText(
                "<style>\n  <contour kind=\"visual\">\n    <visible stroke=\"#1040ff\" width=\"4\"/>\n"
                "    <hidden draw=\"false\"/>\n  </contour>\n  <contour kind=\"shadow\">\n"
                "    <visible stroke=\"#10a040\" width=\"1.5\"/>\n  </contour>\n</style>\n");
            QTest::keyClick(editor, Qt::Key_End, Qt::ControlModifier);
            QTest::keyClicks(editor, "<!-- blue -->");
            QVERIFY(contours.wait(30000));
            QTest::qWait(100);
            QVERIFY(window.currentSvg().contains("#1040ff"));
            QVERIFY(window.currentSvg() != firstSvg);
            // The pane shows it: pixels changed and the blue ink is there.
            const QImage pane = paneImage(window);
            QVERIFY(pane != firstPane);
            qsizetype blue = 0;
            for (int y = 0; y < pane.height(); ++y)
                for (int x = 0; x < pane.width(); ++x) {
                    const QRgb p = pane.pixel(x, y);
                    blue += qBlue(p) > 200 && qRed(p) < 90 && qGreen(p) < 120;
                }
            QVERIFY2(blue > 100, qPrintable(QString("%1 blue pixels in the pane").arg(blue)));
            QVERIFY(window.undoStack()->count() >= 1);

            // The pane zooms about the pointer, pans and fits again.
            snaxels::ui::SvgPane* svgPane = window.svgPane();
            const QRectF fitted = svgPane->drawingRect();
            QWheelEvent wheel(QPointF(40, 50), svgPane->mapToGlobal(QPointF(40, 50)), {}, QPoint(0, 240),
                              Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(svgPane, &wheel);
            QVERIFY(svgPane->zoom() > 1.4);
            QVERIFY(svgPane->drawingRect().width() > fitted.width() * 1.4);
            QTest::mousePress(svgPane, Qt::LeftButton, {}, QPoint(100, 100));
            QTest::mouseMove(svgPane, QPoint(130, 90));
            QTest::mouseRelease(svgPane, Qt::LeftButton, {}, QPoint(130, 90));
            QVERIFY(svgPane->offset() != QPointF());
            QTest::mouseDClick(svgPane, Qt::LeftButton, {}, QPoint(100, 100));
            QCOMPARE(svgPane->drawingRect(), fitted);

            // Camera and light edits; the animation: 4 degrees a frame, 30 frames.
            contours.clear();
            QTest::mousePress(window.meshView(), Qt::LeftButton, {}, QPoint(300, 300));
            QTest::mouseMove(window.meshView(), QPoint(340, 310));
            QTest::mouseRelease(window.meshView(), Qt::LeftButton, {}, QPoint(340, 310));
            QVERIFY(contours.wait(30000));
            window.turnLight(0.4, -0.2);
            QVERIFY(window.userLight().has_value());
            auto* degrees = window.timeline()->findChild<QDoubleSpinBox*>();
            QVERIFY(degrees);
            degrees->setValue(4.0);
            window.timeline()->setFrameCount(30);
            contours.clear();
            window.timeline()->setFrame(7); // scrub
            QVERIFY(contours.wait(30000));
            QCOMPARE(window.timeline()->frame(), 7);

            QSignalSpy finished(&window, &MainWindow::exportFinished);
            window.exportAnimation(dir.filePath("first.svg"));
            QVERIFY(finished.wait(180000));
            exported = readAll(dir.filePath("first.svg"));
            QVERIFY(exported.contains("<animate attributeName=\"d\""));
            QVERIFY(exported.contains("#1040ff"));

            QVERIFY(window.saveProject(projectFile));
            QVERIFY(!window.isModified());
            QVERIFY(window.windowTitle().startsWith("cow.snaxels"));
        }
        // The project keeps the mesh relative to itself.
        QVERIFY(readAll(projectFile).contains("\"mesh\": \"../meshes/spot.obj\""));

        MainWindow reopened;
        QVERIFY(showWindow(reopened, {900, 700})); // another window size: the export must not care
        QSignalSpy opened(&reopened, &MainWindow::projectOpened);
        QSignalSpy contours(&reopened, &MainWindow::contoursUpdated);
        reopened.openFile(projectFile);
        QVERIFY(opened.wait(60000));
        QVERIFY(contours.wait(30000));
        QCOMPARE(reopened.timeline()->frame(), 7);
        QCOMPARE(reopened.timeline()->spec().degrees_per_frame, 4.0);
        QVERIFY(!reopened.isModified());
        QCOMPARE(reopened.undoStack()->count(), 0);
        QSignalSpy finished(&reopened, &MainWindow::exportFinished);
        reopened.exportAnimation(dir.filePath("second.svg"));
        QVERIFY(finished.wait(180000));
        const QByteArray again = readAll(dir.filePath("second.svg"));
        QCOMPARE(again.size(), exported.size());
        QVERIFY2(again == exported, "the reopened project exports other bytes");

        // The command-line twin renders the saved project to the same bytes.
        QProcess cli;
        cli.start(QCoreApplication::applicationDirPath() + "/snaxels-cli",
                  {"render", projectFile, "-o", dir.filePath("cli.svg")});
        QVERIFY(cli.waitForFinished(180000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        QVERIFY2(readAll(dir.filePath("cli.svg")) == exported, "snaxels-cli render writes other bytes");

        // Export > Lottie writes what snaxels-cli render writes for OUT.json.
        QAction* lottie = reopened.findChild<QAction*>("exportLottie");
        QVERIFY(lottie);
        QVERIFY(lottie->text().contains("Lottie"));
        finished.clear();
        reopened.exportAnimation(dir.filePath("app.json"));
        QVERIFY(finished.wait(180000));
        const QByteArray app_lottie = readAll(dir.filePath("app.json"));
        const QJsonDocument doc = QJsonDocument::fromJson(app_lottie);
        QVERIFY2(doc.isObject() && doc.object().value("layers").toArray().size() > 1, "Export > Lottie wrote no layers");
        QCOMPARE(doc.object().value("op").toInt(), 30);
        QProcess cli_lottie;
        cli_lottie.start(QCoreApplication::applicationDirPath() + "/snaxels-cli",
                         {"render", projectFile, "-o", dir.filePath("cli.json")});
        QVERIFY(cli_lottie.waitForFinished(180000));
        QVERIFY2(cli_lottie.exitCode() == 0, cli_lottie.readAllStandardError().constData());
        QVERIFY2(readAll(dir.filePath("cli.json")) == app_lottie, "snaxels-cli render -o OUT.json writes other bytes");
    }

    // Every edit is one undo step; unsaved changes are asked about before
    // the window closes or another project replaces them.
    void undoesEditsAndAsksBeforeLosingThem() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        QTest::qWait(400);
        QCOMPARE(window.undoStack()->count(), 0); // loading is not an edit
        const QByteArray original = window.currentSvg();
        const QString originalStyle = window.styleEditor()->text();

        // Camera: a drag is one step; undo puts the view back exactly.
        const snaxels::OrbitView before = window.meshView()->orbit();
        QTest::mousePress(window.meshView(), Qt::LeftButton, {}, QPoint(300, 300));
        QTest::mouseMove(window.meshView(), QPoint(320, 300));
        QTest::mouseMove(window.meshView(), QPoint(360, 330));
        QTest::mouseRelease(window.meshView(), Qt::LeftButton, {}, QPoint(360, 330));
        QCOMPARE(window.undoStack()->count(), 1);
        QVERIFY(!(window.meshView()->orbit() == before));
        window.undoStack()->undo();
        QVERIFY(window.meshView()->orbit() == before);
        window.undoStack()->redo();
        QVERIFY(!(window.meshView()->orbit() == before));
        window.undoStack()->undo();

        // Style: a preset is a step; undo brings the text and the drawing back.
        QFile toon(snaxels::ui::dataDirectory() + "/styles/toon.xml");
        QVERIFY(toon.open(QIODevice::ReadOnly));
        contours.clear();
        window.styleEditor()->setText(QString::fromUtf8(toon.readAll()));
        QVERIFY(contours.wait(30000));
        QVERIFY(window.currentSvg().contains("<g id=\"fills\""));
        QTest::qWait(1600); // a later edit does not merge with this one
        // Animation: the source is a step.
        auto* source = window.timeline()->findChild<QComboBox*>();
        source->setCurrentIndex(1); // orbiting light
        QCOMPARE(window.timeline()->spec().kind, snaxels::AnimationSpec::Kind::LightOrbit);
        window.undoStack()->undo();
        QCOMPARE(window.timeline()->spec().kind, snaxels::AnimationSpec::Kind::Turntable);
        contours.clear();
        window.undoStack()->undo(); // the preset
        QCOMPARE(window.styleEditor()->text(), originalStyle);
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QCOMPARE(window.currentSvg(), original);
        // Light: a drag is a step; undo returns to the style's light.
        window.turnLight(0.3, 0.1);
        QVERIFY(window.userLight().has_value());
        window.undoStack()->undo();
        QVERIFY(!window.userLight().has_value());
        window.undoStack()->redo();

        // Closing asks: Cancel keeps the window and everything in it.
        QVERIFY(window.isModified());
        bool asked = false;
        answerUnsavedPrompt(QMessageBox::Cancel, &asked);
        QVERIFY(!window.close());
        QVERIFY(asked);
        QVERIFY(window.isVisible());
        QVERIFY(window.userLight().has_value());

        // Opening another project asks too; Cancel keeps this one.
        const QString other = dir.filePath("other.snaxels");
        QVERIFY(window.saveProject(other));
        window.turnLight(0.2, 0.0);
        QVERIFY(window.isModified());
        asked = false;
        answerUnsavedPrompt(QMessageBox::Cancel, &asked);
        QSignalSpy opened(&window, &MainWindow::projectOpened);
        window.openProject(other);
        QVERIFY(asked);
        QTest::qWait(300);
        QCOMPARE(opened.count(), 0);
        QVERIFY(window.isModified());
        // Save answers by saving to the project's file: nothing lost.
        asked = false;
        answerUnsavedPrompt(QMessageBox::Save, &asked);
        QVERIFY(window.close());
        QVERIFY(asked);
        QVERIFY(!window.isModified());
    }

    // A frame that cannot be drawn (the eye on the surface) is said so in
    // the pane; the drawing of the frame before does not stand in for it,
    // and Export Frame writes nothing. snaxels-cli refuses the same frame
    // for the same reason. (An eye inside the mesh draws: the near plane
    // cuts what lies nearer.)
    void aFrameThatCannotBeDrawnIsNotShownAsAnother() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        QVERIFY(contoursSettle(window));
        QVERIFY(!window.currentSvg().isEmpty());
        QVERIFY(window.frameProblem().isEmpty());
        const snaxels::OrbitView outside = window.document()->view();
        snaxels::OrbitView inside = outside;
        inside.distance = 0.02 * outside.distance; // the eye by the orbit's centre, in the cow: drawn, cut
        window.document()->setView(inside, "Inside");
        QVERIFY(contoursSettle(window));
        QVERIFY(window.frameProblem().isEmpty());
        QVERIFY(!window.currentSvg().isEmpty());
        // The orbit moved so that the eye stands on one of the cow's vertices.
        const auto& cow = window.mesh()->mesh;
        const auto p = cow.point(*cow.vertices_begin());
        snaxels::OrbitView on = outside; // moved by its pan (a project keeps the pan; the centre is the mesh's)
        on.pan -= glm::dmat3(snaxels::orbit_view_matrix(outside)) * (glm::dvec3(p[0], p[1], p[2]) - snaxels::orbit_camera(outside).eye);
        window.document()->setView(on, "On");
        QVERIFY(contoursSettle(window));
        QVERIFY(window.currentSvg().isEmpty());
        QVERIFY2(window.frameProblem().contains("lies on the surface"), qPrintable(window.frameProblem()));
        QVERIFY(window.contourLoops() == 0);
        auto* pane = window.findChild<snaxels::ui::SvgPane*>();
        QVERIFY(pane);
        QCOMPARE(pane->problem(), window.frameProblem());
        const QString frame = dir.filePath("frame.svg");
        QSignalSpy failed(&window, &MainWindow::exportFailed);
        QTimer poll; // the warning's box
        poll.setInterval(20);
        QObject::connect(&poll, &QTimer::timeout, [] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) box->accept();
        });
        poll.start();
        QVERIFY(!window.exportFrame(frame));
        poll.stop();
        QCOMPARE(failed.size(), 1);
        QCOMPARE(failed.first().first().toString(), window.frameProblem());
        QVERIFY(!QFileInfo::exists(frame));
        const QString project = dir.filePath("inside.snaxels");
        QVERIFY(window.saveProject(project));
        QProcess still;
        still.start(QCoreApplication::applicationDirPath() + "/snaxels-cli", {"render", project, "--still", "-o", frame});
        QVERIFY(still.waitForFinished(180000));
        QVERIFY(still.exitCode() != 0);
        const QString cliError = QString::fromUtf8(still.readAllStandardError()).trimmed().remove("snaxels-cli: ");
        QVERIFY2(window.frameProblem().endsWith(cliError), qPrintable(cliError + " / " + window.frameProblem()));
        // Back outside, the frame is drawn again and the problem is gone.
        window.document()->setView(outside, "Outside");
        QVERIFY(contoursSettle(window));
        QVERIFY(!window.currentSvg().isEmpty());
        QVERIFY(window.frameProblem().isEmpty());
        QVERIFY(pane->problem().isEmpty());
        QVERIFY(window.exportFrame(frame));
    }

    // Looking from straight above or below (the orbit's top view, at any
    // yaw), through a turntable's frames and without one, the pane holds
    // what snaxels-cli renders for the project saved: the export's camera
    // takes its roll from the view as the pane's does.
    void theTopViewExportsAsThePaneShowsIt() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        int n = 0;
        for (const double pitch : {snaxels::kMaxPitch, -snaxels::kMaxPitch})
            for (const int frame : {0, 40}) {
                snaxels::OrbitView v = window.document()->view();
                v.yaw = 1.0;
                v.pitch = pitch;
                window.document()->setView(v, "Top");
                window.timeline()->setFrame(frame);
                QVERIFY(contoursSettle(window));
                const QString project = dir.filePath(QString("top-%1.snaxels").arg(++n));
                QVERIFY(window.saveProject(project));
                QVERIFY(contoursSettle(window));
                QProcess still;
                still.start(QCoreApplication::applicationDirPath() + "/snaxels-cli",
                            {"render", project, "--still", "-o", project + ".svg"});
                QVERIFY(still.waitForFinished(180000));
                QVERIFY2(still.exitCode() == 0, still.readAllStandardError().constData());
                QVERIFY2(readAll(project + ".svg") == window.currentSvg(),
                         qPrintable(QString("pitch %1, frame %2: the pane differs from render --still").arg(pitch).arg(frame)));
            }
    }

    // As the window goes (the robot's defect 5, found by UBSan): QWidget's
    // destructor deletes the document while the window is no longer a
    // MainWindow, and the undo stack, cleared as it goes, called the
    // window's updateTitle. No signal of the document or of its undo stack
    // may reach the window by then.
    void noDocumentSignalReachesTheWindowAsItGoes() {
        auto* window = new MainWindow;
        QVERIFY(showWithMesh(*window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        snaxels::OrbitView v = window->document()->view();
        v.yaw += 0.5;
        window->document()->setView(v, "Turn"); // an edit: the stack has a step to clear
        QVERIFY(window->isModified());
        QObject* document = window->document();
        QObject* stack = window->undoStack();
        const QObject* asObject = window;
        bool checked = false, reached = false;
        QObject::connect(document, &QObject::destroyed, [&] {
            checked = true;
            reached = QObject::disconnect(stack, nullptr, asObject, nullptr);
            reached = QObject::disconnect(document, nullptr, asObject, nullptr) || reached;
        });
        delete window;
        QVERIFY(checked); // the document went with the window
        QVERIFY2(!reached, "the document or its undo stack was still connected to the window as it went");
    }

    // Typing the editor has not applied yet (it waits for a pause) is an
    // edit like any other: Undo takes it back first, and closing asks about it.
    void typingNotYetAppliedIsUndoneFirstAndNeverLost() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        QPlainTextEdit* editor = window.styleEditor()->editor();
        QAction* undo = nullptr;
        QAction* redo = nullptr;
        for (QAction* a : window.findChildren<QAction*>()) {
            if (a->shortcut() == QKeySequence(QKeySequence::Undo)) undo = a;
            if (a->shortcut() == QKeySequence(QKeySequence::Redo)) redo = a;
        }
        QVERIFY(undo && redo);
        const auto type = [&](const QString& text) {
            editor->setFocus();
            editor->moveCursor(QTextCursor::End);
            QTest::keyClicks(editor, text);
        };
        const QString original = window.document()->styleText();
        type("<!--a-->");
        QTest::qWait(1900); // applied after the pause, and too late to merge with what follows
        QCOMPARE(window.document()->styleText(), original + "<!--a-->");
        type("<!--b-->");
        QVERIFY(window.styleEditor()->pending());
        undo->trigger(); // at once: the typing becomes a step, which is undone
        QCOMPARE(window.document()->styleText(), original + "<!--a-->");
        QCOMPARE(editor->toPlainText(), original + "<!--a-->");
        redo->trigger();
        QCOMPARE(window.document()->styleText(), original + "<!--a-->" + "<!--b-->");
        QTest::qWait(400);
        QCOMPARE(window.document()->styleText(), original + "<!--a-->" + "<!--b-->");

        // Saved, then typed into and closed at once: the close asks.
        QVERIFY(window.saveProject(dir.filePath("p.snaxels")));
        QVERIFY(!window.isModified());
        type("<!--c-->");
        bool asked = false;
        answerUnsavedPrompt(QMessageBox::Save, &asked);
        QVERIFY(window.close());
        QVERIFY(asked);
        QVERIFY(readAll(dir.filePath("p.snaxels")).contains("<!--c-->"));
    }

    // Opening a mesh starts a new untitled document: it asks about unsaved
    // changes first, keeps the style, drops the project's path, its undo
    // history and its animation settings, and is not modified; saving it
    // asks for a name (beside the mesh), so the project it came from is
    // never overwritten with another model.
    void openingAMeshStartsAnUntitledDocument() {
        QTemporaryDir dir;
        QVERIFY(QFile::copy(QString(SNAXELS_TEST_ASSETS) + "/fandisk.obj", dir.filePath("fandisk.obj")));
        MainWindow window;
        QVERIFY(showWithMesh(window, snaxels::ui::defaultScenePath()));
        QVERIFY(!window.isModified()); // a fresh launch
        QVERIFY(!window.isWindowModified());
        const QString first = dir.filePath("first.snaxels");
        snaxels::AnimationSpec orbit = window.timeline()->spec();
        orbit.kind = snaxels::AnimationSpec::Kind::LightOrbit;
        orbit.frames = 102;
        window.document()->setAnimation(orbit); // as the timeline's source and frames would
        window.turnLight(0.4, 0.0);
        QVERIFY(window.saveProject(first));
        const QByteArray saved = readAll(first);
        QVERIFY(!saved.isEmpty());
        const QString style = window.styleEditor()->text();

        // An edit to the project, then another mesh: asked, and discarded.
        QTest::qWait(1600);
        window.turnLight(0.0, 0.3);
        QVERIFY(window.isModified());
        bool asked = false;
        answerUnsavedPrompt(QMessageBox::Discard, &asked);
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openMesh(dir.filePath("fandisk.obj"));
        QVERIFY(loaded.wait(60000));
        QVERIFY(asked);
        QVERIFY(window.projectPath().isEmpty());
        QVERIFY(!window.isModified());
        QVERIFY2(!window.windowTitle().contains("first.snaxels"), qPrintable(window.windowTitle()));
        QVERIFY(window.windowTitle().contains("fandisk.obj"));
        QCOMPARE(window.styleEditor()->text(), style);     // the last document's style
        QVERIFY(!window.userLight().has_value());          // not its light
        QVERIFY(window.timeline()->spec() == snaxels::ui::initial_animation()); // nor its 102-frame orbit
        QCOMPARE(window.timeline()->frame(), 0);
        // Undo has nothing of the other file's.
        QVERIFY(!window.undoStack()->canUndo());
        const snaxels::OrbitView view = window.meshView()->orbit();
        window.undoStack()->undo();
        QVERIFY(window.meshView()->orbit() == view);
        QVERIFY(window.timeline()->spec() == snaxels::ui::initial_animation());
        QCOMPARE(window.mesh()->report.faces, std::size_t(12946));

        // Save on the untitled document asks for a name, beside the mesh.
        window.turnLight(0.2, 0.0);
        QVERIFY(window.isModified());
        const QString second = dir.filePath("fandisk.snaxels"); // the suggestion, taken
        QAction* save = nullptr;
        for (QAction* a : window.findChildren<QAction*>())
            if (a->shortcut() == QKeySequence(QKeySequence::Save)) save = a;
        QVERIFY(save);
        const QString suggested = answerFileDialog([&] { save->trigger(); }, true);
        QCOMPARE(QFileInfo(suggested).fileName(), QString("fandisk.snaxels"));
        QCOMPARE(QFileInfo(suggested).absolutePath(), QFileInfo(dir.filePath("fandisk.obj")).absolutePath());
        QVERIFY(QFile::exists(second));
        QCOMPARE(window.projectPath(), second);
        QVERIFY(!window.isModified());
        QCOMPARE(readAll(first), saved); // the first project, byte for byte
    }

    // View > Up Axis stands a Z-up file upright, the presets look from the
    // model's sides, each is one undo step, and a project keeps the axis.
    void upAxisAndViewPresets() {
        QTemporaryDir dir;
        const QString mesh = dir.filePath("tall-z-up.obj");
        QVERIFY(writeEllipsoid(mesh, {1.2, 0.4, 2.0})); // 4 units tall along Z, 2.4 wide
        MainWindow window;
        QVERIFY(showWithMesh(window, mesh));
        auto action = [&](const char* name) {
            QAction* a = window.findChild<QAction*>(name);
            if (!a) qFatal("no action %s", name);
            return a;
        };
        auto eyeFromCentre = [&] {
            const snaxels::Camera c = window.meshView()->camera();
            return glm::normalize(c.eye - window.meshView()->orbitCentre());
        };
        // A new file stands on +Y and is seen from its front (+Z), a little
        // above and to the side (+X, a three-quarter view).
        QVERIFY(action("upPY")->isChecked());
        QVERIFY(eyeFromCentre().z > 0.8 && eyeFromCentre().y > 0.25 && eyeFromCentre().x > 0.4);
        const double lying = drawnAspect(window);
        QVERIFY2(lying < 1.0, qPrintable(QString("aspect %1 on +Y").arg(lying))); // seen end on, it is wide

        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        const int steps = window.undoStack()->count();
        action("upPZ")->trigger();
        QVERIFY(contours.wait(30000));
        QTest::qWait(100);
        QVERIFY(action("upPZ")->isChecked() && !action("upPY")->isChecked());
        QCOMPARE(window.meshView()->orbit().up, glm::dvec3(0.0, 0.0, 1.0));
        // Upright: the screen's up is the model's +Z, its front (-Y, Blender's) faces the viewer.
        QVERIFY(window.meshView()->camera().up.z > 0.9);
        QVERIFY(eyeFromCentre().y < -0.8 && eyeFromCentre().x > 0.4);
        const double upright = drawnAspect(window);
        QVERIFY2(upright > 1.4, qPrintable(QString("aspect %1 on +Z").arg(upright)));
        QCOMPARE(window.undoStack()->count(), steps + 1);

        action("viewRight")->trigger();
        QVERIFY(eyeFromCentre().x > 0.99);
        action("viewLeft")->trigger();
        QVERIFY(eyeFromCentre().x < -0.99);
        action("viewBack")->trigger();
        QVERIFY(eyeFromCentre().y > 0.99);
        action("viewTop")->trigger();
        QVERIFY(eyeFromCentre().z > 0.99);
        action("viewFront")->trigger();
        QVERIFY(eyeFromCentre().y < -0.99);
        QCOMPARE(window.undoStack()->count(), steps + 6);
        window.undoStack()->undo(); // back to the top view
        QVERIFY(eyeFromCentre().z > 0.99);

        // Home keeps the axis; the project keeps it too.
        action("viewFront")->trigger();
        window.meshView()->resetCamera();
        QCOMPARE(window.meshView()->orbit().up, glm::dvec3(0.0, 0.0, 1.0));
        MainWindow reopened;
        QVERIFY(saveAndReopen(window, dir.filePath("tall.snaxels"), reopened));
        QCOMPARE(reopened.meshView()->orbit().up, glm::dvec3(0.0, 0.0, 1.0));
        QVERIFY(reopened.findChild<QAction*>("upPZ")->isChecked());
        QVERIFY(reopened.meshView()->orbit() == window.meshView()->orbit());

        // Another file stands on +Y again.
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openMesh(QString(SNAXELS_TEST_ASSETS) + "/spot.obj");
        QVERIFY(loaded.wait(60000));
        QCOMPARE(window.meshView()->orbit().up, glm::dvec3(0.0, 1.0, 0.0));
    }

    // A file's cameras are offered in the timeline: looking through one
    // frames the view and the SVG as the file does (its aspect too), a
    // camera the file animates is a source of its own, and the export and
    // snaxels-cli render of the saved project write the same bytes as
    // snaxels-cli animate --camera.
    void looksThroughTheFilesCameras() {
        QTemporaryDir dir;
        const QString scene = QString(SNAXELS_TEST_ASSETS) + "/cameras/blender-shot.gltf";
        MainWindow window;
        QVERIFY(showWithMesh(window, scene));
        auto* cameras = window.timeline()->findChild<QComboBox*>("cameraChoice");
        QVERIFY(cameras && cameras->isVisible());
        QCOMPARE(cameras->count(), 3); // the view's, ShotCam, TopOrtho
        QComboBox* source = nullptr;
        for (QComboBox* box : window.timeline()->findChildren<QComboBox*>())
            if (box != cameras) source = box;
        QVERIFY(source);
        const int move = source->findText("Camera move: ShotCam");
        QVERIFY(move >= 0);
        // The file's own first look: through its first camera, on the clip
        // that moves it, and the status bar says so.
        QCOMPARE(source->currentText(), QString("Clip: ShotCamAction"));
        QCOMPARE(window.document()->animation().camera, std::string("ShotCam"));
        QCOMPARE(window.document()->animation().frames, 49); // 2 s at 24 fps, both ends
        QVERIFY(window.meshView()->looksThroughFileCamera());
        QVERIFY2(window.statusBar()->currentMessage().contains("Looking through the file's camera \"ShotCam\""),
                 qPrintable(window.statusBar()->currentMessage()));
        QVERIFY(!window.isModified()); // the file's look, not an edit
        // The view camera is a choice away; then back to the move.
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        source->setCurrentIndex(source->findText("Turntable"));
        cameras->setCurrentIndex(0);
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QVERIFY(!window.meshView()->looksThroughFileCamera());
        contours.clear();
        source->setCurrentIndex(move);
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QCOMPARE(window.timeline()->spec().kind, snaxels::AnimationSpec::Kind::Camera);
        QCOMPARE(window.timeline()->spec().camera, std::string("ShotCam"));
        QCOMPARE(window.timeline()->spec().frames, 49); // 2 s of keys at 24 fps
        QVERIFY(!cameras->isEnabled()); // the moving camera is the one that looks
        QVERIFY(window.meshView()->looksThroughFileCamera());
        QVERIFY2(window.currentSvg().contains("height=\"450\""), "the canvas does not follow the 16:9 camera");
        // Orbiting leaves the file's camera as it is.
        const snaxels::Camera through = window.meshView()->camera();
        QTest::mousePress(window.meshView(), Qt::LeftButton, {}, QPoint(300, 300));
        QTest::mouseMove(window.meshView(), QPoint(360, 320));
        QTest::mouseRelease(window.meshView(), Qt::LeftButton, {}, QPoint(360, 320));
        QVERIFY(window.meshView()->camera() == through);
        QVERIFY(window.statusBar()->currentMessage().contains("camera"));
        // Half way, the camera has moved.
        contours.clear();
        window.timeline()->setFrame(24);
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QVERIFY(glm::length(window.meshView()->camera().eye - through.eye) > 1.0);

        QSignalSpy finished(&window, &MainWindow::exportFinished);
        window.exportAnimation(dir.filePath("app.svg"));
        QVERIFY(finished.wait(180000));
        const QByteArray app = readAll(dir.filePath("app.svg"));
        QVERIFY(app.contains("height=\"450\""));
        const QString project = dir.filePath("shot.snaxels");
        QVERIFY(window.saveProject(project));
        QVERIFY(readAll(project).contains("\"camera\": \"ShotCam\""));
        auto cli = [&](const QStringList& args, const QString& out) {
            QProcess p;
            p.start(QCoreApplication::applicationDirPath() + "/snaxels-cli", args);
            if (!p.waitForFinished(180000) || p.exitCode() != 0) qWarning() << p.readAllStandardError();
            return readAll(out);
        };
        QVERIFY2(cli({"render", project, "-o", dir.filePath("render.svg")}, dir.filePath("render.svg")) == app,
                 "snaxels-cli render of the project writes other bytes");
        QFile style(dir.filePath("style.xml"));
        QVERIFY(style.open(QIODevice::WriteOnly));
        style.write(window.styleEditor()->text().toUtf8());
        style.close();
        QVERIFY2(cli({"animate", scene, "--camera", "ShotCam", "--style", style.fileName(), "-o", dir.filePath("animate.svg")},
                     dir.filePath("animate.svg")) == app,
                 "snaxels-cli animate --camera writes other bytes");

        // A project naming a camera the file lacks opens on the view's camera and says so.
        QByteArray text = readAll(project);
        text.replace("\"camera\": \"ShotCam\"", "\"camera\": \"Gone\"");
        const QString gone = dir.filePath("gone.snaxels");
        QFile goneFile(gone);
        QVERIFY(goneFile.open(QIODevice::WriteOnly));
        goneFile.write(text);
        goneFile.close();
        {
            MainWindow other;
            QVERIFY(showWindow(other, {1000, 700}));
            QSignalSpy loaded(&other, &MainWindow::meshLoaded);
            other.openFile(gone);
            QVERIFY(loaded.wait(60000));
            QTest::qWait(200);
            QVERIFY2(other.statusBar()->currentMessage().contains("no camera \"Gone\""),
                     qPrintable(other.statusBar()->currentMessage()));
            QVERIFY(other.timeline()->spec().camera.empty());
        }

        // Back to the view's camera: the orbit again, the style's square canvas.
        const int turntable = source->findText("Turntable");
        contours.clear();
        source->setCurrentIndex(turntable);
        cameras->setCurrentIndex(0);
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QVERIFY(!window.meshView()->looksThroughFileCamera());
        QVERIFY(window.currentSvg().contains("height=\"800\""));
    }

    // Looking through a file's camera, a left-drag moves nothing: it is no
    // edit (no "Move Camera" step, the project stays saved). Nor is a
    // release over the view whose press it never had (a menu item chosen
    // over it), looking through the file's camera or orbiting.
    void aDragThatMovesNothingIsNoEdit() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/cameras/blender-shot.gltf"));
        auto* cameras = window.timeline()->findChild<QComboBox*>("cameraChoice");
        QComboBox* source = window.timeline()->findChild<QComboBox*>("source");
        QVERIFY(cameras && source);
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        // From the view camera: through the file's still camera, through its
        // moving one, orbiting.
        source->setCurrentIndex(source->findText("Turntable"));
        cameras->setCurrentIndex(0);
        QVERIFY(contours.wait(30000));
        for (const int mode : {0, 1, 2}) {
            contours.clear();
            if (mode == 0) cameras->setCurrentIndex(cameras->findText("Camera: ShotCam"));
            if (mode == 1) source->setCurrentIndex(source->findText("Camera move: ShotCam"));
            if (mode == 2) {
                source->setCurrentIndex(source->findText("Turntable"));
                cameras->setCurrentIndex(0);
            }
            QVERIFY(contours.wait(30000));
            QTest::qWait(100);
            QCOMPARE(window.meshView()->looksThroughFileCamera(), mode < 2);
            QVERIFY(window.saveProject(dir.filePath("shot.snaxels")));
            QVERIFY(!window.isModified());
            const int steps = window.undoStack()->count();
            const snaxels::Camera seen = window.meshView()->camera();
            if (mode < 2) {
                QTest::mousePress(window.meshView(), Qt::LeftButton, {}, QPoint(300, 300));
                QTest::mouseMove(window.meshView(), QPoint(360, 320));
                QTest::mouseRelease(window.meshView(), Qt::LeftButton, {}, QPoint(360, 320));
                QVERIFY(window.meshView()->camera() == seen);
                QVERIFY(window.statusBar()->currentMessage().contains("camera"));
            }
            QCOMPARE(window.undoStack()->count(), steps);
            // A menu over the view closed by a click on it: its press went to
            // the menu, the moves and the release (the button held) come here.
            for (const QPoint at : {QPoint(200, 200), QPoint(240, 230), QPoint(290, 250)}) {
                QMouseEvent move(QEvent::MouseMove, at, window.meshView()->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                                 Qt::NoModifier);
                QApplication::sendEvent(window.meshView(), &move);
            }
            QMouseEvent release(QEvent::MouseButtonRelease, QPoint(290, 250), window.meshView()->mapToGlobal(QPoint(290, 250)),
                                Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
            QApplication::sendEvent(window.meshView(), &release);
            QTest::qWait(50);
            QVERIFY(window.meshView()->camera() == seen);
            QCOMPARE(window.undoStack()->count(), steps);
            QVERIFY2(!window.isModified(), qPrintable(QString("mode %1").arg(mode)));
        }
    }

    // A turntable's degrees per frame, typed in, is saved with the project
    // and shown again when it is reopened.
    void degreesPerFrameSurviveAReopen() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        auto* degrees = window.timeline()->findChild<QDoubleSpinBox*>("degreesPerFrame");
        QVERIFY(degrees && degrees->isEnabled());
        for (const double value : {2.0, 3.5, 1.0}) {
            degrees->setFocus();
            degrees->selectAll();
            QTest::keyClicks(degrees, QString::number(value, 'f', 2));
            QTest::keyClick(degrees, Qt::Key_Return);
            QCOMPARE(degrees->value(), value);
            QCOMPARE(window.document()->animation().degrees_per_frame, value);
            MainWindow reopened;
            QVERIFY(saveAndReopen(window, dir.filePath("turn.snaxels"), reopened));
            auto* shown = reopened.timeline()->findChild<QDoubleSpinBox*>("degreesPerFrame");
            QCOMPARE(shown->value(), value);
            QCOMPARE(reopened.timeline()->spec().degrees_per_frame, value);
            QCOMPARE(reopened.document()->animation().degrees_per_frame, value);
            QVERIFY(!reopened.isModified());
        }
        // Typed and saved straight away (Ctrl+S, no Enter): what the box
        // shows is what is saved.
        degrees->setFocus();
        degrees->selectAll();
        QTest::keyClicks(degrees, "2.00");
        QCOMPARE(degrees->text().left(4), QString("2.00"));
        {
            MainWindow reopened;
            QVERIFY(saveAndReopen(window, dir.filePath("typed.snaxels"), reopened));
            QCOMPARE(reopened.timeline()->findChild<QDoubleSpinBox*>("degreesPerFrame")->value(), 2.0);
            QCOMPARE(reopened.document()->animation().degrees_per_frame, 2.0);
        }
        QCOMPARE(window.document()->animation().degrees_per_frame, 2.0);
        // Reopened in the same window, over another value.
        const QString saved = dir.filePath("turn.snaxels");
        degrees->setFocus();
        degrees->selectAll();
        QTest::keyClicks(degrees, "7.25");
        QTest::keyClick(degrees, Qt::Key_Return);
        QCOMPARE(window.document()->animation().degrees_per_frame, 7.25);
        bool asked = false;
        answerUnsavedPrompt(QMessageBox::Discard, &asked);
        QSignalSpy opened(&window, &MainWindow::projectOpened);
        window.openFile(saved);
        QVERIFY(opened.wait(60000));
        QVERIFY(asked);
        QCOMPARE(degrees->value(), 1.0);
        QCOMPARE(window.document()->animation().degrees_per_frame, 1.0);
        QVERIFY(!window.isModified());
    }

    // Undoing back to the text that was saved leaves the project as saved,
    // however the edits merged: typing on straight after a save is a step
    // of its own, and the text being the saved text is what counts.
    void undoingToTheSavedTextIsUnmodified() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        const QString original = window.styleEditor()->text();
        const QString a = QString(original).replace("</style>", "<!-- a -->\n</style>");
        const QString b = QString(a).replace("<!-- a -->", "<!-- ab -->");
        window.document()->setStyleText(a); // typing, taken up
        QVERIFY(window.saveProject(dir.filePath("typed.snaxels")));
        QVERIFY(!window.isModified());
        window.document()->setStyleText(b); // more typing, at once
        QVERIFY(window.isModified());
        QVERIFY(window.isWindowModified());
        window.undoStack()->undo();
        QCOMPARE(window.document()->styleText(), a);
        QVERIFY(!window.isModified());
        QVERIFY(!window.isWindowModified());
        window.undoStack()->undo(); // before the save
        QCOMPARE(window.document()->styleText(), original);
        QVERIFY(window.isModified());
        // Typed back by hand, the saved text is the saved text.
        QTest::qWait(1600);
        window.document()->setStyleText(a);
        QVERIFY(!window.isModified());
        QVERIFY(!window.isWindowModified());
    }

    // A scene's own objects in the style (hidden, occluders, intersection
    // lines) leave it when another mesh is opened: nothing is left over to
    // warn about on every other model. Patterns stay.
    void anotherMeshDropsTheLastScenesObjects() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/hard/CesiumMilkTruck.gltf"));
        const auto& objects = window.mesh()->objects;
        QVERIFY(objects.size() >= 2);
        const QString part = QString::fromStdString(objects[0].name);
        auto* combo = window.objectsPanel()->findChild<QComboBox*>("state:" + QString::fromStdString(objects[0].path));
        QVERIFY(combo);
        combo->setFocus();
        QTest::keyClick(combo, Qt::Key_End); // Hidden, chosen as a user does
        QVERIFY(window.styleEditor()->text().contains("<object name=\"" + part + "\" hide=\"true\"/>"));
        QString withPattern = window.styleEditor()->text();
        withPattern.replace("</style>", "  <object name=\"tyre*\" draw=\"false\"/>\n</style>");
        window.document()->setStyleText(withPattern);
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        bool asked = false;
        answerUnsavedPrompt(QMessageBox::Discard, &asked);
        window.openMesh(QString(SNAXELS_TEST_ASSETS) + "/spot.obj");
        QVERIFY(asked);
        QVERIFY(loaded.wait(60000));
        QTest::qWait(100);
        const QString text = window.styleEditor()->text();
        QVERIFY2(!text.contains("name=\"" + part + "\""), qPrintable(text));
        QVERIFY(text.contains("<object name=\"tyre*\" draw=\"false\"/>"));
        QCOMPARE(window.document()->styleText(), text);
        auto* status = window.styleEditor()->findChild<QLabel*>("styleStatus");
        QVERIFY(status);
        QVERIFY2(!status->text().contains(part), qPrintable(status->text()));
        QVERIFY(!window.isModified()); // a new untitled document
        QCOMPARE(window.undoStack()->count(), 0);
    }

    // The Objects panel lists the truck's parts; hiding one (chosen with the
    // keyboard on its combo, as a user does) is one undo step that changes
    // the SVG pane, Ctrl+Z brings the drawing back byte for byte, selecting
    // a part tints it in the 3-D view, and a saved project reopens with the
    // part hidden.
    void objectsPanelHidesPartsAndSavesThem() {
        QTemporaryDir dir;
        const QString truck = QString(SNAXELS_TEST_ASSETS) + "/hard/CesiumMilkTruck.gltf";
        MainWindow window;
        QVERIFY(showWithMesh(window, truck));
        QTest::qWait(300);
        auto* dock = window.findChild<QDockWidget*>("objectsDock");
        QVERIFY(dock);
        dock->show();
        dock->raise();
        QTreeWidget* tree = window.objectsPanel()->tree();
        QCOMPARE(tree->topLevelItemCount(), 2);
        QTreeWidgetItem* objects = tree->topLevelItem(0);
        QTreeWidgetItem* materials = tree->topLevelItem(1);
        QCOMPARE(objects->childCount(), 3);
        QCOMPARE(materials->childCount(), 4);
        QStringList names;
        int faces = 0;
        for (int i = 0; i < objects->childCount(); ++i) {
            names << objects->child(i)->text(0);
            faces += objects->child(i)->text(2).toInt();
        }
        QVERIFY2(names.contains("Geometry-mesh001Node") && names.contains("meshInst962Node"), qPrintable(names.join(",")));
        QCOMPARE(faces, int(window.mesh()->mesh.n_faces()));
        QVERIFY2(objects->child(0)->text(3).startsWith("visual"), qPrintable(objects->child(0)->text(3))); // the style's line sets take every part

        // Selecting the wheels tints their faces in the view.
        tree->setCurrentItem(objects->child(1));
        QVERIFY(window.meshView()->highlightTriangles() > 100);

        // Hide the front wheels: Down twice on their combo (Drawn -> Occluder only -> Hidden).
        auto* state = window.objectsPanel()->findChild<QComboBox*>("state:Geometry-mesh002Node/Geometry-mesh001Node");
        QVERIFY(state);
        const QByteArray before = window.currentSvg();
        const int steps = window.undoStack()->count();
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        state->setFocus();
        QTest::keyClick(state, Qt::Key_Down);
        QVERIFY(contours.wait(30000));
        QTest::keyClick(state, Qt::Key_Down);
        QVERIFY(contours.wait(30000));
        QTest::qWait(300);
        QCOMPARE(state->currentIndex(), 2);
        QCOMPARE(window.undoStack()->count(), steps + 2);
        QVERIFY(window.undoStack()->text(window.undoStack()->index() - 1).startsWith("Hide"));
        QVERIFY(window.styleEditor()->text().contains("<object name=\"Geometry-mesh001Node\" hide=\"true\"/>"));
        const QByteArray hidden = window.currentSvg();
        QVERIFY(hidden != before);
        QVERIFY2(hidden.size() < before.size(), "hiding the wheels drew more, not less");

        // Ctrl+Z twice: the drawing as it was.
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        window.meshView()->setFocus();
        QTest::keyClick(window.meshView(), Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(contours.wait(30000));
        QTest::keyClick(window.meshView(), Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(contours.wait(30000));
        QTest::qWait(300);
        QCOMPARE(state->currentIndex(), 0);
        QCOMPARE(window.undoStack()->count(), steps + 2);
        QCOMPARE(window.undoStack()->index(), steps);
        QVERIFY2(window.currentSvg() == before, "undoing did not bring the drawing back");

        // Redo, save, reopen: the wheels stay hidden.
        window.undoStack()->redo();
        window.undoStack()->redo();
        QVERIFY(contours.wait(30000));
        QTest::qWait(300);
        MainWindow reopened;
        QVERIFY(saveAndReopen(window, dir.filePath("truck.snaxels"), reopened));
        QTest::qWait(300);
        auto* again = reopened.objectsPanel()->findChild<QComboBox*>("state:Geometry-mesh002Node/Geometry-mesh001Node");
        QVERIFY(again);
        QCOMPARE(again->currentIndex(), 2);
        QCOMPARE(reopened.objectsPanel()->tree()->topLevelItem(0)->child(1)->text(3), QString("none"));

        // A pattern that names no part of the truck is a warning in the
        // style editor, naming it and the parts the scene has.
        reopened.styleEditor()->setText("<style>\n<contour kind=\"visual\" object=\"Trailer*\"/>\n</style>\n");
        auto* status = reopened.styleEditor()->findChild<QLabel*>("styleStatus");
        QVERIFY(status);
        QVERIFY2(status->text().contains("2:1: warning: object \"Trailer*\" matches none") &&
                     status->text().contains("meshInst962Node"),
                 qPrintable(status->text()));
    }

    // Where objects meet (#55): a click on an object's Meets box in the
    // Objects panel draws its intersection lines in the SVG pane (one
    // undo step, a line set in the style); a second click leaves them out
    // again.
    void objectsPanelDrawsIntersectionLines() {
        const QString sunk = QString(SNAXELS_TEST_ASSETS) + "/meet/sunk.gltf";
        MainWindow window;
        QVERIFY(showWithMesh(window, sunk));
        QTest::qWait(300);
        auto* dock = window.findChild<QDockWidget*>("objectsDock");
        QVERIFY(dock);
        dock->show();
        dock->raise();
        QTreeWidget* tree = window.objectsPanel()->tree();
        QTreeWidgetItem* objects = tree->topLevelItem(0);
        QTreeWidgetItem* ball = objectItem(window, "Ball");
        QVERIFY(ball);
        QCOMPARE(ball->checkState(4), Qt::Unchecked);
        QVERIFY(!window.currentSvg().contains("data-kind=\"intersection\""));
        // Listing the objects edits nothing.
        QVERIFY(!window.isModified());
        QVERIFY2(!window.statusBar()->currentMessage().contains("intersection"), qPrintable(window.statusBar()->currentMessage()));
        const int steps = window.undoStack()->count();
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        // Clicks the check box at the left of the Meets cell (where it is
        // now: the Line sets column beside it grows as line sets are added).
        auto click_meets = [&] {
            tree->scrollToItem(ball);
            tree->scrollTo(tree->model()->index(objects->indexOfChild(ball), 4, tree->model()->index(0, 0)));
            const QRect cell = tree->visualItemRect(ball).intersected(QRect(tree->header()->sectionViewportPosition(4), 0,
                                                                            tree->header()->sectionSize(4), 1 << 20));
            QVERIFY(cell.isValid() && tree->viewport()->rect().contains(cell.center()));
            QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, QPoint(cell.left() + 10, cell.center().y()));
        };
        click_meets();
        QCOMPARE(ball->checkState(4), Qt::Checked);
        QVERIFY2(window.styleEditor()->text().contains("intersection"), qPrintable(window.styleEditor()->text()));
        // (The pane may have its drawing before the click returns.)
        QVERIFY(contours.count() > 0 || contours.wait(30000));
        QTest::qWait(300);
        QCOMPARE(window.undoStack()->count(), steps + 1);
        QVERIFY(window.styleEditor()->text().contains("<contour kind=\"intersection\" object=\"Ball\"/>"));
        QVERIFY2(window.currentSvg().contains("data-kind=\"intersection\""), "no intersection lines in the SVG pane");
        contours.clear();
        QTest::qWait(QApplication::doubleClickInterval() + 100); // a second click, not a double click
        click_meets();
        QVERIFY(contours.count() > 0 || contours.wait(30000));
        QTest::qWait(300);
        QCOMPARE(ball->checkState(4), Qt::Unchecked);
        QVERIFY(!window.styleEditor()->text().contains("kind=\"intersection\""));
        QVERIFY(!window.currentSvg().contains("data-kind=\"intersection\""));
    }

    // A style given on the command line is where the session starts, not an
    // edit: opening the mesh asks nothing, and there is nothing to undo.
    void aStartingStyleIsNoEdit() {
        QFile toon(snaxels::ui::dataDirectory() + "/styles/toon.xml");
        QVERIFY(toon.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(toon.readAll());
        MainWindow window;
        window.setStartingStyle(text, toon.fileName());
        QVERIFY(!window.isModified());
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj")); // no question to answer
        QVERIFY(!window.isModified());
        QVERIFY(!window.undoStack()->canUndo());
        QCOMPARE(window.styleEditor()->text(), text);
        QVERIFY(window.currentSvg().contains("<g id=\"fills\""));
    }

    // What a new user looks for: the style reference under Help, every dock
    // back from the View menu, a Default preset, tooltips on the controls.
    void helpAndDiscovery() {
        MainWindow window;
        QVERIFY(showWindow(window, {1000, 700}));
        QAction* reference = window.findChild<QAction*>("helpStyleReference");
        QVERIFY(reference);
        reference->trigger();
        QTextBrowser* browser = nullptr;
        for (QWidget* w : QApplication::topLevelWidgets())
            if (w->objectName() == "helpBrowser") browser = qobject_cast<QTextBrowser*>(w);
        QVERIFY(browser);
        QVERIFY2(browser->toPlainText().contains("min-derivative"), "the style reference is not what is shown");
        browser->close();

        // A closed dock comes back from the View menu.
        auto* dock = window.findChild<QDockWidget*>("styleDock");
        QVERIFY(dock);
        dock->close();
        QVERIFY(!dock->isVisible());
        QAction* toggle = nullptr;
        for (QAction* menu : window.menuBar()->actions())
            if (QString(menu->text()).remove('&') == "View")
                for (QAction* a : menu->menu()->actions())
                    if (a == dock->toggleViewAction()) toggle = a;
        QVERIFY(toggle);
        toggle->trigger();
        QVERIFY(dock->isVisible());
        QVERIFY(window.findChild<QDockWidget*>("timelineDock"));

        // The Default preset: the style a new window starts with.
        window.styleEditor()->setText("<style version=\"1\"/>");
        QAction* preset = nullptr;
        for (QAction* menu : window.menuBar()->actions())
            if (QString(menu->text()).remove('&') == "Style")
                for (QAction* sub : menu->menu()->actions())
                    if (sub->menu())
                        for (QAction* a : sub->menu()->actions())
                            if (a->text() == "Default") preset = a;
        QVERIFY(preset);
        preset->trigger();
        QCOMPARE(window.styleEditor()->text(), snaxels::ui::initial_style_text());

        // Every control of the timeline and the views says what it does.
        for (QWidget* w : window.timeline()->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
            if (!qobject_cast<QLabel*>(w) && !w->inherits("QLayout"))
                QVERIFY2(!w->toolTip().isEmpty(), w->metaObject()->className());
        QVERIFY(!window.meshView()->toolTip().isEmpty());
        QVERIFY(!window.svgPane()->toolTip().isEmpty());
    }

    // The timeline: a click on the track goes to the click, a typed frame
    // goes there on Enter, and a frame count typed digit by digit takes
    // effect on Enter (not clamping the current frame to its first digit).
    // Point 3 of the first hour: Play keeps wall-clock time when the
    // preview cannot keep up (frames it has no time for are dropped), and
    // says how many frames a second it shows. The horse in the toon preset
    // takes longer than a 24 fps frame to draw on this machine.
    void playKeepsTimeAndReportsItsRate() {
        MainWindow window;
        QVERIFY(showHorseInToon(window));
        window.timeline()->setFrameCount(720); // 30 s: no loop within the test
        window.timeline()->setFrame(0);
        QTest::qWait(500);
        std::vector<qint64> shownAt; // when contours arrived, on the wall clock
        QElapsedTimer wall;
        connect(&window, &MainWindow::contoursUpdated, this, [&] { shownAt.push_back(wall.nsecsElapsed()); });
        QPushButton* play = childWithText<QPushButton>(window.timeline(), tr("Play"));
        QVERIFY(play);
        QCheckBox* every = childWithText<QCheckBox>(window.timeline(), tr("Every frame"));
        QVERIFY(every && !every->isChecked()); // dropping frames is the default
        wall.start();
        QTest::mouseClick(play, Qt::LeftButton);
        QTest::qWait(10000);
        const double seconds = double(wall.nsecsElapsed()) * 1e-9;
        const int frame = window.timeline()->frame();
        const double reported = window.timeline()->shownRate();
        const QString status = window.statusBar()->currentMessage();
        bool shown_beside = false; // the timeline says the rate beside the time
        for (QLabel* label : window.timeline()->findChildren<QLabel*>())
            shown_beside |= label->text().contains(QString(" · %1 fps shown").arg(reported, 0, 'f', 1));
        QTest::mouseClick(play, Qt::LeftButton);
        QVERIFY(shown_beside);
        const double expected = seconds * 24.0;
        std::printf("play: frame %d after %.2f s (%.1f due), %.1f fps reported, %zu frames shown; \"%s\"\n", frame,
                    seconds, expected, reported, shownAt.size(), qPrintable(status));
        QVERIFY2(std::abs(frame - expected) <= 0.05 * expected, qPrintable(QString("frame %1, %2 due").arg(frame).arg(expected)));
        // The rate reported is the rate of frames shown over the last second.
        const double last_second = double(std::count_if(shownAt.begin(), shownAt.end(), [&](qint64 t) {
            return double(t) * 1e-9 > seconds - 1.0;
        }));
        QVERIFY2(reported > 0.0 && std::abs(reported - last_second) <= std::max(2.0, 0.25 * last_second),
                 qPrintable(QString("reported %1 fps, %2 shown in the last second").arg(reported).arg(last_second)));
        if (reported < 0.95 * 24.0) QVERIFY2(status.contains("dropping frames"), qPrintable(status));
        else QVERIFY2(status.contains("full rate"), qPrintable(status));
        QVERIFY(window.statusBar()->currentMessage().isEmpty()); // stopped: the message goes
    }

    // The option: every frame is shown, in order, the preview then running
    // slower than real time (and saying so).
    void playOfEveryFrameShowsEachFrame() {
        MainWindow window;
        QVERIFY(showHorseInToon(window));
        window.timeline()->setFrame(0);
        QTest::qWait(500);
        QCheckBox* every = childWithText<QCheckBox>(window.timeline(), tr("Every frame"));
        QVERIFY(every);
        QTest::mouseClick(every, Qt::LeftButton);
        QVERIFY(window.timeline()->playsEveryFrame());
        std::vector<int> frames; // the timeline's frame at each contour update
        connect(&window, &MainWindow::contoursUpdated, this, [&] { frames.push_back(window.timeline()->frame()); });
        QPushButton* play = childWithText<QPushButton>(window.timeline(), tr("Play"));
        QVERIFY(play);
        QElapsedTimer wall;
        wall.start();
        QTest::mouseClick(play, Qt::LeftButton);
        // At least four seconds of play, and a dozen updates however loaded the machine is.
        QTest::qWait(4000);
        QTRY_VERIFY_WITH_TIMEOUT(frames.size() > 12, 60000);
        const QString status = window.statusBar()->currentMessage();
        const double reported = window.timeline()->shownRate();
        QTest::mouseClick(play, Qt::LeftButton);
        for (std::size_t i = 1; i < frames.size(); ++i)
            QVERIFY2(frames[i] == frames[i - 1] || frames[i] == frames[i - 1] + 1,
                     qPrintable(QString("frame %1 after %2: one was skipped").arg(frames[i]).arg(frames[i - 1])));
        std::printf("every frame: %zu updates up to frame %d in %.1f s, %.1f fps reported; \"%s\"\n", frames.size(),
                    frames.back(), double(wall.elapsed()) / 1000.0, reported, qPrintable(status));
        if (reported < 0.95 * 24.0) QVERIFY2(status.contains("every frame shown"), qPrintable(status));
    }

    // While the camera orbits, the contours drawn at each repaint lie on the
    // mesh's outline (a convex mesh: its visual contour is all outline),
    // read back from the GL view: contours of an earlier camera, still
    // computing their successors, are drawn on the surface against its depth.
    void orbitKeepsContoursOnTheOutline() {
        QTemporaryDir dir;
        const QString path = dir.filePath("ellipsoid.obj");
        QVERIFY(writeEllipsoid(path));
        MainWindow window;
        QVERIFY(showWithMesh(window, path, {1000, 700}));
        window.meshView()->setFrameShown(false); // the background all around
        QTest::qWait(300);
        snaxels::ui::MeshView* view = window.meshView();
        const QImage still = view->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        const double at_rest = contourOffOutline(still);
        QVERIFY2(at_rest >= 0.0 && at_rest <= 2.0, qPrintable(QString("at rest %1 px").arg(at_rest)));
        // A drag of 60 steps of 3 pixels (1.7 degrees each), a repaint read back after each.
        QPoint at(view->width() / 2, view->height() / 2);
        QTest::mousePress(view, Qt::LeftButton, {}, at);
        double worst = 0.0;
        int stale = 0;
        for (int step = 0; step < 60; ++step) {
            at += QPoint(3, step % 3 == 0 ? 1 : 0);
            QMouseEvent move(QEvent::MouseMove, QPointF(at), view->mapToGlobal(QPointF(at)), Qt::NoButton, Qt::LeftButton, {});
            QApplication::sendEvent(view, &move);
            QTest::qWait(15);
            stale += view->contoursStale();
            const QImage frame = view->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
            const double off = contourOffOutline(frame);
            if (step == 30) frame.save(QString(SCREENSHOT_DIR) + "/mainwindow-orbit-step.png");
            QVERIFY2(off >= 0.0, qPrintable(QString("no contour drawn at step %1").arg(step)));
            worst = std::max(worst, off);
        }
        QTest::mouseRelease(view, Qt::LeftButton, {}, at);
        std::printf("orbit: contour pixels at most %.1f px off the outline over 60 repaints (%d with contours of an earlier camera)\n",
                    worst, stale);
        QVERIFY2(worst <= 2.0, qPrintable(QString("%1 px off the outline").arg(worst)));
    }

    // At the window's default size the style dock shows every preset's
    // longest line whole (wrapped at the dock's edge, nothing scrolled out
    // of sight sideways); the screenshots are kept.
    void stylePresetsReadWholeAtTheDefaultSize() {
        MainWindow window; // its own default size
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        std::printf("default window: %dx%d, style dock %d px wide\n", window.width(), window.height(),
                    window.styleEditor()->width());
        QPlainTextEdit* edit = window.styleEditor()->editor();
        const QDir presets(snaxels::ui::dataDirectory() + "/styles");
        const QStringList files = presets.entryList({"*.xml"}, QDir::Files);
        QVERIFY(files.size() >= 8);
        QDir().mkpath(SCREENSHOT_DIR);
        for (const QString& name : files) {
            QFile f(presets.filePath(name));
            QVERIFY(f.open(QIODevice::ReadOnly));
            window.styleEditor()->setText(QString::fromUtf8(f.readAll()));
            QCoreApplication::processEvents();
            QTextBlock longest = edit->document()->firstBlock();
            for (QTextBlock b = longest; b.isValid(); b = b.next())
                if (b.length() > longest.length()) longest = b;
            QTextCursor end(longest);
            end.movePosition(QTextCursor::EndOfBlock);
            edit->setTextCursor(end);
            edit->ensureCursorVisible();
            QCoreApplication::processEvents();
            QCOMPARE(edit->horizontalScrollBar()->maximum(), 0); // nothing to scroll to sideways
            QTextCursor start(longest);
            const QRect first = edit->cursorRect(start), last = edit->cursorRect(end);
            const QRect seen = edit->viewport()->rect();
            QVERIFY2(seen.contains(first.center()) && seen.contains(last.center()),
                     qPrintable(name + ": its longest line (" + QString::number(longest.length()) + " characters) is cut"));
            window.styleEditor()->grab().save(QString(SCREENSHOT_DIR) + "/style-dock-" + QFileInfo(name).baseName() + ".png");
        }
    }

    void timelineTakesClicksAndTypedFrames() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj", {1200, 800}));
        snaxels::ui::Timeline* timeline = window.timeline();
        QCOMPARE(timeline->spec().frames, 180);
        auto* slider = timeline->findChild<QSlider*>();
        QVERIFY(slider);
        QTest::mouseClick(slider, Qt::LeftButton, {}, QPoint(slider->width() * 3 / 4, slider->height() / 2));
        QVERIFY2(std::abs(timeline->frame() - 134) <= 8, qPrintable(QString::number(timeline->frame())));

        QSpinBox* frameBox = nullptr;
        QSpinBox* frames = nullptr;
        for (QSpinBox* box : timeline->findChildren<QSpinBox*>()) {
            if (box->prefix().contains("frame")) frameBox = box;
            if (box->suffix().contains("frames")) frames = box;
        }
        QVERIFY(frameBox && frames);
        QCOMPARE(frameBox->value(), timeline->frame());
        frameBox->setFocus();
        frameBox->selectAll();
        QTest::keyClicks(frameBox, "42");
        QTest::keyClick(frameBox, Qt::Key_Return);
        QCOMPARE(timeline->frame(), 42);
        QCOMPARE(slider->value(), 42);

        timeline->setFrame(100);
        frames->setFocus();
        frames->selectAll();
        QTest::keyClick(frames, Qt::Key_1);
        QCOMPARE(timeline->frame(), 100); // not clamped to 1 frame on the way
        QCOMPARE(timeline->spec().frames, 180);
        QTest::keyClicks(frames, "02");
        QTest::keyClick(frames, Qt::Key_Return);
        QCOMPARE(timeline->spec().frames, 102);
        QCOMPARE(timeline->frame(), 100);
        const QLabel* label = nullptr;
        for (const QLabel* l : timeline->findChildren<QLabel*>())
            if (l->text().contains(" s of ")) label = l;
        QVERIFY(label);
        QVERIFY2(label->text().contains("4.17 s of 4.25 s"), qPrintable(label->text())); // 100 of 102 at 24 fps
    }

    // Export dialogs start in the folder of the last export, with the mesh's
    // name; an export names its whole path in the status bar and offers to
    // show its folder.
    void exportDialogsRemember() {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath("renders"));
        QVERIFY(QFile::copy(QString(SNAXELS_TEST_ASSETS) + "/spot.obj", dir.filePath("spot.obj")));
        MainWindow window;
        QVERIFY(showWithMesh(window, dir.filePath("spot.obj")));
        QTest::qWait(200);
        const QString frame = dir.filePath("renders/first-frame.svg");
        QVERIFY(window.exportFrame(frame));
        const QString message = window.statusBar()->currentMessage();
        QVERIFY2(message.contains(QDir::toNativeSeparators(frame)), qPrintable(message)); // the full path
        auto* reveal = window.findChild<QToolButton*>("revealExport");
        QVERIFY(reveal && reveal->isVisible());
        QVERIFY(reveal->toolTip().contains(QDir::toNativeSeparators(dir.filePath("renders"))));

        // Each export dialog opens there, suggesting the mesh's name.
        const QList<QPair<QString, QString>> dialogs{
            {"exportAnimatedSvg", "spot.svg"}, {"exportLottie", "spot.json"}, {"exportFrame", "spot.svg"}};
        for (const auto& [action, expected] : dialogs) {
            QAction* a = window.findChild<QAction*>(action);
            QVERIFY2(a, qPrintable(action));
            const QString suggested = answerFileDialog([&] { a->trigger(); }, false); // nothing is exported
            QCOMPARE(QFileInfo(suggested).fileName(), expected);
            QCOMPARE(QFileInfo(suggested).absolutePath(), QFileInfo(frame).absolutePath());
        }
    }

    // A glTF with its own clips: the timeline offers them, scrubbing poses
    // the mesh (its contours move) and the export follows the clip.
    void playsTheMeshsOwnClip() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/anim/skinned-bar.gltf", {1000, 700}));
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        auto* source = window.timeline()->findChild<QComboBox*>();
        int clip = -1;
        for (int i = 0; i < source->count() && clip < 0; ++i)
            if (source->itemText(i).startsWith("Clip: ")) clip = i;
        QVERIFY(clip >= 0);
        // The file opens on its own clip, whole: the first Play plays it.
        QCOMPARE(source->currentIndex(), clip);
        QCOMPARE(window.timeline()->spec().kind, snaxels::AnimationSpec::Kind::Clip);
        QVERIFY(window.timeline()->spec().frames > 2); // the clip's length at 24 fps
        QVERIFY(window.document()->animation() == window.timeline()->spec());
        QVERIFY(!window.isModified());
        QVERIFY(contoursSettle(window));
        QTest::qWait(200);
        const QByteArray rest = window.currentSvg();
        contours.clear();
        window.timeline()->setFrame(window.timeline()->spec().frames / 2);
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QVERIFY(window.currentSvg() != rest); // the bar bent
        window.grab().save(QString(SCREENSHOT_DIR) + "/mainwindow-clip.png");

        QTemporaryDir dir;
        QSignalSpy finished(&window, &MainWindow::exportFinished);
        window.exportAnimation(dir.filePath("clip.svg"));
        QVERIFY(finished.wait(120000));
        QVERIFY(readAll(dir.filePath("clip.svg")).contains("<animate attributeName=\"d\""));
        // Back to the turntable: the mesh returns to its loaded pose.
        contours.clear();
        snaxels::AnimationSpec turntable;
        turntable.kind = snaxels::AnimationSpec::Kind::Turntable;
        window.document()->setAnimation(turntable);
        window.timeline()->setFrame(0);
        QVERIFY(contours.wait(30000));
    }

    // A broken mesh, a broken project and an unwritable export leave the
    // document as it was, with a message in the window.
    void badInputLosesNothing() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        window.turnLight(0.3, 0.0);
        QTest::qWait(300);
        const auto* mesh = window.mesh();
        const QString style = window.styleEditor()->text();
        const int steps = window.undoStack()->count();

        QSignalSpy failed(&window, &MainWindow::loadFailed);
        bool asked = false;
        answerUnsavedPrompt(QMessageBox::Discard, &asked); // the light was turned; the file fails anyway
        window.openMesh(QString(SNAXELS_TEST_ASSETS) + "/bad/truncated.ply");
        QVERIFY(failed.wait(30000));
        QVERIFY(asked);
        QVERIFY(!failed.first().first().toString().isEmpty());
        auto* box = window.findChild<QMessageBox*>();
        QVERIFY(box && box->isVisible());
        QVERIFY(box->text().contains("truncated.ply"));
        box->close();
        QCOMPARE(window.mesh(), mesh);
        QCOMPARE(window.styleEditor()->text(), style);
        QCOMPARE(window.undoStack()->count(), steps);

        QFile broken(dir.filePath("broken.snaxels"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{\"format\": \"snaxels-project\", \"version\": 1, \"mesh\": \"nowhere.obj\",");
        broken.close();
        QSignalSpy projectFailed(&window, &MainWindow::projectFailed);
        window.openProject(broken.fileName());
        QCOMPARE(projectFailed.count(), 1);
        QVERIFY(projectFailed.first().first().toString().contains("broken.snaxels"));
        QCOMPARE(window.mesh(), mesh);
        // A project whose mesh is gone: named, and nothing replaced.
        QVERIFY(window.saveProject(dir.filePath("p.snaxels")));
        window.turnLight(0.1, 0.0);
        QFile(dir.filePath("p.snaxels")).copy(dir.filePath("sub.snaxels"));
        QDir(dir.path()).mkpath("elsewhere");
        QVERIFY(QFile::rename(dir.filePath("sub.snaxels"), dir.filePath("elsewhere/moved.snaxels")));
        projectFailed.clear();
        asked = false;
        answerUnsavedPrompt(QMessageBox::Discard, &asked);
        window.openProject(dir.filePath("elsewhere/moved.snaxels"));
        QVERIFY(projectFailed.wait(30000));
        QVERIFY(projectFailed.first().first().toString().contains("moved.snaxels"));
        QCOMPARE(window.mesh(), mesh);
        QCOMPARE(window.styleEditor()->text(), style);

        // Saving where it cannot be written: a message, the document stays unsaved.
        window.turnLight(0.1, 0.0);
        QTimer::singleShot(200, [] {
            if (auto* w = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) w->accept();
        });
        QVERIFY(!window.saveProject(dir.filePath("no-such-folder/p.snaxels")));
        QVERIFY(window.isModified());
    }

    // Files that crash Assimp's readers (and one that declares 500,000,000
    // indices) are read by the snaxels-import helper: each costs that
    // process, the window stays up with a message naming the file, and the
    // document is untouched. The helpers' peak memory stays under 2 GB.
    void importerKillersLoseNothing() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        window.turnLight(0.3, 0.0);
        QTest::qWait(300);
        const auto* mesh = window.mesh();
        const QString style = window.styleEditor()->text();
        const int steps = window.undoStack()->count();
        const bool modified = window.isModified();
        QVERIFY(modified); // the light was turned: every open asks first (Discard), and fails
        AnswerEveryUnsavedPrompt discard(QMessageBox::Discard);
        const QDir dir(QString(SNAXELS_TEST_ASSETS) + "/bad/importer");
        const QStringList files = dir.entryList(QDir::Files, QDir::Name);
        QVERIFY(files.size() >= 11);
        int crashes = 0;
        for (const QString& name : files) {
            QSignalSpy failed(&window, &MainWindow::loadFailed);
            QElapsedTimer clock;
            clock.start();
            window.openMesh(dir.filePath(name));
            QVERIFY2(failed.wait(30000), qPrintable(name));
            QVERIFY2(clock.elapsed() < 10000, qPrintable(name + ": refused after " + QString::number(clock.elapsed()) + " ms"));
            QMessageBox* box = nullptr;
            for (auto* b : window.findChildren<QMessageBox*>())
                if (b->isVisible()) box = b;
            QVERIFY2(box, qPrintable(name));
            QVERIFY2(box->text().contains(name), qPrintable(box->text()));
            crashes += box->text().contains("the mesh reader crashed on this file") ? 1 : 0;
            box->close();
            QVERIFY(window.isVisible());
            QCOMPARE(window.mesh(), mesh);
            QCOMPARE(window.styleEditor()->text(), style);
            QCOMPARE(window.undoStack()->count(), steps);
            QCOMPARE(window.isModified(), modified);
        }
        // Six of them abort Assimp or fault in it (the others are refused by
        // the pre-validation): the helper died, this process did not.
        QCOMPARE(crashes, 6);
        rusage children{};
        getrusage(RUSAGE_CHILDREN, &children);
        QVERIFY2(children.ru_maxrss < 2L * 1024 * 1024, qPrintable(QString::number(children.ru_maxrss) + " KB"));
        // A file that keeps the reader busy past its time limit: a 320,000-face
        // grid under a limit of 2 ms stands in for one that would take minutes.
        // (A fast machine reads the grid in under 0.3 s; starting the helper
        // alone, with Assimp to link, takes longer than 2 ms anywhere.)
        QTemporaryDir scratch;
        const QString grid = scratch.filePath("busy-grid.obj");
        {
            QFile out(grid);
            QVERIFY(out.open(QIODevice::WriteOnly));
            QTextStream s(&out);
            const int n = 400;
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) s << "v " << i << ' ' << j << ' ' << (i * 7 + j * 13) % 10 * 0.1 << '\n';
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const int a = i * (n + 1) + j + 1;
                    s << "f " << a << ' ' << a + 1 << ' ' << a + n + 2 << "\nf " << a << ' ' << a + n + 2 << ' ' << a + n + 1 << '\n';
                }
        }
        qputenv("SNAXELS_IMPORT_SECONDS", "0.002");
        {
            QSignalSpy failed(&window, &MainWindow::loadFailed);
            QElapsedTimer clock;
            clock.start();
            window.openMesh(grid);
            QVERIFY(failed.wait(30000));
            QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
            QVERIFY2(failed.first().first().toString().contains("busy-grid.obj: reading the file took longer than 0.002 s"),
                     qPrintable(failed.first().first().toString()));
        }
        qunsetenv("SNAXELS_IMPORT_SECONDS");
        for (auto* b : window.findChildren<QMessageBox*>())
            if (b->isVisible()) b->close();
        QCOMPARE(window.mesh(), mesh);

        // And the window still works: a good mesh opens.
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        window.openMesh("proc:torus:5000");
        QVERIFY(contours.wait(60000));
        QVERIFY(window.mesh() != mesh);
    }

    // Dropping a mesh file opens it; dropping a project opens the project.
    // A numbered series of mesh files plays on the timeline, is saved in a
    // project relative to it, and reopens and renders (window and
    // snaxels-cli alike) from anywhere.
    void playsAMeshSequence() {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath("shots/blob"));
        const snaxels::TriangleSoup base = snaxels::make_procedural("sphere:3000");
        for (int k = 1; k <= 5; ++k) {
            QFile out(dir.filePath(QString("shots/blob/blob_%1.obj").arg(k, 4, 10, QChar('0'))));
            QVERIFY(out.open(QIODevice::WriteOnly));
            QTextStream s(&out);
            for (const auto& p : base.positions) s << "v " << p.x * (1.0 + 0.3 * k) << ' ' << p.y << ' ' << p.z << '\n';
            for (const auto& t : base.triangles) s << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
        }
        MainWindow window;
        QVERIFY(showWindow(window, {1000, 700}));
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        QVERIFY(window.openSequence(dir.filePath("shots/blob/blob_0003.obj"))); // any of its files
        QVERIFY(contours.wait(60000));
        snaxels::AnimationSpec spec = window.timeline()->spec();
        QCOMPARE(spec.kind, snaxels::AnimationSpec::Kind::Sequence);
        QCOMPARE(spec.frames, 5);
        QCOMPARE(spec.first_file, 1);
        QVERIFY(!window.isModified()); // freshly opened
        QTest::qWait(200);
        const QByteArray first = window.currentSvg();
        contours.clear();
        window.timeline()->setFrame(4); // the widest blob
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QVERIFY(window.currentSvg() != first);
        window.grab().save(QString(SCREENSHOT_DIR) + "/mainwindow-sequence.png");

        // Saved relative to the project; reopened from there, as it was.
        const QString projectFile = dir.filePath("shots/blob.snaxels");
        QVERIFY(window.saveProject(projectFile));
        QFile saved(projectFile);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        const QByteArray text = saved.readAll();
        QVERIFY2(text.contains("\"pattern\": \"blob/blob_####.obj\""), text.constData());
        QVERIFY(!window.isModified());
        QSignalSpy finished(&window, &MainWindow::exportFinished);
        window.exportAnimation(dir.filePath("sequence.svg"));
        QVERIFY(finished.wait(120000));
        const QByteArray exported = readAll(dir.filePath("sequence.svg"));
        QVERIFY(exported.contains("<animate attributeName=\"d\""));

        MainWindow reopened;
        QVERIFY(showWindow(reopened, {900, 600}));
        QSignalSpy opened(&reopened, &MainWindow::projectOpened);
        QSignalSpy reopenedContours(&reopened, &MainWindow::contoursUpdated);
        reopened.openProject(projectFile);
        QVERIFY(opened.wait(60000));
        QVERIFY(reopenedContours.wait(30000));
        QTest::qWait(300);
        QCOMPARE(reopened.timeline()->spec().kind, snaxels::AnimationSpec::Kind::Sequence);
        QCOMPARE(reopened.timeline()->spec().frames, 5);
        QCOMPARE(reopened.timeline()->frame(), 4);
        QVERIFY(!reopened.isModified());
        // The frame shown is the one snaxels-cli renders as a still.
        QProcess still;
        still.setWorkingDirectory(QDir::tempPath());
        still.start(QCoreApplication::applicationDirPath() + "/snaxels-cli",
                    {"render", projectFile, "--still", "--frame", "4", "-o", dir.filePath("still.svg")});
        QVERIFY(still.waitForFinished(180000));
        QVERIFY2(still.exitCode() == 0, still.readAllStandardError().constData());
        QVERIFY2(readAll(dir.filePath("still.svg")) == reopened.currentSvg(), "the window shows another frame than render --still");

        // Switching away and back to the sequence plays its files again.
        auto* source = reopened.timeline()->findChild<QComboBox*>();
        const int sequence = source->currentIndex();
        QVERIFY(source->itemText(sequence).startsWith("Sequence: "));
        source->setCurrentIndex(0);
        reopened.timeline()->setFrameCount(9);
        source->setCurrentIndex(sequence);
        QCOMPARE(reopened.timeline()->spec().frames, 5);

        // snaxels-cli renders it from another working folder.
        QProcess cli;
        cli.setWorkingDirectory(QDir::tempPath());
        cli.start(QCoreApplication::applicationDirPath() + "/snaxels-cli",
                  {"render", projectFile, "-o", dir.filePath("cli.svg")});
        QVERIFY(cli.waitForFinished(180000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        QVERIFY2(readAll(dir.filePath("cli.svg")) == exported, "snaxels-cli render writes other bytes");
        // A file with no number, or with no neighbours, is not a sequence.
        QSignalSpy failed(&reopened, &MainWindow::loadFailed);
        QVERIFY(!reopened.openSequence(QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        QVERIFY(failed.count() == 1 && failed.first().first().toString().contains("no frame number"));
        QVERIFY(QFile::copy(dir.filePath("shots/blob/blob_0001.obj"), dir.filePath("lonely_7.obj")));
        QVERIFY(!reopened.openSequence(dir.filePath("lonely_7.obj")));
        QVERIFY(failed.count() == 2 && failed.last().first().toString().contains("at least two"));
        QCOMPARE(reopened.timeline()->spec().kind, snaxels::AnimationSpec::Kind::Sequence); // nothing changed
        for (QMessageBox* box : reopened.findChildren<QMessageBox*>()) box->close();
    }

    // A globe in the view's corner shows where the light comes from, and
    // turns with it.
    void showsWhereTheLightIs() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        auto* globe = window.meshView()->findChild<QWidget*>("lightGlobe");
        QVERIFY(globe && globe->isVisible());
        QVERIFY(globe->geometry().right() >= window.meshView()->width() - 2); // top right
        auto yellow = [](const QImage& image, QPoint* where) {
            int n = 0;
            QPoint sum;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    if (c.red() > 200 && c.green() > 160 && c.blue() < 140) ++n, sum += QPoint(x, y);
                }
            if (n) *where = sum / n;
            return n;
        };
        QTest::qWait(200);
        QPoint before, after;
        QVERIFY(yellow(globe->grab().toImage(), &before) > 10);
        // The default light is the viewer's upper left: the dot is left of
        // and above the globe's middle.
        QVERIFY2(before.x() < globe->width() - 32 && before.y() < 30, qPrintable(QString("%1,%2").arg(before.x()).arg(before.y())));
        window.turnLight(1.2, 0.0); // toward the right
        QTest::qWait(300);
        QVERIFY(yellow(globe->grab().toImage(), &after) > 10);
        QVERIFY2(after.x() > before.x() + 5, qPrintable(QString("%1 -> %2").arg(before.x()).arg(after.x())));
    }

    // The view is shaded by the document's light, not a headlight: the lit
    // side of a sphere follows the light turned by 180 degrees; during an
    // orbiting-light animation the globe shows the light moving.
    void shadingFollowsTheLight() {
        MainWindow window;
        QVERIFY(showWithMesh(window, "proc:sphere:20000"));
        window.meshView()->setFrameShown(false); // the background all around
        window.regionsAction()->setChecked(false);
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        // Brightness of the sphere's left and right halves in the framebuffer.
        auto halves = [&]() {
            const QImage image = window.meshView()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
            double left = 0.0, right = 0.0;
            const int mid = image.width() / 2;
            const QRgb background = image.pixel(0, 0);
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QRgb c = image.pixel(x, y);
                    if (c != background) (x < mid ? left : right) += qGray(c); // the sphere's pixels
                }
            return std::pair<double, double>(left, right);
        };
        window.turnLight(-1.2, 0.0); // toward the viewer's left
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        const auto [l0, r0] = halves();
        QVERIFY2(l0 > 1.1 * r0, qPrintable(QString("left %1, right %2").arg(l0).arg(r0)));
        window.turnLight(kPi, 0.0); // half a turn about the screen's up axis
        contours.clear();
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        const auto [l1, r1] = halves();
        QVERIFY2(r1 > 1.1 * l1, qPrintable(QString("left %1, right %2").arg(l1).arg(r1)));

        // An orbiting light: the globe's dot moves from frame to frame.
        auto* globe = window.meshView()->findChild<QWidget*>("lightGlobe");
        QVERIFY(globe);
        auto* source = window.timeline()->findChild<QComboBox*>();
        source->setCurrentIndex(source->findText("Orbiting light"));
        QCOMPARE(window.timeline()->spec().kind, snaxels::AnimationSpec::Kind::LightOrbit);
        contours.clear();
        window.timeline()->setFrame(0);
        QTest::qWait(300);
        const QImage first = globe->grab().toImage();
        contours.clear();
        window.timeline()->setFrame(30); // 60 degrees on
        QVERIFY(contours.wait(30000));
        QTest::qWait(200);
        QVERIFY(globe->grab().toImage() != first);
    }

    // Region colouring in the 3-D view classes the surface as the maps do
    // (region.h), every band of the style: twelve bands of twelve hues on a
    // sphere, each seen, the ninth to twelfth too.
    void coloursEveryBandInTheView() {
        MainWindow window;
        QVERIFY(showWithMesh(window, "proc:sphere:20000"));
        QString style = "<style version=\"1\">\n  <region class=\"lit\" fill=\"#808080\"/>\n"
                        "  <region class=\"shadow\" fill=\"#404040\"/>\n";
        constexpr int kBands = 12;
        for (int i = 0; i < kBands; ++i)
            style += QString("  <region class=\"band\" k=\"%1\" fill=\"%2\"/>\n")
                         .arg(0.04 + 0.075 * i)
                         .arg(QColor::fromHsv(30 * i, 255, 255).name());
        style += "  <contour kind=\"visual\"><visible stroke=\"#000000\" width=\"1\"/></contour>\n</style>\n";
        window.styleEditor()->setText(style);
        QVERIFY2(window.styleEditor()->problem().isEmpty(), qPrintable(window.styleEditor()->problem()));
        QTRY_VERIFY_WITH_TIMEOUT(!window.contoursBusy(), 30000);
        window.regionsAction()->setChecked(true);
        QTest::qWait(300);
        const QImage image = window.meshView()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        image.save(QString(SCREENSHOT_DIR) + "/mainwindow-twelve-bands.png");
        std::vector<int> pixels(kBands, 0);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (c.hsvSaturation() < 200 || c.value() < 100) continue; // grey tones, outlines, background
                const int hue = c.hsvHue();
                for (int i = 0; i < kBands; ++i) {
                    const int d = std::abs(hue - 30 * i);
                    if (std::min(d, 360 - d) <= 6) ++pixels[std::size_t(i)];
                }
            }
        QString counts;
        for (int i = 0; i < kBands; ++i) counts += QString(" %1").arg(pixels[std::size_t(i)]);
        for (int i = 0; i < kBands; ++i)
            QVERIFY2(pixels[std::size_t(i)] > 30, qPrintable("pixels per band:" + counts));
        window.regionsAction()->setChecked(false);
    }

    void opensWhatIsDropped() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        QVERIFY(window.saveProject(dir.filePath("dropped.snaxels")));
        auto drop = [&](const QString& path) {
            QMimeData data;
            data.setUrls({QUrl::fromLocalFile(path)});
            QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(&window, &enter);
            QVERIFY(enter.isAccepted());
            QDropEvent event(QPointF(50, 50), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(&window, &event);
        };
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        drop(QString(SNAXELS_TEST_ASSETS) + "/fandisk.obj");
        QVERIFY(loaded.wait(60000));
        QCOMPARE(window.mesh()->report.faces, std::size_t(12946));
        QVERIFY(window.projectPath().isEmpty()); // a new untitled document
        QVERIFY(!window.isModified());           // with nothing to save: opening the project asks nothing
        QSignalSpy opened(&window, &MainWindow::projectOpened);
        drop(dir.filePath("dropped.snaxels"));
        QVERIFY(opened.wait(60000));
        QCOMPARE(window.mesh()->report.vertices, std::size_t(2930)); // spot again
        QCOMPARE(window.projectPath(), dir.filePath("dropped.snaxels"));
    }

    // A save killed at any moment (SIGKILL to a helper process that saves
    // the project over and over) leaves the earlier project file, byte for
    // byte, or a complete new one.
    void projectSaveSurvivesKill() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("scene.snaxels");
        snaxels::Project earlier_project;
        earlier_project.mesh = "proc:torus:20000";
        earlier_project.style = "<style version=\"1\"/>\n";
        snaxels::write_project(path.toStdString(), earlier_project);
        const QByteArray earlier = readAll(path);
        QVERIFY(!earlier.isEmpty());
        int kept = 0, complete = 0;
        for (int round = 0; round < 20; ++round) {
            QFile::remove(path);
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(earlier);
            f.close();
            QProcess helper;
            helper.start(QCoreApplication::applicationFilePath(), {"--save-helper", path});
            QVERIFY(helper.waitForStarted(10000));
            // Killed while it saves: after 0 to 40 ms of saving.
            QVERIFY(helper.waitForReadyRead(60000));
            QTest::qWait(2 * round);
            helper.kill(); // SIGKILL
            QVERIFY(helper.waitForFinished(10000));
            const QByteArray now = readAll(path);
            if (now == earlier) {
                ++kept;
                continue;
            }
            snaxels::Project p;
            try {
                p = snaxels::read_project(path.toStdString());
            } catch (const std::exception& e) {
                QFAIL(qPrintable(QString("round %1: the project file is broken: %2").arg(round).arg(e.what())));
            }
            QCOMPARE(p.mesh, std::string("proc:torus:20000"));
            QVERIFY2(QString::fromStdString(p.style).contains("helper save"), p.style.c_str());
            ++complete;
        }
        qInfo("20 kills: %d left the earlier project, %d a complete new one", kept, complete);
        QVERIFY(complete > 0);
        // No temporaries stay once a save has run after the kills.
        MainWindow window;
        QVERIFY(showWithMesh(window, "proc:torus:20000"));
        QVERIFY(window.saveProject(path));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"scene.snaxels"});
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

    // The document alone is the scene: a Document made without any widget,
    // given by its setters every kind of state the window's widgets edited
    // (style, view, light, animation, frame), exports the very bytes the
    // window exports, saves the window's project, and reloaded from that
    // file exports and saves them again.
    void theDocumentAloneExportsWhatTheWindowExports() {
        QTemporaryDir dir;
        const QString scene = QString(SNAXELS_TEST_ASSETS) + "/cameras/blender-shot.gltf";
        MainWindow window;
        QVERIFY(showWithMesh(window, scene));
        QSignalSpy contours(&window, &MainWindow::contoursUpdated);
        // Every kind of edit, each through its widget (from the view
        // camera's turntable: the file opens through its camera).
        window.timeline()->findChild<QComboBox*>("source")->setCurrentIndex(
            window.timeline()->findChild<QComboBox*>("source")->findText("Turntable"));
        window.timeline()->findChild<QComboBox*>("cameraChoice")->setCurrentIndex(0);
        QVERIFY(contoursSettle(window));
        QFile toon(snaxels::ui::dataDirectory() + "/styles/toon.xml");
        QVERIFY(toon.open(QIODevice::ReadOnly));
        window.styleEditor()->setText(QString::fromUtf8(toon.readAll()));
        window.findChild<QAction*>("viewLeft")->trigger();
        QTest::mousePress(window.meshView(), Qt::LeftButton, {}, QPoint(300, 300));
        QTest::mouseMove(window.meshView(), QPoint(340, 310));
        QTest::mouseRelease(window.meshView(), Qt::LeftButton, {}, QPoint(340, 310));
        window.turnLight(0.4, -0.2);
        auto* degrees = window.timeline()->findChild<QDoubleSpinBox*>("degreesPerFrame");
        degrees->setFocus();
        degrees->selectAll();
        QTest::keyClicks(degrees, "9.00");
        QTest::keyClick(degrees, Qt::Key_Return);
        window.timeline()->setFrameCount(6);
        window.timeline()->setFrame(4);
        QVERIFY(contoursSettle(window));
        const snaxels::ui::Document& shown = *window.document();
        QCOMPARE(shown.animation().degrees_per_frame, 9.0);
        QCOMPARE(shown.animation().frames, 6);
        QCOMPARE(shown.frame(), 4);
        QVERIFY(shown.light().has_value());
        // Left, then dragged 40 px to the right and 10 down: 0.01 rad a pixel.
        const snaxels::OrbitView left = snaxels::preset_view(shown.view(), *snaxels::find_named_view("left"));
        QVERIFY(std::abs(shown.view().yaw - (left.yaw + 0.4)) < 1e-9);
        QVERIFY(std::abs(shown.view().pitch - (left.pitch + 0.1)) < 1e-9);
        QVERIFY(shown.styleText() != snaxels::ui::initial_style_text());
        QSignalSpy finished(&window, &MainWindow::exportFinished);
        window.exportAnimation(dir.filePath("window.svg"));
        QVERIFY(finished.wait(180000));
        QVERIFY(window.saveProject(dir.filePath("window.snaxels")));

        // The same scene read by the loader alone, and a document with no window.
        snaxels::ui::MeshLoader loader;
        snaxels::ui::LoadResult result;
        QObject::connect(&loader, &snaxels::ui::MeshLoader::finished, [&](const snaxels::ui::LoadResult& r) { result = r; });
        QVERIFY(loader.load(scene));
        QTRY_VERIFY_WITH_TIMEOUT(!loader.loading(), 60000);
        QVERIFY(result.mesh);
        snaxels::ui::SceneFacts facts{result.scene->clips, result.scene->cameras, result.geometry->centre,
                                      result.geometry->radius};
        auto exported = [&](const snaxels::ui::Document& doc, const QString& name) {
            snaxels::AnimationJob job = doc.animationJob();
            if (!snaxels::set_output(job, dir.filePath(name).toStdString())) return QByteArray();
            snaxels::run_animation(*doc.mesh(), doc.meshSpec().toStdString(), job);
            return readAll(dir.filePath(name));
        };
        snaxels::ui::Document alone(snaxels::ui::initial_style_text());
        alone.startNew(scene, result.mesh, facts, snaxels::ui::initial_animation());
        alone.setStyleText(shown.styleText());
        alone.setView(shown.view());
        alone.setLight(shown.light());
        alone.setAnimation(shown.animation());
        alone.setFrame(shown.frame());
        const QByteArray windowSvg = readAll(dir.filePath("window.svg"));
        QVERIFY(windowSvg.size() > 1000);
        QVERIFY2(exported(alone, "alone.svg") == windowSvg, "the document alone exports other bytes than the window");
        alone.save(dir.filePath("alone.snaxels"));
        QCOMPARE(readAll(dir.filePath("alone.snaxels")), readAll(dir.filePath("window.snaxels")));

        // Reloaded from the window's project: the same export and the same file.
        snaxels::ui::Document reloaded(snaxels::ui::initial_style_text());
        const snaxels::Project project = snaxels::read_project(dir.filePath("window.snaxels").toStdString());
        QVERIFY(reloaded.load(project, dir.filePath("window.snaxels"), scene, result.mesh, facts).isEmpty());
        QVERIFY(!reloaded.isModified());
        QVERIFY(reloaded.edited() == shown.edited());
        QCOMPARE(reloaded.frame(), shown.frame());
        QVERIFY2(exported(reloaded, "reloaded.svg") == windowSvg, "the reloaded project exports other bytes");
        reloaded.save(dir.filePath("reloaded.snaxels"));
        QCOMPARE(readAll(dir.filePath("reloaded.snaxels")), readAll(dir.filePath("window.snaxels")));
    }


    // File > Revert reads the project again (after asking), Close leaves a
    // window without a mesh, New opens the default scene with the default
    // style; each by its key, and Save As has Ctrl+Shift+S.
    void fileRevertCloseAndNew() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        window.activateWindow();
        const QString project = dir.filePath("spot.snaxels");
        window.styleEditor()->setText("<style version=\"1\"><contour kind=\"visual\"/></style>");
        QVERIFY(window.saveProject(project));
        window.turnLight(0.4, 0.0);
        QVERIFY(window.isModified());
        QSignalSpy opened(&window, &MainWindow::projectOpened);
        QTimer::singleShot(300, [] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (box && box->objectName() == "revertBox") box->button(QMessageBox::Discard)->click();
        });
        window.findChild<QAction*>("revert")->trigger();
        QVERIFY(opened.wait(60000));
        QVERIFY(!window.isModified());
        QVERIFY(!window.userLight().has_value()); // as saved
        QCOMPARE(window.styleEditor()->text(), QString("<style version=\"1\"><contour kind=\"visual\"/></style>"));

        // Close (Ctrl+W): no mesh, nothing drawn, and it says why.
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        window.meshView()->setFocus();
        QTest::keySequence(window.meshView(), QKeySequence::Close);
        QTest::qWait(100);
        QVERIFY(!window.mesh());
        QVERIFY(window.currentSvg().isEmpty());
        QVERIFY2(window.frameProblem().contains("No mesh"), qPrintable(window.frameProblem()));
        QVERIFY(window.projectPath().isEmpty());
        QVERIFY(!window.isModified());

        // New (Ctrl+N): the default scene, the default style, untitled.
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        QTest::keySequence(window.meshView(), QKeySequence::New);
        QVERIFY(loaded.wait(60000));
        QCOMPARE(QFileInfo(loaded.first().first().toString()).fileName(), QFileInfo(snaxels::ui::defaultScenePath()).fileName());
        QCOMPARE(window.styleEditor()->text(), snaxels::ui::initial_style_text());
        QVERIFY(!window.isModified());
        QVERIFY(window.projectPath().isEmpty());

        QAction* saveAs = nullptr;
        for (QAction* a : window.findChildren<QAction*>())
            if (a->text() == QString("Save Project &As…")) saveAs = a;
        QVERIFY(saveAs);
        QCOMPARE(saveAs->shortcut(), QKeySequence(QKeySequence::SaveAs).isEmpty() ? QKeySequence("Ctrl+Shift+S")
                                                                                   : QKeySequence(QKeySequence::SaveAs));
        QVERIFY(!saveAs->shortcut().isEmpty());
    }


    // At 1280 x 800, with a file that has cameras and a camera move, every
    // timeline control shows inside the window, the scrubber is at least
    // 200 px wide, and nothing moves sideways when play starts or stops.
    void timelineFitsAt1280x800() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/cameras/blender-shot.gltf", {1280, 800}));
        QTest::qWait(200);
        window.grab().save(QString(SCREENSHOT_DIR) + "/mainwindow-1280x800.png");
        const QRect inside = window.rect();
        int controls = 0;
        for (QWidget* w : window.timeline()->findChildren<QWidget*>()) {
            const bool control = qobject_cast<QAbstractButton*>(w) || qobject_cast<QComboBox*>(w) ||
                                 qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QSlider*>(w);
            if (!control || !w->isVisibleTo(window.timeline())) continue;
            const QRect at(w->mapTo(&window, QPoint(0, 0)), w->size());
            QVERIFY2(inside.contains(at), qPrintable(QString("%1 at %2,%3 %4x%5 is not inside the window")
                                                         .arg(w->metaObject()->className())
                                                         .arg(at.x()).arg(at.y()).arg(at.width()).arg(at.height())));
            QVERIFY2(w->width() >= 20 && w->height() >= 12, w->metaObject()->className());
            ++controls;
        }
        QVERIFY(controls >= 10); // source, camera, degrees, from, frames, fps, loop, every frame, play, scrubber, frame
        auto* slider = window.timeline()->findChild<QSlider*>();
        QVERIFY(slider);
        QVERIFY2(slider->width() >= 200, qPrintable(QString::number(slider->width())));
        QPushButton* play = nullptr;
        for (QPushButton* b : window.timeline()->findChildren<QPushButton*>())
            if (b->text() == "Play") play = b;
        QVERIFY(play);
        const QPoint playAt = play->mapTo(&window, QPoint(0, 0)), sliderAt = slider->mapTo(&window, QPoint(0, 0));
        const int sliderWidth = slider->width();
        window.timeline()->togglePlay();
        QTest::qWait(300);
        QCOMPARE(play->text(), QString("Pause"));
        QCOMPARE(play->mapTo(&window, QPoint(0, 0)), playAt);
        QCOMPARE(slider->mapTo(&window, QPoint(0, 0)), sliderAt);
        QCOMPARE(slider->width(), sliderWidth);
        window.timeline()->togglePlay();
        QTest::qWait(100);
        QCOMPARE(slider->width(), sliderWidth);
    }


    // Home frames the model as it is posed: panned out of the view, or a
    // clip's frame, it comes back whole inside the view.
    void homeFramesThePosedModel() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/anim/skinned-bar.gltf", {1000, 700}));
        QVERIFY(contoursSettle(window));
        window.timeline()->setFrame(window.document()->animation().frames / 2); // bent
        QVERIFY(contoursSettle(window));
        snaxels::ui::MeshView* view = window.meshView();
        view->setFrameShown(false); // the background all around
        // Pan it out of sight with a right drag.
        QTest::mousePress(view, Qt::RightButton, {}, QPoint(100, 100));
        for (int x = 120; x <= 900; x += 60) QTest::mouseMove(view, QPoint(x, 100));
        QTest::mouseRelease(view, Qt::RightButton, {}, QPoint(900, 100));
        QTest::qWait(100);
        const QRect away = inkBox(view->grabFramebuffer());
        const QRect inside = QRect(QPoint(0, 0), view->grabFramebuffer().size()).adjusted(2, 2, -2, -2);
        QVERIFY2(away.isEmpty() || !inside.contains(away), "the drag did not take the model out of the view");
        window.findChild<QAction*>("resetCamera")->trigger();
        QVERIFY(contoursSettle(window));
        QTest::qWait(100);
        const QRect home = inkBox(view->grabFramebuffer());
        QVERIFY2(!home.isEmpty() && inside.contains(home),
                 qPrintable(QString("ink %1,%2 %3x%4").arg(home.x()).arg(home.y()).arg(home.width()).arg(home.height())));
        QVERIFY(home.width() > inside.width() / 4 || home.height() > inside.height() / 4); // framed, not a speck
    }


    // Restyling one object from the Objects panel: a colour and a width from
    // its Lines button write its own line set (each one undo step, shown in
    // the style's text), and the frame the pane shows draws that object's
    // outline in that colour.
    void objectsPanelRestylesOneObject() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/hard/CesiumMilkTruck.gltf"));
        QVERIFY(contoursSettle(window));
        const auto& objects = window.mesh()->objects;
        QVERIFY(objects.size() >= 2);
        const QString name = QString::fromStdString(objects[0].name);
        auto* button = window.objectsPanel()->findChild<QToolButton*>("lines:" + QString::fromStdString(objects[0].path));
        QVERIFY(button);
        const int steps = window.undoStack()->count();
        QTimer::singleShot(300, [] {
            if (auto* dialog = qobject_cast<QColorDialog*>(QApplication::activeModalWidget())) {
                dialog->setCurrentColor(QColor("#cc2200"));
                dialog->accept();
            }
        });
        button->menu()->findChild<QAction*>("linesColour")->trigger();
        QCOMPARE(window.undoStack()->count(), steps + 1);
        QTest::qWait(1600); // past the merge window: the width is a step of its own
        button->menu()->findChild<QAction*>("linesWidth3")->trigger();
        QCOMPARE(window.undoStack()->count(), steps + 2);
        QVERIFY(contoursSettle(window));
        QTest::qWait(200);
        const QString text = window.styleEditor()->text();
        QVERIFY2(text.contains("<contour kind=\"visual\" object=\"" + name + "\"><visible stroke=\"#cc2200\" width=\"3\"/>"),
                 qPrintable(text));
        const QByteArray svg = window.currentSvg();
        const qsizetype group = svg.indexOf(("data-label=\"visual object=" + name + "\"").toUtf8());
        QVERIFY2(group >= 0, "no group for the object's line set");
        const QByteArray tag = svg.mid(group, svg.indexOf('>', group) - group);
        QVERIFY2(tag.contains("stroke=\"#cc2200\"") && tag.contains("stroke-width=\"3\""), tag.constData());
        const qsizetype path = svg.indexOf("<path", group), close = svg.indexOf("</g>", group);
        QVERIFY2(path > group && path < close, "the object's line set draws nothing");
        // Undone twice: the style as it was.
        window.undoStack()->undo();
        window.undoStack()->undo();
        QVERIFY(!window.styleEditor()->text().contains("object=\"" + name + "\"><visible"));
    }


    // Export > Video asks the video's size and quality, remembers them, and
    // the file written has that size (ffprobe reads it).
    // View > Orthographic and the axonometric presets: one undo step each,
    // the engine's camera parallel along the view, kept by Home and by the
    // project file; Field of View keeps what the view frames.
    void orthographicAndAxonometricViews() {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        auto action = [&](const char* name) {
            QAction* a = window.findChild<QAction*>(name);
            if (!a) qFatal("no action %s", name);
            return a;
        };
        QVERIFY(!action("orthographic")->isChecked());
        QVERIFY(!window.meshView()->camera().orthographic());
        const int steps = window.undoStack()->count();
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QTest::keyClick(window.meshView(), Qt::Key_O, Qt::ControlModifier | Qt::ShiftModifier); // the menu's key
        QVERIFY(action("orthographic")->isChecked());
        QVERIFY(window.document()->view().orthographic);
        const snaxels::Camera ortho = window.meshView()->camera();
        QVERIFY(ortho.orthographic());
        QCOMPARE(ortho.ortho_height, snaxels::orbit_view_height(window.document()->view()));
        QCOMPARE(window.undoStack()->count(), steps + 1);
        window.undoStack()->undo();
        QVERIFY(!action("orthographic")->isChecked() && !window.meshView()->camera().orthographic());

        // Isometric: the command line's iso direction, orthographic.
        action("viewIso")->trigger();
        QCOMPARE(window.undoStack()->count(), steps + 1);
        QVERIFY(action("orthographic")->isChecked());
        const snaxels::NamedView& iso = *snaxels::find_named_view("iso");
        QVERIFY(glm::length(window.meshView()->camera().forward() - snaxels::view_dir_at(window.document()->view().up, iso.yaw, iso.pitch)) < 1e-9);
        window.meshView()->resetCamera(); // Home keeps the projection
        QVERIFY(window.document()->view().orthographic);

        // Field of view: asked in degrees; the framing at the orbited point stays.
        const double height = snaxels::orbit_view_height(window.document()->view());
        QTimer poll;
        poll.setInterval(20);
        QObject::connect(&poll, &QTimer::timeout, [&] {
            auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            poll.stop();
            dialog->setDoubleValue(20.0);
            dialog->accept();
        });
        poll.start();
        action("fieldOfView")->trigger();
        QCOMPARE(window.document()->view().fov_deg, 20.0);
        QVERIFY(std::abs(snaxels::orbit_view_height(window.document()->view()) - height) < 1e-9 * height);

        // Saved and read back.
        const QString project = dir.filePath("iso.snaxels");
        window.document()->save(project);
        const snaxels::Project read = snaxels::read_project(project.toStdString());
        QVERIFY(read.view.orthographic);
        QCOMPARE(read.view.fov_deg, 20.0);
    }

    // Export > Page Setup on the milk truck's isometric view: A4 landscape
    // at 1:30, written into the style's <canvas> as one undo step; the frame
    // exported as PDF is an A4 landscape page whose vertical edges are
    // parallel, as poppler reads them (the command line's check).
    void isometricTruckOnAnA4PageAtScale() {
        if (QStandardPaths::findExecutable("pdfinfo").isEmpty()) QSKIP("poppler-utils is not installed");
        QTemporaryDir dir;
        QSettings().setValue(snaxels::ui::kExportFolder, dir.path());
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/hard/CesiumMilkTruck.gltf"));
        window.findChild<QAction*>("viewIso")->trigger();
        QVERIFY(contoursSettle(window));
        const int steps = window.undoStack()->count();
        bool asked = false;
        QTimer poll;
        poll.setInterval(20);
        QObject::connect(&poll, &QTimer::timeout, [&] {
            auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            if (!dialog || dialog->objectName() != "pageSetup") return;
            poll.stop();
            asked = true;
            auto pick = [&](const char* name, const QString& data) {
                auto* box = dialog->findChild<QComboBox*>(name);
                box->setCurrentIndex(box->findData(data));
                QVERIFY(box->currentIndex() >= 0);
            };
            pick("paper", "A4");
            pick("orientation", "landscape");
            pick("size", "scale");
            dialog->findChild<QDoubleSpinBox*>("scale")->setValue(30.0);
            QVERIFY(dialog->findChild<QLabel*>("pageSummary")->text().contains("297 × 210 mm"));
            dialog->accept();
        });
        poll.start();
        window.findChild<QAction*>("pageSetup")->trigger();
        QVERIFY(asked);
        const QString style = window.document()->styleText();
        QVERIFY2(style.contains("paper=\"A4\"") && style.contains("orientation=\"landscape\"") &&
                     style.contains("scale=\"1:30\""),
                 qPrintable(style));
        QCOMPARE(window.undoStack()->count(), steps + 1);
        QCOMPARE(window.document()->style().width, 1123);
        QVERIFY(contoursSettle(window));
        QSignalSpy finished(&window, &MainWindow::exportFinished);
        const QString pdf = answerFileDialog([&] { window.findChild<QAction*>("exportFramePdf")->trigger(); }, true);
        QVERIFY(QFileInfo(pdf).suffix() == "pdf");
        QCOMPARE(finished.count(), 1);
        QProcess check;
        check.start("python3", {QString(SNAXELS_TEST_SCRIPTS) + "/page_pdf_test.py", "--check", pdf});
        QVERIFY(check.waitForFinished(60000));
        const QString said = QString::fromUtf8(check.readAllStandardOutput() + check.readAllStandardError());
        qInfo("%s", qPrintable(said.trimmed()));
        QVERIFY2(check.exitCode() == 0, qPrintable(said));
        // A preset chosen keeps the page.
        QAction* toon = nullptr;
        for (QAction* a : window.findChildren<QAction*>())
            if (a->text() == "toon") toon = a;
        QVERIFY(toon);
        toon->trigger();
        QTRY_VERIFY(window.document()->styleText().contains("#f6c86b")); // the toon preset's
        QVERIFY(window.document()->styleText().contains("paper=\"A4\"") && window.document()->style().page.scale == 30.0);
        window.undoStack()->undo(); // the preset
        window.undoStack()->undo(); // the page goes with one undo
        QVERIFY(!window.document()->styleText().contains("paper="));
    }

    // Through the still life's 16:9 camera, the 3-D view's frame shows the
    // picture the drawing shows. Object by object (the others hidden by the
    // style), the object's pixels in a grab of the 3-D view, mapped from
    // the frame to the canvas, and the ink of the SVG rendered by QtSvg have
    // bounding boxes whose edges agree within 2% of the frame's width.
    void theViewsFrameShowsTheDrawingsPicture() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/meet/still-life.gltf"));
        QVERIFY(window.meshView()->looksThroughFileCamera()); // the file's first look: its camera
        const auto parts = snaxels::loaded_parts(*window.document()->mesh());
        QVERIFY(parts);
        double worst = 0.0;
        QString worstObject;
        for (const snaxels::SceneObject& object : parts->objects) {
            if (object.name == "Floor") continue; // larger than the frame: cut by it in both
            QString style = "<style><canvas width=\"800\" height=\"800\"/><contour kind=\"visual\"/>";
            for (const snaxels::SceneObject& other : parts->objects)
                if (other.name != object.name) style += QString("<object name=\"%1\" hide=\"true\"/>").arg(QString::fromStdString(other.name));
            window.document()->setStyleText(style + "</style>");
            QVERIFY(contoursSettle(window));
            QTest::qWait(50);
            // The 3-D view: pixels other than the background inside the frame.
            const QImage view = window.meshView()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
            const QRectF frame = window.meshView()->frameRect();
            const QRgb background = qRgb(41, 43, 48);
            auto inkBox = [](const QImage& image, const QRect& within, auto&& isInk) {
                int x0 = INT_MAX, y0 = INT_MAX, x1 = -1, y1 = -1;
                for (int y = within.top(); y <= within.bottom(); ++y)
                    for (int x = within.left(); x <= within.right(); ++x)
                        if (isInk(image.pixel(x, y))) {
                            x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
                        }
                return QRectF(QPointF(x0, y0), QPointF(x1 + 1, y1 + 1));
            };
            auto far = [](QRgb a, QRgb b) {
                return std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b)) > 24;
            };
            const QRect inside = frame.toAlignedRect().adjusted(2, 2, -2, -2) & view.rect();
            const QRectF seen = inkBox(view, inside, [&](QRgb p) { return far(p, background); });
            // The drawing: its SVG rendered at the canvas's size.
            QSvgRenderer svg(window.currentSvg());
            QVERIFY(svg.isValid());
            const QSize canvas = svg.viewBox().size();
            QCOMPARE(canvas, QSize(800, 450)); // the camera's 16:9
            QImage drawn(canvas, QImage::Format_RGB32);
            drawn.fill(Qt::white);
            QPainter painter(&drawn);
            svg.render(&painter);
            painter.end();
            const QRectF ink = inkBox(drawn, drawn.rect(), [&](QRgb p) { return far(p, qRgb(255, 255, 255)); });
            QVERIFY2(ink.isValid() && seen.isValid(), qPrintable(QString::fromStdString(object.name)));
            // The view's box in canvas pixels.
            const double k = canvas.width() / frame.width();
            const QRectF mapped((seen.left() - frame.left()) * k, (seen.top() - frame.top()) * k, seen.width() * k,
                                seen.height() * k);
            for (const double d : {mapped.left() - ink.left(), mapped.right() - ink.right(), mapped.top() - ink.top(),
                                   mapped.bottom() - ink.bottom()}) {
                const double part = std::abs(d) / canvas.width();
                if (part > worst) worst = part, worstObject = QString::fromStdString(object.name);
            }
        }
        qInfo("worst edge apart: %.2f%% of the frame's width (%s)", 100.0 * worst, qPrintable(worstObject));
        QVERIFY2(worst <= 0.02, qPrintable(worstObject));
    }

    // View > Frame Selected frames the objects selected in the Objects
    // panel: the still life's ball, seen through the view's camera, then
    // stands at the drawing's centre and fills most of it.
    void frameSelectedFramesTheSelection() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/meet/still-life.gltf"));
        snaxels::AnimationSpec still = window.document()->animation();
        still.camera.clear(); // the view's camera
        window.document()->setAnimation(still);
        QVERIFY(contoursSettle(window));
        QTreeWidgetItem* ball = objectItem(window, "Ball");
        QVERIFY(ball);
        window.objectsPanel()->tree()->setCurrentItem(ball);
        QVERIFY(window.meshView()->highlightTriangles() > 100);
        const int steps = window.undoStack()->count();
        window.findChild<QAction*>("frameSelected")->trigger();
        QCOMPARE(window.undoStack()->count(), steps + 1); // a camera edit
        QVERIFY(contoursSettle(window));
        // The ball's vertices as the drawing projects them.
        const snaxels::LoadedMesh& mesh = *window.document()->mesh();
        std::uint32_t index = 0;
        for (std::uint32_t i = 0; i < mesh.objects.size(); ++i)
            if (mesh.objects[i].name == "Ball") index = i;
        const snaxels::ImageProjection projection(window.meshView()->camera(), mesh.report.centre(), 1.0, 800, 800);
        QRectF box;
        for (const auto f : mesh.mesh.faces()) {
            if (mesh.face_object[std::size_t(f.idx())] != index) continue;
            for (const auto v : mesh.mesh.fv_range(f)) {
                const auto p = mesh.mesh.point(v);
                const glm::dvec2 q = projection.project({p[0], p[1], p[2]});
                box |= QRectF(q.x, q.y, 1e-6, 1e-6);
            }
        }
        qInfo("the ball's box on the 800 px canvas: %.0f,%.0f %.0f x %.0f", box.x(), box.y(), box.width(), box.height());
        QVERIFY(std::abs(box.center().x() - 400.0) < 16.0 && std::abs(box.center().y() - 400.0) < 16.0);
        QVERIFY(std::max(box.width(), box.height()) > 0.6 * 800.0 && QRectF(0, 0, 800, 800).contains(box));
    }

    // A skinned character from Debian's assimp test models opens ready to
    // play: on its clip, its first frame posed and framed in both panes
    // (the ink inside the 3-D view's frame and the SVG's canvas, filling a
    // good part of each, near the centre), not modified; the first Play
    // plays the clip.
    void aSkinnedCharacterOpensPlayingReadyAndFramed() {
        QString wuson = "/usr/share/assimp/models/X/Testwuson.X";
        if (!QFileInfo::exists(wuson)) wuson = QString(SNAXELS_TEST_ASSETS) + "/anim/Testwuson.X"; // the same file
        MainWindow window;
        QVERIFY(showWithMesh(window, wuson, {1000, 700}));
        QVERIFY(contoursSettle(window));
        QTest::qWait(300);
        QVERIFY(contoursSettle(window)); // drawn again, framed as posed
        QCOMPARE(window.document()->animation().kind, snaxels::AnimationSpec::Kind::Clip);
        QVERIFY(!window.isModified());
        auto check = [](const QRectF& ink, const QRectF& within, const char* where) {
            const QString what = QString("%1: ink %2,%3 %4x%5 in %6,%7 %8x%9")
                                     .arg(where)
                                     .arg(ink.x()).arg(ink.y()).arg(ink.width()).arg(ink.height())
                                     .arg(within.x()).arg(within.y()).arg(within.width()).arg(within.height());
            qInfo("%s", qPrintable(what));
            QVERIFY2(within.contains(ink), qPrintable(what));
            QVERIFY2(std::max(ink.width() / within.width(), ink.height() / within.height()) > 0.5, qPrintable(what));
            const QPointF off = ink.center() - within.center();
            QVERIFY2(std::abs(off.x()) < 0.15 * within.width() && std::abs(off.y()) < 0.15 * within.height(), qPrintable(what));
        };
        // The 3-D view: the character's pixels inside the frame.
        snaxels::ui::MeshView* view = window.meshView();
        view->setFrameShown(false);
        QTest::qWait(100);
        const QImage image = view->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        check(QRectF(inkBox(image)), view->frameRect(), "3-D view");
        view->setFrameShown(true);
        // The drawing: its SVG's ink on its canvas.
        QSvgRenderer svg(window.currentSvg());
        QImage drawn(svg.viewBox().size(), QImage::Format_RGB32);
        drawn.fill(Qt::white);
        QPainter painter(&drawn);
        svg.render(&painter);
        painter.end();
        check(QRectF(inkBox(drawn)), QRectF(drawn.rect()), "drawing");
        // The first Play plays the clip.
        QPushButton* play = childWithText<QPushButton>(window.timeline(), tr("Play"));
        QVERIFY(play);
        const QByteArray first = window.currentSvg();
        QTest::mouseClick(play, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(window.timeline()->frame() > 2 && window.currentSvg() != first, 30000);
        QTest::mouseClick(play, Qt::LeftButton);
    }

    // Edit > Preferences, answered in its dialog: a style file and a sharp
    // angle for new documents, the model's unit for Page Setup and the
    // export folder. File > New starts with that style and angle; export
    // dialogs start in that folder; a style file that does not parse is
    // refused with a message and nothing is kept.
    void preferencesSetWhatANewDocumentStartsWith() {
        QTemporaryDir dir;
        const QString style = dir.filePath("mine.xml");
        {
            QFile f(style);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("<style>\n  <contour kind=\"visual\"><visible stroke=\"#aa2200\" width=\"2.5\"/></contour>\n</style>\n");
        }
        const QString broken = dir.filePath("broken.xml");
        {
            QFile f(broken);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("<style><contour kind=\"visual\">");
        }
        QVERIFY(QDir(dir.path()).mkdir("exports"));
        const QString exports = dir.filePath("exports");
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        auto answer = [&](const QString& path, bool expectRefusal) {
            bool refused = false, asked = false;
            QTimer poll;
            poll.setInterval(20);
            QObject::connect(&poll, &QTimer::timeout, [&] {
                QWidget* modal = QApplication::activeModalWidget();
                if (auto* box = qobject_cast<QMessageBox*>(modal)) { // the refusal
                    refused = true;
                    box->accept();
                    return;
                }
                auto* dialog = qobject_cast<QDialog*>(modal);
                if (!dialog || dialog->objectName() != "preferences") return;
                if (asked) { // refused: cancel it
                    if (refused) {
                        poll.stop();
                        dialog->reject();
                    }
                    return;
                }
                asked = true;
                auto* edit = dialog->findChild<QLineEdit*>("prefStyle");
                edit->clear();
                QTest::keyClicks(edit, path);
                auto* sharp = dialog->findChild<QComboBox*>("prefSharpAngle");
                sharp->setCurrentIndex(sharp->findData("45"));
                auto* units = dialog->findChild<QComboBox*>("prefModelUnits");
                units->setCurrentIndex(units->findData("cm"));
                dialog->findChild<QLineEdit*>("prefExportFolder")->setText(exports);
                QPushButton* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
                // Clicked once this tick is over: a refusal's box opens its own
                // loop, where this timer (still in its slot) could not answer it.
                QTimer::singleShot(0, ok, [ok] { QTest::mouseClick(ok, Qt::LeftButton); });
                if (!expectRefusal) poll.stop();
            });
            poll.start();
            window.findChild<QAction*>("preferences")->trigger();
            QVERIFY(asked);
            QCOMPARE(refused, expectRefusal);
        };
        answer(broken, true);
        QVERIFY(QSettings().value(snaxels::ui::kPrefStyle).toString().isEmpty()); // nothing kept
        answer(style, false);
        QCOMPARE(QSettings().value(snaxels::ui::kPrefStyle).toString(), style);
        QCOMPARE(QSettings().value(snaxels::ui::kPrefSharpAngle).toString(), QString("45"));
        QCOMPARE(QSettings().value(snaxels::ui::kPrefModelUnits).toString(), QString("cm"));
        // File > New: the preferred style with its sharp angle.
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.findChild<QAction*>("newDocument")->trigger();
        QVERIFY(loaded.wait(60000));
        QVERIFY(contoursSettle(window));
        const QString text = window.document()->styleText();
        QVERIFY2(text.contains("#aa2200") && text.contains("sharp-angle=\"45\""), qPrintable(text));
        QCOMPARE(window.document()->style().surface.sharp_angle, 45.0);
        // Exports start in the preferred folder.
        const QString suggested = answerFileDialog([&] { window.findChild<QAction*>("exportFrame")->trigger(); }, false);
        QCOMPARE(QFileInfo(suggested).absolutePath(), QFileInfo(exports).absoluteFilePath());
        // Page Setup's scale measures in the preferred unit.
        QTimer poll;
        poll.setInterval(20);
        QString unit;
        QObject::connect(&poll, &QTimer::timeout, [&] {
            auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            if (!dialog || dialog->objectName() != "pageSetup") return;
            poll.stop();
            unit = dialog->findChild<QComboBox*>("modelUnits")->currentData().toString();
            dialog->reject();
        });
        poll.start();
        window.findChild<QAction*>("pageSetup")->trigger();
        QCOMPARE(unit, QString("cm"));
        for (const char* key : {snaxels::ui::kPrefStyle, snaxels::ui::kPrefSharpAngle, snaxels::ui::kPrefModelUnits,
                                snaxels::ui::kPrefExportFolder})
            QSettings().remove(key);
    }

    // The Objects panel, raised at 1280 x 800 on a scene of eleven objects,
    // widens its dock to show every column: no horizontal scroll bar, and
    // the 3-D view and the SVG pane keep room.
    void objectsPanelShowsItsColumns() {
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/meet/still-life.gltf", {1280, 760}));
        auto* dock = window.findChild<QDockWidget*>("objectsDock");
        QVERIFY(dock);
        const int before = dock->width(); // the Style tab's width: too narrow for the columns
        dock->raise(); // as a click on its tab does
        QTest::qWait(300);
        QTreeWidget* tree = window.objectsPanel()->tree();
        const int columns = tree->header()->length();
        QVERIFY2(before < columns, qPrintable(QString("the dock was %1 px already").arg(before)));
        qInfo("columns %d px, the tree's viewport %d px, the dock %d px", columns, tree->viewport()->width(), dock->width());
        QVERIFY2(columns <= tree->viewport()->width(), qPrintable(QString("%1 > %2").arg(columns).arg(tree->viewport()->width())));
        QVERIFY(!tree->horizontalScrollBar()->isVisible());
        QVERIFY(window.meshView()->width() >= 300 && window.svgPane()->width() >= 250);
    }

    void videoExportTakesItsSettings() {
        if (QStandardPaths::findExecutable("ffprobe").isEmpty()) QSKIP("ffprobe is not installed");
        QTemporaryDir dir;
        QSettings().setValue(snaxels::ui::kExportFolder, dir.path());
        QSettings().remove(snaxels::ui::kVideoWidth);
        QSettings().remove(snaxels::ui::kVideoCrf);
        MainWindow window;
        QVERIFY(showWithMesh(window, QString(SNAXELS_TEST_ASSETS) + "/spot.obj"));
        window.timeline()->setFrameCount(4);
        QVERIFY(contoursSettle(window));
        QSignalSpy finished(&window, &MainWindow::exportFinished);
        bool asked = false;
        QTimer poll; // the settings dialog, once the file dialog is answered
        poll.setInterval(50);
        QObject::connect(&poll, &QTimer::timeout, [&] {
            auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            if (!dialog || dialog->objectName() != "videoSettings") return;
            poll.stop();
            asked = true;
            auto* width = dialog->findChild<QComboBox*>("videoWidth");
            width->setCurrentIndex(width->findData(640));
            dialog->findChild<QSpinBox*>("videoCrf")->setValue(30);
            dialog->accept();
        });
        poll.start();
        const QString suggested = answerFileDialog([&] { window.findChild<QAction*>("exportVideo")->trigger(); }, true);
        QVERIFY(asked);
        QVERIFY(finished.wait(120000));
        QCOMPARE(QFileInfo(suggested).fileName(), QString("spot.mp4"));
        QProcess probe;
        probe.start("ffprobe", {"-v", "error", "-select_streams", "v:0", "-show_entries", "stream=width,height", "-of",
                                "csv=p=0", suggested});
        QVERIFY(probe.waitForFinished(30000));
        QCOMPARE(QString::fromUtf8(probe.readAllStandardOutput()).trimmed(), QString("640,640"));
        QCOMPARE(QSettings().value(snaxels::ui::kVideoWidth).toInt(), 640); // remembered
        QCOMPARE(QSettings().value(snaxels::ui::kVideoCrf).toInt(), 30);
        QSettings().remove(snaxels::ui::kVideoWidth);
        QSettings().remove(snaxels::ui::kVideoCrf);
    }

};

int main(int argc, char** argv) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    QApplication app(argc, argv);
    if (argc == 3 && QString(argv[1]) == "--save-helper") {
        // For projectSaveSurvivesKill: load a mesh, say so, then save the
        // project to argv[2] over and over, a different style each time,
        // until killed.
        QStandardPaths::setTestModeEnabled(true);
        MainWindow window;
        window.show();
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openMesh("proc:torus:20000");
        if (!loaded.wait(60000)) return 2;
        std::printf("ready\n");
        std::fflush(stdout);
        for (int n = 0;; ++n) {
            window.styleEditor()->setText(QString("<style version=\"1\">\n<!-- helper save %1 %2 -->\n</style>\n")
                                              .arg(n)
                                              .arg(QString(4000 + n % 7, 'x')));
            if (!window.saveProject(QString(argv[2]))) return 3;
        }
    }
    TestMainWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_mainwindow.moc"
