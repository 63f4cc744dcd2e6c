#pragma once
/// The application's orbiting camera as numbers a project file keeps: the
/// camera circles a point (the mesh's centre, shifted by a pan in screen
/// space) at a distance, turned by yaw and pitch, with a turntable angle on
/// top. One function turns it into the engine's Camera, so the 3-D view,
/// the project file and the command line see the very same camera.
///
/// Yaw and pitch are measured in the model's own frame: its up axis (the
/// world direction shown upward, +Y unless the user says otherwise) and its
/// front (model_front()). Yaw 0, pitch 0 looks at the front.

#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/scene/camera.h"

namespace snaxels {

/// Radians above the horizon the default views look from: a little above.
inline constexpr double kDefaultPitch = 0.3;
/// The default views' yaw: the model's front seen a little from its right
/// hand side of the picture (30 degrees toward +X of the model's frame), a
/// three-quarter view that reads its depth; View > Front is straight on.
inline constexpr double kDefaultYaw = -M_PI / 6.0;

/// The front of a model whose up axis is @p up (unit): the direction it
/// faces, perpendicular to up. +Z for +Y up (the glTF and OBJ convention);
/// -Y for +Z up (Blender's, whose exporters turn -Y into glTF's +Z); for
/// other ups, +Z (or +Y when up lies near the Z axis) made perpendicular.
glm::dvec3 model_front(const glm::dvec3& up);

/// The orthographic view direction (eye to scene) that looks at the front
/// of a model with up axis @p up from a little above and to the side (as
/// kDefaultPitch and kDefaultYaw say): the command line's default view.
glm::dvec3 default_view_dir(const glm::dvec3& up);

/// The orthographic view direction (eye to scene) of an eye at @p yaw
/// radians about the model's up axis @p up (0 at its front; negative toward
/// its right, as the orbit's yaw) and @p pitch radians above its horizon.
glm::dvec3 view_dir_at(const glm::dvec3& up, double yaw, double pitch);

/// A named orthographic view of the command line's --view: its name, its
/// yaw and pitch (view_dir_at), and what it is.
struct NamedView {
    const char* name;
    double yaw, pitch;
    const char* summary;
    /// An axonometric view (isometric, dimetric, trimetric): orthographic
    /// by definition, so the application's preset turns orthographic too.
    bool axonometric = false;
};
/// front, back, left, right and top (as View > Front and the others), and
/// the axonometric views of technical illustration, each from the model's
/// front right and above:
/// - isometric: 45 degrees around and atan(1/sqrt 2) = 35.264 above: the
///   three axes foreshortened alike, receding edges at 30 degrees;
/// - dimetric: 45 around and 30 above: the 2:1 dimetric, receding edges at
///   atan(1/2) = 26.565 degrees (a slope of 1 in 2), two axes alike;
/// - trimetric: 30 around and 20 above: the three axes foreshortened
///   differently.
const std::vector<NamedView>& named_views();

struct OrbitView {
    glm::dvec3 centre{0.0}; ///< the mesh's bounding-box centre
    glm::dvec3 pan{0.0};    ///< screen-space shift (x right, y up) in world units
    glm::dvec3 up{0.0, 1.0, 0.0}; ///< the model's up axis (unit): the orbit and the turntable turn about it
    double yaw = kDefaultYaw; ///< radians about up; 0 looks straight at the model's front
    double pitch = kDefaultPitch; ///< radians above the horizon
    double distance = 3.0;  ///< eye to the orbited point
    double turntable = 0.0; ///< radians; the camera orbits by this about world +Y
    double fov_deg = 35.0;  ///< vertical field of view
    /// An orthographic view: parallel projection along the line of sight,
    /// showing the height the perspective view shows at the orbited point
    /// (2 distance tan(fov/2)), so zooming still changes the distance.
    bool orthographic = false;

    bool operator==(const OrbitView&) const = default;
};

/// How far from the centre of a sphere of @p radius an eye with a vertical
/// field of view of @p fov_deg stands to frame it, with a little room.
double framing_distance(double radius, double fov_deg);

/// A view of the model's front from a little above and to the side that
/// frames a sphere of @p radius about @p centre, the model standing on @p up.
OrbitView framing_view(const glm::dvec3& centre, double radius, const glm::dvec3& up = {0.0, 1.0, 0.0});

/// The named view called @p name (named_views()), or null.
const NamedView* find_named_view(const std::string& name);

/// @p view turned to look at the model from @p preset (front, back, left
/// and right level, top from above short of the pole by the orbit's pitch
/// limit, the axonometric ones as named_views() says), keeping its
/// distance, pan, up and field of view; an axonometric preset makes it
/// orthographic, the others keep its projection.
OrbitView preset_view(OrbitView view, const NamedView& preset);

/// The height in world units an orbit view shows at the orbited point,
/// from the bottom of the 3-D view to its top (an orthographic view shows
/// this height everywhere).
double orbit_view_height(const OrbitView& view);

/// The orbit's pitch limit: a little short of straight above or below, where
/// the up axis would lie along the line of sight.
inline constexpr double kMaxPitch = 1.55;

/// World to eye space (OpenGL convention: the eye looks down -Z).
glm::dmat4 orbit_view_matrix(const OrbitView& view);

/// The camera of @p view: perspective, or orthographic along its line of
/// sight with ortho_height orbit_view_height() (spanning the image's smaller
/// side, as the perspective field of view does).
Camera orbit_camera(const OrbitView& view);

/// The camera of @p view before the turntable turns, with the model's up
/// axis as its up: what an animation export starts from (a turntable turns
/// about that axis).
Camera orbit_base_camera(OrbitView view);

} // namespace snaxels
