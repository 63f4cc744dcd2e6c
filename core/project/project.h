#pragma once
/// A project: the mesh (its path relative to the project file), the orbiting
/// camera, the user's light, the animation, the current frame and the style's
/// XML text. The application saves and opens it; `snaxels-cli` renders it.
/// Stored as JSON with every number written so that it reads back exactly:
/// a reopened project exports the same bytes.

#include <optional>
#include <string>

#include "snaxels/animation/frame_driver.h"
#include "snaxels/scene/orbit.h"

namespace snaxels {

struct Project {
    /// The mesh as the file holds it: relative to the project's folder,
    /// absolute, or a procedural proc:NAME[:FACES].
    std::string mesh;
    OrbitView view;             ///< its centre is the mesh's, not stored
    std::optional<Light> light; ///< none: the style's light, else the default one
    AnimationSpec animation;
    int frame = 0;
    std::string style; ///< the style's XML text ("" for the default style)

    bool operator==(const Project&) const = default;
};

/// The extension project files carry.
inline constexpr const char* kProjectExtension = ".snaxels";

/// Reads @p path. Throws snaxels::Error naming the file and the field that
/// is missing or wrong.
Project read_project(const std::string& path);

/// The project's JSON text.
std::string project_text(const Project& project);

/// Writes @p project to @p path atomically (see write_file_atomically).
void write_project(const std::string& path, const Project& project);

/// The mesh path to store for @p mesh_path in a project saved as @p project_path:
/// relative to its folder when possible; proc: specs unchanged.
std::string project_mesh_reference(const std::string& project_path, const std::string& mesh_path);

/// The mesh file (or proc: spec) a project at @p project_path refers to.
std::string resolve_project_mesh(const std::string& project_path, const std::string& reference);

} // namespace snaxels
