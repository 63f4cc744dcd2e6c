#pragma once
/// What changes from frame to frame: the camera orbiting (turntable), the
/// light orbiting, the mesh's own clip (skinning, morph targets), a
/// numbered sequence of mesh files with the same connectivity, or one of
/// the file's cameras moving through its clip.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/scene/camera.h"
#include "snaxels/mesh/topology.h"

namespace snaxels {

struct AnimationSpec {
    /// Camera: the file's camera `camera` moves through its clip; the mesh stays.
    enum class Kind { Still, Turntable, LightOrbit, Clip, Sequence, Camera };
    Kind kind = Kind::Still;
    double degrees_per_frame = 1.0; ///< turntable and light orbit
    std::string clip;               ///< Clip, Camera: name or index; empty for the first (Camera: the one that moves it)
    /// The file's camera that films the animation (its name); empty: the
    /// view's camera. It follows the clip's keys (of a Clip, or of its own
    /// clip for any other kind) at each frame's time; a turntable turns it.
    std::string camera;
    std::string pattern;            ///< Sequence: path with #### or %d for the frame number
    int first_file = -1;            ///< Sequence: number of the first file (-1: 0 or 1, whichever exists)
    int frames = 1;
    int start = 0; ///< the source's frame the animation begins at (its in point)
    double fps = 24.0;

    bool operator==(const AnimationSpec&) const = default;
};

/// The light at @p source_frame (the spec's start counted in) of @p spec,
/// from its light at frame 0: turned about @p axis by the turntable (a
/// directional light, so the mesh stays lit from the same side) or by the
/// light orbit (a point light about @p centre); otherwise unchanged.
Light light_at_frame(const AnimationSpec& spec, const Light& light, double source_frame, const glm::dvec3& axis,
                     const glm::dvec3& centre);

/// The file's camera of @p track @p seconds into its clip, its target on
/// its line of sight at @p centre's depth.
Camera file_camera_at(const CameraTrack& track, double seconds, const glm::dvec3& centre);

/// The camera of @p spec at @p source_frame (the spec's start counted in):
/// the file's camera (@p track, when the spec names one) at the frame's
/// time, else @p camera; turned by a turntable about the model's up,
/// centred on @p centre for a file's framing camera.
Camera camera_at_frame(const AnimationSpec& spec, const Camera& camera, const CameraTrack* track, int source_frame,
                       const glm::dvec3& centre);

/// What one frame shows: where the camera and the light are, and the mesh
/// in its pose (the loaded one unless a clip or a sequence moves it).
struct FramePose {
    Camera camera;
    Light light;
    MeshTopology mesh;
};

/// Poses the scene for each frame: camera, light, and (for clips and
/// sequences) the mesh, as a pose of its one shared connectivity.
class FrameDriver {
  public:
    /// @p mesh is the loaded first frame (or bind pose) and @p topology the
    /// engine's topology of it (refined or not); @p centre the point the
    /// camera and light orbit (the mesh's bounding-box centre).
    FrameDriver(const AnimationSpec& spec, const LoadedMesh& mesh, const MeshTopology& topology,
                const Camera& camera, const Light& light, const glm::dvec3& centre,
                const std::string& mesh_path);
    ~FrameDriver();

    bool mesh_moves() const;
    /// The light at frame 0 (the spec's start), from which the frames' are turned.
    void set_light(const Light& light) { light_ = light; }
    /// The file's camera the spec names, or null.
    const FileCamera* file_camera() const { return track_ ? &track_->info() : nullptr; }
    /// Whether a file's camera moves from frame to frame.
    bool camera_moves() const { return track_ && track_->info().animated(); }
    /// Frame @p k (0-based, counted from the spec's start); throws
    /// snaxels::Error if a sequence file is missing or does not match the
    /// first frame's connectivity.
    FramePose pose(int k);

    /// The file of sequence frame @p k.
    std::string sequence_path(int k) const;

  private:
    /// The mesh at frame @p k of a clip or a sequence.
    MeshTopology mesh_pose(int k);

    AnimationSpec spec_;
    std::vector<std::uint32_t> vertex_source_; ///< per mesh vertex: its vertex in the file's triangle soup
    MeshTopology rest_;
    Camera camera_;
    Light light_;
    glm::dvec3 centre_;
    std::unique_ptr<MeshAnimation> clip_;
    std::unique_ptr<CameraTrack> track_;
    std::size_t soup_size_ = 0;
    std::vector<glm::dvec3> soup_;
};

/// Frames of @p spec as its source plays them: its own count, or for a clip
/// or a camera's clip with none (0), the clip's length at its frame rate
/// from its start. Reads the clip's length from @p mesh_path.
int animation_frame_count(const AnimationSpec& spec, const std::string& mesh_path);

/// The file of frame @p k of @p spec's sequence (counted from its first
/// file; a first_file of -1 starts at 0 or 1, whichever exists).
std::string sequence_file(const AnimationSpec& spec, int k);

/// A numbered series of mesh files found from one of them.
struct SequenceFiles {
    std::string pattern; ///< the file's path with its number as #### (as wide as it is written)
    int first_file = 0;  ///< the lowest number of the unbroken run the file belongs to
    int count = 0;       ///< files in that run
};

/// The numbered series @p file belongs to: the last run of digits in its
/// name is the frame number, and the files with the neighbouring numbers
/// (written as wide) that exist make the run. Empty when the name holds
/// no number.
std::optional<SequenceFiles> find_sequence(const std::string& file);

} // namespace snaxels
