// snaxels: the desktop application. Opens the project or mesh given on the
// command line, or the bundled default scene.

#include <QApplication>
#include <QCommandLineParser>
#include <QFile>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>
#include <string>

#include "snaxels/mesh/isolated_import.h"
#include "snaxels/util/memory.h"
#include "snaxels/version.h"
#include "ui/mainwindow.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"

namespace {

void name_application() {
    QCoreApplication::setApplicationName("snaxels");
    QCoreApplication::setOrganizationName("snaxels");
    QCoreApplication::setApplicationVersion(snaxels::version);
}

} // namespace

int main(int argc, char** argv) {
    snaxels::tune_allocator();
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(4);
    QSurfaceFormat::setDefaultFormat(format);

    QCommandLineParser parser;
    parser.setApplicationDescription("Snaxels: vector line art from 3-D meshes.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("file", "Project (.snaxels), mesh file or proc:NAME[:FACES] to open "
                                         "(default: the bundled Spot scene).");
    const QCommandLineOption style_option("style-file", "Start with this XML style (docs/styles.md).", "xml");
    const QCommandLineOption screenshot_option(
        "screenshot", "Save a picture of the window to this PNG once the drawing is ready, then quit.", "png");
    const QCommandLineOption parabolic_option("parabolic", "Start with View > Parabolic Curves on.");
    parser.addOption(style_option);
    parser.addOption(screenshot_option);
    parser.addOption(parabolic_option);
    // --help and --version answer without a display (a GUI application
    // cannot start without one): a plain application reads them and quits.
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h" || arg == "--help-all" || arg == "--version" || arg == "-v") {
            QCoreApplication plain(argc, argv);
            name_application();
            parser.process(plain); // prints and exits
        }
    }

    QApplication app(argc, argv);
    name_application();
    parser.process(app);

    // Mesh files are read by the snaxels-import helper in a process of its
    // own: a file that crashes the reader costs that process, not the work
    // open in this window.
    snaxels::set_mesh_importer(snaxels::importer_beside_executable());
    snaxels::ui::MainWindow window;
    if (parser.isSet(style_option)) {
        QFile in(parser.value(style_option));
        if (!in.open(QIODevice::ReadOnly)) {
            std::fprintf(stderr, "snaxels: cannot read %s: %s\n", qPrintable(in.fileName()), qPrintable(in.errorString()));
            return 1;
        }
        window.setStartingStyle(QString::fromUtf8(in.readAll()), in.fileName());
    }
    if (parser.isSet(parabolic_option)) window.parabolicAction()->setChecked(true);
    window.show();
    if (parser.isSet(screenshot_option)) {
        const QString png = parser.value(screenshot_option);
        QObject::connect(&window, &snaxels::ui::MainWindow::contoursUpdated, &window, [&window, png] {
            if (window.parabolicPending()) return; // the drawing is ready once they are on it
            QTimer::singleShot(300, &window, [&window, png] {
                const bool saved = window.grab().save(png);
                if (!saved) std::fprintf(stderr, "snaxels: cannot write %s\n", qPrintable(png));
                QApplication::exit(saved ? 0 : 1);
            });
        });
        QObject::connect(&window, &snaxels::ui::MainWindow::projectFailed, &window, [](const QString& message) {
            std::fprintf(stderr, "snaxels: %s\n", qPrintable(message));
            QApplication::exit(1);
        });
        QObject::connect(&window, &snaxels::ui::MainWindow::loadFailed, &window, [](const QString& message) {
            std::fprintf(stderr, "snaxels: %s\n", qPrintable(message));
            QApplication::exit(1);
        });
    }
    const QStringList args = parser.positionalArguments();
    window.openFile(args.isEmpty() ? snaxels::ui::defaultScenePath() : args.first());
    return app.exec();
}
