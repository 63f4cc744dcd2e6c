#include "ui/resources.h"

#include <QCoreApplication>
#include <QDir>

namespace snaxels::ui {

QString dataDirectory() {
    const QDir bin(QCoreApplication::applicationDirPath());
    return QDir::cleanPath(bin.absoluteFilePath("../share/snaxels"));
}

QString docsDirectory() {
    const QDir bin(QCoreApplication::applicationDirPath());
    return QDir::cleanPath(bin.absoluteFilePath("../share/doc/snaxels"));
}

QString defaultScenePath() { return dataDirectory() + "/resources/spot.obj"; }

} // namespace snaxels::ui
