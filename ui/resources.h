#pragma once
// Locates the data the application ships (default scene, presets).

#include <QString>

namespace snaxels::ui {

/// The folder holding resources/ and styles/: share/snaxels next to the
/// executable's bin/ folder, as in the build tree and in an install.
QString dataDirectory();

/// The folder holding the documentation (styles.md, app.md, ...):
/// share/doc/snaxels next to the executable's bin/ folder.
QString docsDirectory();

/// The bundled default scene (Keenan Crane's Spot, CC0).
QString defaultScenePath();

} // namespace snaxels::ui
