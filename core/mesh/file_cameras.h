#pragma once
/// The cameras a scene file holds (glTF, FBX, Collada and the other formats
/// Assimp reads): their names, projections and framing, and their poses
/// over time where a clip moves them (the camera's node or a parent of it
/// has keys). Positions are in the mesh's coordinates: the same node
/// transforms, and the same turn upright from the file's own axes, apply to
/// both.

#include <memory>
#include <string>
#include <vector>

#include "snaxels/scene/camera.h"

namespace snaxels {

struct FileCamera {
    std::string name;          ///< its node's name
    bool orthographic = false;
    double fov_deg = 0.0;      ///< perspective: vertical field of view
    double ortho_height = 0.0; ///< orthographic: the view's height in world units
    double aspect = 0.0;       ///< width over height; 0 when the file does not say
    /// Perspective: its near clipping distance (glTF's znear, Blender's clip
    /// start), in the camera's own units; 0 when the file gives none.
    double clip_start = 0.0;
    std::string clip;          ///< the first clip that moves it ("" when none does)
    double clip_seconds = 0.0; ///< that clip's length
    /// Where it stands at the start of that clip (or at rest): what the
    /// default light is placed from (the viewer's upper left), as a
    /// turntable's is from its first frame.
    Camera first;

    bool animated() const { return !clip.empty(); }
};

/// Whether @p path is in a format that can hold cameras (not OBJ, PLY, STL
/// or OFF, nor a procedural mesh): where file_cameras is worth a read.
bool may_hold_cameras(const std::string& path);

/// The cameras of @p path, in the file's order (empty when it has none).
/// With an isolated importer (isolated_import.h) the helper reads the file
/// first, so a file that crashes the reader is refused before it is read
/// here. Throws snaxels::Error naming the file when it cannot be read.
std::vector<FileCamera> file_cameras(const std::string& path);

/// One camera of a file posed at any time: its clip's keys interpolated,
/// or the camera at rest when no clip moves it.
class CameraTrack {
  public:
    /// Camera @p name of @p path (its name, or its index in file_cameras()),
    /// moved by clip @p clip (a name or index; empty: the first clip that
    /// moves the camera, if any). Throws snaxels::Error naming the file and
    /// listing its cameras when there is no such camera, or its clips when
    /// there is no such clip.
    CameraTrack(const std::string& path, const std::string& name, const std::string& clip = "");
    ~CameraTrack();
    CameraTrack(CameraTrack&&) noexcept;

    const FileCamera& info() const;
    /// The camera @p seconds into its clip (clamped to the clip), as the
    /// engine's Camera: own_frame set, so its field of view (or
    /// orthographic height) spans the picture's height.
    Camera at(double seconds) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The canvas height that gives a @p width wide picture the camera's
/// aspect, or @p height when the camera's aspect is unknown.
int canvas_height_for(const FileCamera& camera, int width, int height);

} // namespace snaxels
