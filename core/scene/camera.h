#pragma once
/// Camera, light and the projection to image (SVG pixel) coordinates.

#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

namespace snaxels {

/// A perspective camera's default near plane, as a fraction of the mesh's
/// bounding radius: what lies nearer the eye than this is clipped.
inline constexpr double kDefaultNearFraction = 1e-3;

/// Orthographic (a view direction) or perspective (eye, target, field of view).
struct Camera {
    enum class Projection { Orthographic, Perspective };
    Projection projection = Projection::Orthographic;
    glm::dvec3 view_dir{0.0, 0.0, 1.0}; ///< orthographic: where the camera looks (eye to scene)
    glm::dvec3 eye{0.0, 0.0, 5.0};      ///< perspective
    glm::dvec3 target{0.0};             ///< perspective
    double fov_deg = 35.0;              ///< perspective: vertical field of view
    glm::dvec3 up{0.0, 1.0, 0.0};       ///< world direction that appears upward
    /// A camera that frames the picture itself (a file's camera): the
    /// perspective field of view spans the image's height, and an
    /// orthographic view shows ortho_height world units from top to bottom.
    /// Otherwise the field of view spans the image's smaller side, and an
    /// orthographic view shows ortho_height across that side, or, with no
    /// ortho_height (0), fits the mesh's bounding sphere into the image.
    bool own_frame = false;
    /// Orthographic: the world units the view shows (see own_frame), about
    /// the line through `eye` along view_dir; 0: fit the bounding sphere.
    double ortho_height = 0.0;
    /// Perspective: the near plane's distance from the eye along the line
    /// of sight (a file camera's clip start); 0: kDefaultNearFraction of
    /// the mesh's bounding radius. What lies nearer is clipped.
    double near_clip = 0.0;

    bool operator==(const Camera&) const = default;
    bool orthographic() const { return projection == Projection::Orthographic; }
    /// Unit vector from @p p toward the viewer (V of the paper).
    glm::dvec3 to_viewer(const glm::dvec3& p) const {
        return orthographic() ? -glm::normalize(view_dir) : glm::normalize(eye - p);
    }
    /// The direction the camera looks, unit.
    glm::dvec3 forward() const {
        return glm::normalize(orthographic() ? view_dir : target - eye);
    }
    /// The near plane's distance for a mesh of bounding radius @p radius.
    double near_plane(double radius) const { return near_clip > 0.0 ? near_clip : kDefaultNearFraction * radius; }
    /// Screen right and up vectors in world space (unit, orthogonal to forward()).
    void screen_basis(glm::dvec3& right, glm::dvec3& screen_up) const;
};

/// Directional (dir points from the surface toward the light) or point light.
struct Light {
    bool point = false;
    glm::dvec3 dir{-1.0, 1.0, -1.0};
    glm::dvec3 pos{0.0};
    /// Unit vector from @p p toward the light (L of the paper).
    glm::dvec3 to_light(const glm::dvec3& p) const {
        return point ? glm::normalize(pos - p) : glm::normalize(dir);
    }
    bool operator==(const Light&) const = default;
};

/// Light from the viewer's upper left for @p camera: the default light.
Light default_light(const Camera& camera);

/// Maps world points to image pixels (x right, y down). Orthographic views
/// fit the given bounding sphere into the image within a margin; perspective
/// views map the field of view to the image height.
class ImageProjection {
  public:
    /// @p margin: pixels between the bounding circle and the image edge
    /// (orthographic views).
    ImageProjection(const Camera& camera, const glm::dvec3& centre, double radius, int width,
                    int height, double margin = 32.0);
    /// A perspective camera's points nearer than its near plane
    /// (Camera::near_plane of the radius), which no stage draws, project as
    /// if moved along the line of sight onto the plane: far outside the
    /// picture, but finite and continuous where a stroke crosses the plane,
    /// never mirrored from behind the eye.
    glm::dvec2 project(const glm::dvec3& p) const;
    /// The ray through image point @p pixel: an origin on the camera's side
    /// (@p back world units before the bounding sphere's centre, for
    /// orthographic views; the eye for perspective ones) and a unit direction.
    void pixel_ray(const glm::dvec2& pixel, double back, glm::dvec3& origin, glm::dvec3& dir) const;
    int width() const { return width_; }
    int height() const { return height_; }
    /// Pixels per world unit across the line of sight (orthographic), or the
    /// focal length in pixels (perspective: pixels per unit at unit depth).
    double scale() const { return scale_; }
    /// The camera it projects through.
    const Camera& camera() const { return camera_; }

  private:
    Camera camera_;
    glm::dvec3 right_{}, up_{}, forward_{}, centre_{};
    double scale_ = 1.0; ///< pixels per world unit (orthographic) or focal length in pixels
    double near_ = 1e-12; ///< perspective: the least depth a point projects from
    int width_, height_;
};

nlohmann::json to_json(const Camera& camera);
nlohmann::json to_json(const Light& light);

} // namespace snaxels
