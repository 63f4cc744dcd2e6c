#include "snaxels/visibility/near_plane.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "snaxels/error.h"

namespace snaxels {

double near_plane_of(const Camera& camera, const MeshTopology& topology) {
    if (camera.orthographic()) return 0.0;
    return camera.near_plane(camera.near_clip > 0.0 ? 0.0 : bounding_radius(topology));
}

NearPlane::NearPlane(const Camera& camera, const MeshTopology& topology)
    : NearPlane(camera, near_plane_of(camera, topology)) {}

NearPlane::NearPlane(const Camera& camera, double distance)
    : eye_(camera.eye), forward_(camera.forward()), distance_(distance), active_(!camera.orthographic()) {}

double NearPlane::crossing(const glm::dvec3& a, const glm::dvec3& b) const {
    const double da = past(a), db = past(b);
    return da == db ? 0.0 : std::clamp(da / (da - db), 0.0, 1.0);
}

std::vector<glm::dvec3> NearPlane::clip(std::span<const glm::dvec3> loop) const {
    const std::size_t n = loop.size();
    if (!active_ || std::none_of(loop.begin(), loop.end(), [&](const glm::dvec3& p) { return cuts(p); }))
        return {loop.begin(), loop.end()};
    // Sutherland-Hodgman against the one plane.
    std::vector<glm::dvec3> out;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& a = loop[i];
        const glm::dvec3& b = loop[(i + 1) % n];
        const bool in_a = !cuts(a), in_b = !cuts(b);
        if (in_a) out.push_back(a);
        if (in_a != in_b) out.push_back(glm::mix(a, b, crossing(a, b)));
    }
    if (out.size() < 3) out.clear();
    return out;
}

std::vector<std::vector<glm::dvec3>> NearPlane::clip_polyline(std::vector<glm::dvec3> points) const {
    std::vector<std::vector<glm::dvec3>> pieces;
    if (!active_ || std::none_of(points.begin(), points.end(), [&](const glm::dvec3& p) { return cuts(p); })) {
        pieces.push_back(std::move(points));
        return pieces;
    }
    std::vector<glm::dvec3> piece;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const bool in = !cuts(points[k]);
        if (k > 0 && in != !cuts(points[k - 1]))
            piece.push_back(glm::mix(points[k - 1], points[k], crossing(points[k - 1], points[k])));
        if (in) {
            piece.push_back(points[k]);
        } else if (!piece.empty()) {
            if (piece.size() >= 2) pieces.push_back(std::move(piece));
            piece.clear();
        }
    }
    if (piece.size() >= 2) pieces.push_back(std::move(piece));
    return pieces;
}

void NearPlane::cut_face(const MeshTopology& topology, FaceId f, std::vector<FacePoint>& out) const {
    out.clear();
    const auto& fv = topology.face_vertices()[f];
    const auto& fe = topology.face_edges()[f];
    const auto positions = topology.positions();
    for (std::size_t k = 0; k < 3; ++k) {
        const VertexId v = fv[k], w = fv[(k + 1) % 3];
        const bool in_v = !cuts(positions[v]), in_w = !cuts(positions[w]);
        if (in_v) out.push_back({v.index(), positions[v]});
        if (in_v == in_w) continue;
        // From the edge's own first vertex, so that both faces agree.
        const auto [a, b] = topology.edge_vertices()[fe[k]];
        out.push_back({std::int64_t(topology.n_vertices()) + fe[k].index(),
                       glm::mix(positions[a], positions[b], crossing(positions[a], positions[b]))});
    }
}

namespace {

/// The distance from @p p to the segment @p a -> @p b.
double segment_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

/// Whether triangle @p a, @p b, @p c passes within @p eps of @p p.
bool within(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double eps) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double area2 = glm::length(n);
    if (area2 > 0.0) {
        const double height = glm::dot(p - a, n) / area2;
        if (std::abs(height) > eps) return false;
        // The foot of p inside the triangle: each edge sees it on the face's side.
        const glm::dvec3 q = p - height * n / area2;
        if (glm::dot(glm::cross(b - a, q - a), n) >= 0.0 && glm::dot(glm::cross(c - b, q - b), n) >= 0.0 &&
            glm::dot(glm::cross(a - c, q - c), n) >= 0.0)
            return true;
    }
    return segment_distance(p, a, b) <= eps || segment_distance(p, b, c) <= eps || segment_distance(p, c, a) <= eps;
}

} // namespace

void require_eye_off_surface(const Camera& camera, const MeshTopology& topology) {
    if (camera.orthographic()) return;
    const double eps = 1e-6 * std::max(bounding_radius(topology), 1e-300);
    const auto positions = topology.positions();
    for (const FaceId f : topology.faces()) {
        const auto& fv = topology.face_vertices()[f];
        if (!within(camera.eye, positions[fv[0]], positions[fv[1]], positions[fv[2]], eps)) continue;
        char eye[96];
        std::snprintf(eye, sizeof eye, "(%g, %g, %g)", camera.eye.x, camera.eye.y, camera.eye.z);
        throw Error(std::string("the eye ") + eye + " lies on the surface (face " + std::to_string(f.index()) +
                    " passes through it), where the surface is seen edge-on and cannot be drawn; move the eye off "
                    "the surface");
    }
}

} // namespace snaxels
