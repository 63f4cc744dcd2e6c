// What the snaxel-defined map leaves uncovered of large faces that are
// partly hidden (see fill_snaxel_map_gaps in planar_map.h).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "snaxels/planarmap/detail/clip.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

namespace {

/// Faces smaller than this in the image (square pixels) leave no gap worth
/// filling: a dense mesh's occlusion fronts cut them within a pixel.
constexpr double kGapFacePixels = 16.0;
/// Nor, among several objects, faces shorter than this (pixels, their
/// longest side in the image) with a corner no region holds.
constexpr double kGapFaceLength = 6.0;
/// Pieces of the gap thinner than this on average (pixels, across) are
/// mostly the seams between a region's outline and a face's edge, not
/// surface left out; what of them is wider than kSeamWidth is kept.
constexpr double kGapWidth = 0.5;
constexpr double kSeamWidth = 0.2;
/// Pieces smaller than this (square pixels) are left out.
constexpr double kGapPiecePixels = 0.5;

} // namespace

int shading_class_at(const MeshTopology& topo, const RayHit& hit, const ShadingClasses& classes, const Camera& camera,
                     const Light& light) {
    const auto& fv = topo.face_vertices()[hit.face];
    const double w0 = 1.0 - hit.u - hit.v;
    const glm::dvec3 p = w0 * topo.positions()[fv[0]] + hit.u * topo.positions()[fv[1]] + hit.v * topo.positions()[fv[2]];
    glm::dvec3 n = w0 * topo.normals()[fv[0]] + hit.u * topo.normals()[fv[1]] + hit.v * topo.normals()[fv[2]];
    if (const double len = glm::length(n); len > 0.0) n /= len;
    const glm::dvec3 l = light.to_light(p);
    const double nl = glm::dot(n, l);
    const double rv = glm::dot(camera.to_viewer(p), 2.0 * nl * n - l);
    return classes.classify(nl < 0.0, [&](int b) { return nl >= classes.level(2 + b); },
                            [&](int h) { return rv >= classes.level(classes.first_highlight() + h); });
}

namespace {

/// The outline, in the image, of the faces where a gap in @p map can show
/// (none: empty).
ClipperLib::Paths gap_faces(const PlanarMap& map, const MeshTopology& topo, const ImageProjection& projection,
                            const Camera& camera) {
    // The faces that can show where no region reaches: turned to the
    // viewer and large in the image (where something hides part of one,
    // a region's front stops on the face's edges, and between those stops
    // it cuts straight across the face, not along the outline of what
    // hides the rest).
    // Each vertex projected once; the size test comes first (on a dense
    // mesh no face passes it).
    VertexData<glm::dvec2> image(topo.n_vertices());
    parallel_for(topo.vertices(), [&](VertexId v) { image[v] = projection.project(topo.positions()[v]); }, 4096);
    // Among several objects, also a long face with a corner no region
    // holds (hidden, or turned away): the straight cut across it leaves a
    // wedge as long as the face, through which the object behind shows
    // (a thin rod through a ball, its sides' long faces running from a
    // rim turned away to a ring inside the ball).
    const bool long_faces_matter = topo.parts() && topo.parts()->several();
    auto long_and_cut = [&](const std::array<VertexId, 3>& fv, glm::dvec2 pa, glm::dvec2 pb, glm::dvec2 pc) {
        if (map.vertex_region[fv[0]] >= 0 && map.vertex_region[fv[1]] >= 0 && map.vertex_region[fv[2]] >= 0) return false;
        const double longest2 = std::max({glm::dot(pb - pa, pb - pa), glm::dot(pc - pb, pc - pb), glm::dot(pa - pc, pa - pc)});
        return longest2 >= kGapFaceLength * kGapFaceLength;
    };
    // Their union as an outline (faces turned to the viewer all wind one
    // way in the image: the edges two of them share cancel). A face the
    // near plane cuts counts with what of it lies past the plane.
    const NearPlane near(camera, topo);
    std::unordered_map<std::int64_t, glm::dvec2> crossings; // id: image point
    std::vector<NearPlane::FacePoint> cut;
    clip::Outline outline;
    bool any = false;
    for (const FaceId f : topo.faces()) {
        const auto& fv = topo.face_vertices()[f];
        const glm::dvec3 &a = topo.positions()[fv[0]], &b = topo.positions()[fv[1]], &c = topo.positions()[fv[2]];
        if (near.cuts(a) || near.cuts(b) || near.cuts(c)) {
            near.cut_face(topo, f, cut);
            if (cut.empty() || glm::dot(glm::cross(b - a, c - a), camera.to_viewer(cut[0].p)) <= 0.0) continue;
            for (std::size_t k = 0; k < cut.size(); ++k) {
                if (cut[k].id >= std::int64_t(topo.n_vertices())) crossings[cut[k].id] = projection.project(cut[k].p);
                outline.walk(cut[k].id, cut[(k + 1) % cut.size()].id);
            }
            any = true;
            continue;
        }
        const glm::dvec2 pa = image[fv[0]], pb = image[fv[1]], pc = image[fv[2]];
        const double pixels = 0.5 * std::abs((pb.x - pa.x) * (pc.y - pa.y) - (pc.x - pa.x) * (pb.y - pa.y));
        if (pixels < kGapFacePixels && !(long_faces_matter && long_and_cut(fv, pa, pb, pc))) continue;
        if (glm::dot(glm::cross(b - a, c - a), camera.to_viewer((a + b + c) / 3.0)) <= 0.0) continue;
        if (topo.has_strips() && !face_has_area(topo, f)) continue;
        for (std::size_t k = 0; k < 3; ++k) outline.walk(fv[k].index(), fv[(k + 1) % 3].index());
        any = true;
    }
    if (!any) return {};
    return outline.paths([&](std::int64_t id) {
        return id < std::int64_t(topo.n_vertices()) ? image[VertexId(std::int32_t(id))] : crossings.at(id);
    });
}

/// The region of @p map of class @p region_class at @p level nearest on the
/// mesh to @p face: at its corners, else within two rings of them (a piece
/// beside an occluder can lie in a face whose corners are all hidden); -1
/// when there is none.
std::int32_t nearest_region(const PlanarMap& map, const MeshTopology& topo, FaceId face, RegionClass region_class,
                            double level) {
    std::int32_t into = -1;
    std::vector<VertexId> ring(topo.face_vertices()[face].begin(), topo.face_vertices()[face].end());
    std::vector<VertexId> seen = ring;
    for (int rings = 0; rings <= 2 && into < 0; ++rings) {
        for (const VertexId v : ring) {
            const std::int32_t r = map.vertex_region[v];
            if (r >= 0 && map.regions[r].cls == region_class && map.regions[r].k == level) {
                into = r;
                break;
            }
        }
        std::vector<VertexId> next;
        for (const VertexId v : ring)
            for (const VertexId w : topo.neighbours(v))
                if (std::find(seen.begin(), seen.end(), w) == seen.end()) seen.push_back(w), next.push_back(w);
        ring = std::move(next);
    }
    return into;
}

} // namespace

void fill_snaxel_map_gaps(PlanarMap& map, const SnaxelEngine& engine, const SnaxelMapInput& input, const RayScene& rays,
                          const ImageProjection& projection, const Camera& camera, const Light& light) {
    const MeshTopology& topo = engine.topology();
    if (map.vertex_region.size() != topo.n_vertices()) return;
    const ClipperLib::Paths faces = gap_faces(map, topo, projection, camera);
    if (faces.empty()) return;
    clip::Box reach;
    for (const ClipperLib::Path& path : faces) reach.add(path);
    // What of them no region covers.
    ClipperLib::Paths covered;
    for (const MapRegion& region : map.regions) {
        for (ClipperLib::Path& path : clip::to_paths(region.polygons)) {
            clip::Box box;
            box.add(path);
            if (box.meets(reach)) covered.push_back(std::move(path));
        }
    }
    ClipperLib::PolyTree tree;
    clip::difference_tree(faces, covered, tree);
    // Each piece is the surface seen through it: the class the rays through
    // its inside points find over most of the spans' width, by the shading
    // at the hit (the normalized interpolated normal, as the contours
    // follow it). It joins the region of that class one of the hit face's
    // corners is in, or becomes a region of its own.
    const ShadingClasses classes = shading_classes(input);
    const NearPlane near(camera, topo);
    const double back = 4.0 * bounding_radius(topo) + 1.0;
    int deepest = 0;
    for (const MapRegion& region : map.regions) deepest = std::max(deepest, region.depth);
    // Seams between a region's outline and a face's edge are left out:
    // pieces under half a pixel, and what of a piece thinner than kGapWidth
    // on average (twice the area over the perimeter is a strip's width)
    // an opening by kSeamWidth / 2 takes away (a seam can join a wedge of
    // real surface left on a long thin face, which the opening keeps).
    std::vector<ClipperLib::Paths> pieces;
    for (ClipperLib::Paths& piece : clip::pieces_of(tree)) {
        const double pixels = clip::area(piece);
        if (pixels < kGapPiecePixels) continue;
        if (2.0 * pixels >= kGapWidth * clip::perimeter(piece)) {
            pieces.push_back(std::move(piece));
            continue;
        }
        for (ClipperLib::Paths& part : clip::pieces_of_opened(piece, 0.5 * kSeamWidth))
            if (clip::area(part) >= kGapPiecePixels) pieces.push_back(std::move(part));
    }
    for (const ClipperLib::Paths& piece : pieces) {
        std::map<int, std::pair<double, FaceId>> votes; // class: width, a face seen
        for (const clip::InsidePoint& point : clip::inside_points(piece)) {
            VisibilityRay ray;
            projection.pixel_ray(point.at, back, ray.origin, ray.dir);
            ray.origin = near.ray_start(ray.origin, ray.dir);
            ray.tfar = std::numeric_limits<double>::infinity();
            const RayHit hit = rays.nearest(ray);
            if (!hit.hit()) continue;
            const int cls = shading_class_at(topo, hit, classes, camera, light);
            auto& vote = votes.try_emplace(cls, 0.0, hit.face).first->second;
            vote.first += point.width;
        }
        if (votes.empty()) continue;
        const auto best = std::max_element(votes.begin(), votes.end(),
                                           [](const auto& a, const auto& b) { return a.second.first < b.second.first; });
        const int cls = best->first;
        const RegionClass region_class = classes.region_class(cls);
        const double level = classes.level(cls);
        // The region of that class nearest on the mesh: at the hit face's
        // corners, else within two rings of them (a piece beside an
        // occluder can lie in a face whose corners are all hidden). Joined
        // to it, the piece keeps the region's identity through animation.
        const std::int32_t into = nearest_region(map, topo, best->second.second, region_class, level);
        if (into >= 0) {
            MapRegion& region = map.regions[into];
            const ClipperLib::Paths joined = clip::op(clip::to_paths(region.polygons), piece, ClipperLib::ctUnion);
            region.polygons = clip::from_paths(joined);
            region.area = clip::area(joined);
        } else {
            MapRegion region;
            region.cls = region_class;
            region.k = level;
            region.depth = deepest + 1;
            region.polygons = clip::from_paths(piece);
            region.area = clip::area(piece);
            // The hit face's corners no region holds go with it, so that the
            // region tracker (which follows regions by their vertices) finds
            // it again in the next frame.
            for (const VertexId v : topo.face_vertices()[best->second.second])
                if (map.vertex_region[v] < 0) map.vertex_region[v] = std::int32_t(map.regions.size());
            map.regions.push_back(std::move(region));
        }
    }
}

} // namespace snaxels
