// snaxels: the desktop application. Opens the mesh given on the command
// line, or the bundled default scene.

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>

#include "ui/mainwindow.h"
#include "ui/resources.h"

int main(int argc, char** argv) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(4);
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    QApplication::setApplicationName("snaxels");
    QApplication::setOrganizationName("snaxels");
    QApplication::setApplicationVersion(SNAXELS_VERSION);

    QCommandLineParser parser;
    parser.setApplicationDescription("Snaxels: vector line art from 3-D meshes.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("mesh", "Mesh file or proc:NAME[:FACES] to open "
                                         "(default: the bundled Spot scene).");
    parser.process(app);

    snaxels::ui::MainWindow window;
    window.show();
    const QStringList args = parser.positionalArguments();
    window.openMesh(args.isEmpty() ? snaxels::ui::defaultScenePath() : args.first());
    return app.exec();
}
