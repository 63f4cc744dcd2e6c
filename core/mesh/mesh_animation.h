#pragma once
/// The mesh's own animation from its file (Assimp): skeletal skinning and
/// morph targets, posed at any time of a chosen clip, as soup positions in
/// the order read_triangle_soup gives them.

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels {

class MeshAnimation {
  public:
    /// Reads @p path and picks clip @p clip: its name, its index, or empty
    /// for the first. Throws snaxels::Error naming the file when it has no
    /// animation or no such clip (the message lists the clips).
    MeshAnimation(const std::string& path, const std::string& clip);
    ~MeshAnimation();

    const std::vector<std::string>& clip_names() const;
    const std::string& clip() const;
    /// The clip's length in seconds.
    double duration() const;
    /// Soup positions at @p seconds into the clip (looping).
    void pose(double seconds, std::vector<glm::dvec3>& positions) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct AnimationClipInfo {
    std::string name;
    double duration = 0.0; ///< seconds
};

/// Frames a clip of @p seconds plays at @p fps, both ends included (at least 1).
int clip_frame_count(double seconds, double fps);

/// Every clip of @p path (empty when it has none), named as MeshAnimation
/// names them.
std::vector<AnimationClipInfo> animation_clips(const std::string& path);

} // namespace snaxels
