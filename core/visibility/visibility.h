#pragma once
/// Hidden lines: the quantitative invisibility (QI, the number of surface
/// layers between a point and the viewer) of every contour sample, and each
/// loop cut into runs of equal QI at change points found by bisection.

#include <vector>

#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/near_plane.h"
#include "snaxels/visibility/ray_scene.h"

namespace snaxels {

struct VisibilityOptions {
    /// A sample's ray starts this many local edge lengths off the surface,
    /// along its smooth normal: on the visual contour the ray grazes the
    /// surface, and the mesh's facets must not hide their own silhouette.
    /// A snaxel's local length is its edge's, but no more than twice the
    /// least height of the faces beside it (a long, narrow face leaves
    /// the surface only across its width); on a rung of a split sharp
    /// edge's strip (no length), a tenth of the edges' round it.
    double normal_offset = 0.2;
    /// Bisection steps that locate a QI change between two samples
    /// (10 steps: 1/1024 of the segment, far below a pixel).
    int bisection_steps = 10;
    /// On a refined mesh, a ray ignores the faces of the mesh as loaded
    /// around where it starts (VisibilityRay::original_neighbourhood): a
    /// contour inside a large flat face is then not hidden by the face's
    /// own neighbours, as it is not on the mesh as loaded.
    bool original_neighbourhood = true;
};

/// The class of a snaxel, and a run, that its contour leaves out of the
/// drawing (ContourResult::snaxel_margin < 0: a weak suggestive contour),
/// in place of a QI: it is neither visible nor hidden, and not drawn.
constexpr int kNotDrawn = -1;

/// A stretch of a loop with one QI (or kNotDrawn). Points are 3-D, in the mesh's coordinates.
struct VisibilityRun {
    int qi = 0;
    bool closed = false; ///< the whole loop, closed, at one QI
    std::vector<glm::dvec3> points;
    /// The loop index of the first snaxel among points; points[0] is the
    /// change point on the segment before it when @p from_change.
    std::size_t first = 0;
    bool from_change = false;
};

struct LoopVisibility {
    std::vector<int> snaxel_qi; ///< per snaxel, in loop order
    /// Per snaxel whose QI differs from the one before it in the loop: where
    /// the change happens on the segment between them (else unused).
    std::vector<glm::dvec3> change_before;
    std::vector<VisibilityRun> runs;
};

struct ContourVisibility {
    std::vector<LoopVisibility> loops; ///< parallel to the contour's loops
};

class VisibilitySampler {
  public:
    /// A perspective @p camera clips at its near plane (Camera::near_plane
    /// of the scene's bounding radius): points nearer the eye are not
    /// drawn, and nothing nearer hides anything.
    VisibilitySampler(const RayScene& scene, const Camera& camera, VisibilityOptions options = {});

    /// How far @p p lies past the near plane along the line of sight
    /// (negative: nearer the eye, clipped); +infinity for orthographic views.
    double past_near(const glm::dvec3& p) const;

    /// The ray from a snaxel: its edge's end vertices' faces are ignored.
    VisibilityRay snaxel_ray(const Snaxel& s, const glm::dvec3& p, const glm::dvec3& n) const;
    /// The ray from a point inside face @p face: the faces around its corners are ignored.
    VisibilityRay face_ray(FaceId face, const glm::dvec3& p, const glm::dvec3& n) const;
    /// The ray from vertex @p v: the faces around it are ignored. It starts
    /// off the surface on its normal's side, or (@p back_side) the other:
    /// a vertex turned away is seen, if at all, from its back.
    VisibilityRay vertex_ray(VertexId v, bool back_side = false) const;
    /// The ray from the point at @p t along edge @p e (0 at its first
    /// vertex): the faces around both ends are ignored.
    VisibilityRay edge_ray(EdgeId e, double t) const;
    /// The ray from point @p p of an intersection line, where two surfaces
    /// meet: nothing is ignored, and it starts a thousandth of @p scale
    /// (the local edge length) toward the viewer, so that where the view
    /// passes into either surface that surface's far side is counted, and
    /// where it passes between them nothing near p is.
    VisibilityRay meeting_ray(const glm::dvec3& p, double scale) const;
    /// QI along a ray: crossings of front- and back-facing layers (the larger
    /// count, so open sheets seen from behind count too).
    int qi(const VisibilityRay& ray) const;

    /// QI of every snaxel of @p contour and its loops cut into runs; the
    /// snaxels the contour leaves out (snaxel_margin) are kNotDrawn, cut
    /// from the others where the margin interpolates to zero, and so are
    /// the stretches on parts its selector does not take
    /// (selected_stretches), cut where the part changes.
    ///
    /// With HiddenLevels::WhereSeen, the QI of a hidden snaxel is counted
    /// only where the next snaxel along its loop is seen (the level the
    /// change to seen is found from); every other hidden snaxel takes the
    /// level of its hidden stretch's end (1 where that is not counted). The
    /// runs seen, where they end and their order are classify's with every
    /// level counted; only hidden runs may be cut elsewhere (and a closed
    /// loop's walk may start elsewhere inside a hidden stretch, which
    /// leaves the order of the runs seen as it was). For drawings that
    /// show no hidden lines and weigh no stroke by QI, at about half the
    /// rays' cost: a count follows every layer on a hidden point's ray,
    /// "is it hidden" stops at the first. Snaxels of a scene of several
    /// objects are always counted.
    enum class HiddenLevels { Counted, WhereSeen };
    ContourVisibility classify(const SnaxelEngine& engine, const ContourResult& contour,
                               HiddenLevels levels = HiddenLevels::Counted) const;

    /// Per snaxel of a visual contour: whether it lies over another object
    /// in the image (PartSelector::over_objects): the surface seen just
    /// outside it (the nearest on the viewer's ray through a point
    /// kOverObjectsStep of the mesh's bounding radius across the contour in
    /// the image plane) belongs to an object other than its own. All false
    /// on a mesh of one object.
    std::vector<std::uint8_t> over_other_objects(const SnaxelEngine& engine, const ContourResult& contour) const;

  private:
    VisibilityRay make_ray(const glm::dvec3& p, const glm::dvec3& n, double scale) const;
    /// QI along @p ray, cast for point @p p of a face of @p object (-1: a
    /// mesh of one object). Where the ray's start, off the surface, went
    /// through another object's surface that passes through p itself (a
    /// box's bottom edge resting on a floor: its outline runs along the
    /// floor, and the offset dips under it), that surface does not hide p:
    /// QI from as far off toward the viewer instead.
    int contact_qi(const VisibilityRay& ray, const glm::dvec3& p, std::int64_t object) const;
    /// QI of @p ray started at @p origin instead, toward the viewer from there.
    int qi_from(const VisibilityRay& ray, const glm::dvec3& origin) const;
    /// QI 0 of @p ray checked: where its start, off the surface, left
    /// another object that p lies inside (a thin rod's contour just inside
    /// the ball it passes through, lifted by a long face's offset past the
    /// ball's surface), the QI from between p and that surface.
    int enclosed_qi(const VisibilityRay& ray, const glm::dvec3& p, std::int64_t object) const;
    /// Whether contact_qi(ray, p, object) is @p q, casting no more than it
    /// needs to tell (a point that is not seen, asked whether its QI is 0,
    /// needs no count of its layers).
    bool qi_is(const VisibilityRay& ray, const glm::dvec3& p, std::int64_t object, int q) const;
    /// classify's HiddenLevels::WhereSeen: counts the levels of the hidden
    /// snaxels of @p snaxel_qi (marked uncounted) that it needs, and gives
    /// the others their stretch's.
    void count_where_seen(const SnaxelEngine& engine, const ContourResult& contour, std::vector<int>& snaxel_qi) const;

    /// @p ray (toward the eye) ended at the near plane: what lies nearer hides nothing.
    void stop_at_near(VisibilityRay& ray) const;

    const RayScene& scene_;
    Camera camera_;
    VisibilityOptions options_;
    double near_ = 0.0;        ///< perspective: the near plane's distance from the eye
    glm::dvec3 forward_{0.0};  ///< the line of sight (unit)
};

/// How far past a silhouette over_other_objects looks, as a fraction of
/// the mesh's bounding radius (about a pixel and a half when the mesh
/// fills an 800-pixel canvas).
inline constexpr double kOverObjectsStep = 0.004;

/// Without hidden lines: the loops of a contour that leaves parts out
/// (snaxel_margin, or a part selector), or that a perspective @p camera's
/// near plane clips, cut into drawn runs (QI 0) and kNotDrawn ones, as
/// classify() cuts them; empty (every loop drawn whole) for the others. A
/// contour drawn only over other objects needs the rays classify() casts:
/// without them none of it is drawn.
ContourVisibility drawn_parts(const SnaxelEngine& engine, const ContourResult& contour, const Camera* camera = nullptr);

/// Per snaxel of @p contour: whether the stretch of its loop from it to the
/// next snaxel (an open loop's last snaxel: from the one before) lies on a
/// part of the scene its spec's selector takes (ContourSpec::parts). A
/// stretch across a face lies on that face's part; a stretch along an edge
/// (creases, borders, material and object lines) on either face's; a
/// stretch of an intersection line on the parts of both surfaces. Empty
/// when the selector takes every part: nothing is left out. Where a loop
/// passes from one part to another the cut is at the snaxel on the edge
/// between them, exactly.
std::vector<std::uint8_t> selected_stretches(const MeshTopology& topology, const ContourResult& contour);

/// The face two snaxels on edges of one face share (kNone if none).
FaceId common_face(const MeshTopology& topology, const Snaxel& a, const Snaxel& b);

} // namespace snaxels
