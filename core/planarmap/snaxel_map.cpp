// The snaxel-defined planar map, its first stages: the vertices labelled,
// the regions grown (flecks dissolved) and the points placed where fronts
// stop on the edges (the later stages: snaxel_map_walk.cpp).
#include "snaxels/planarmap/detail/snaxel_map_builder.h"

namespace snaxels {
namespace detail {

SnaxelMap SnaxelMapBuilder::build() {
    const auto start = std::chrono::steady_clock::now();
    label_vertices();
    grow_regions();
    place_edge_points();
    select_faces();
    walk_faces();
    take_rim_rings();
    cancel_opposite_steps();
    chain_outlines();
    class_and_rank_regions();
    map_.vertex_region = std::move(comp_);
    map_.stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return std::move(map_);
}

std::vector<double> SnaxelMapBuilder::shading_levels(const SnaxelMapInput& in) {
    std::vector<double> l{0.0};
    for (const ContourResult* iso : in.isophotes) l.push_back(iso->spec.k);
    return l;
}

bool SnaxelMapBuilder::face_hidden(FaceId f) const {
    const auto& fv = topo_.face_vertices()[f];
    const glm::dvec3 &p0 = position(fv[0]), &p1 = position(fv[1]), &p2 = position(fv[2]);
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    if (topo_.has_strips() && !face_has_area(topo_, f)) return true; // a sharp edge's strip covers nothing
    if (near_.cuts((p0 + p1 + p2) / 3.0)) return true;                 // its middle cut by the near plane
    return rays_.occluded(sampler_.face_ray(f, (p0 + p1 + p2) / 3.0, glm::normalize(n)));
}

void SnaxelMapBuilder::label_vertices() {
    label_.assign(topo_.n_vertices(), VertexLabel::occluded());
    nl_.assign(topo_.n_vertices(), 0.0);
    // The rays cast beforehand, if cast in this pose and camera.
    const VertexSight* sight = in_.sight && in_.sight->pose == topo_.pose() && in_.sight->camera == camera_ &&
                                       in_.sight->code.size() == topo_.n_vertices()
                                   ? in_.sight
                                   : nullptr;
    const bool open = sight ? sight->open : is_open(topo_);
    parallel_for(topo_.vertices(), [&](VertexId v) {
        label_[v] = label_vertex(v, open, sight);
        // N.L of the vertices turned away too, which the walk past the contour uses.
        if (label_[v].is_away()) nl_[v] = glm::dot(topo_.normals()[v], light_.to_light(position(v)));
    }, 256);
}

VertexLabel SnaxelMapBuilder::label_vertex(VertexId v, bool open, const VertexSight* sight) {
    if (near_.cuts(position(v))) return VertexLabel::occluded(); // cut by the near plane: in no region
    const bool turned_away = visual_.vertex_f[v] < 0.0;
    // The ray cast beforehand where it was cast from this side.
    const bool same_side =
        sight && bool(sight->code[v] & VertexSight::kTurnedAway) == turned_away;
    const std::uint8_t code = same_side ? sight->code[v] : sight_of(rays_, sampler_, v, turned_away, open);
    if (!(code & VertexSight::kCast)) return VertexLabel::away();
    if (code & VertexSight::kBlocked) {
        // Hidden; one turned away is hidden by its own fold as often as
        // not, and faces past the contour may still be seen whole.
        return turned_away ? VertexLabel::away() : VertexLabel::occluded();
    }
    nl_[v] = glm::dot(topo_.normals()[v], light_.to_light(position(v)));
    // Seen although turned away: through a hole of an open mesh, or a
    // corner past the contour of interpolated normals. Its side of the
    // surface forms its own regions, classed by N.L alone.
    if (turned_away) return VertexLabel::far_side(class_of(nl_[v]));
    return VertexLabel::near_side(classes_.classify(
        in_.shadow && in_.shadow->vertex_f[v] < 0.0, [&](int b) { return in_.isophotes[b]->vertex_f[v] >= 0.0; },
        [&](int h) { return in_.gleams[h]->vertex_f[v] >= 0.0; }));
}

void SnaxelMapBuilder::grow_regions() {
    comp_label_.resize(std::size_t(grow_vertex_sets(
        topo_, comp_, [&](VertexId v) { return label(v).seen(); },
        [&](VertexId v, VertexId w) { return label(v) == label(w); })));
    for (const VertexId v : topo_.vertices())
        if (comp_[v] != kNoRegion) comp_label_[comp_[v]] = label(v);
    map_.stats.seeds = comp_label_.size();
    for (int pass = 0; pass < 3; ++pass) { // dissolving can leave a new fleck behind
        const auto moves = fleck_moves();
        if (moves.empty()) break;
        regrow_moved(moves);
        map_.stats.seeds += comp_label_.size();
    }
    for (const VertexLabel l : label_) { // as the flecks left them
        if (l.seen()) ++map_.stats.visible_vertices;
        if (l.is_occluded()) ++map_.stats.occluded_vertices;
    }
}

double SnaxelMapBuilder::vertex_area(VertexId v) const {
    double area = 0.0;
    topo_.for_each_face_beside_edges(v, [&](FaceId f) {
        const auto& fv = topo_.face_vertices()[f];
        const glm::dvec2 p0 = projection_.project(position(fv[0]));
        const glm::dvec2 p1 = projection_.project(position(fv[1]));
        const glm::dvec2 p2 = projection_.project(position(fv[2]));
        area += std::abs((p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y)) / 12.0;
    });
    return area;
}

std::vector<std::pair<VertexId, VertexLabel>> SnaxelMapBuilder::fleck_moves() const {
    std::vector<char> supported(comp_label_.size(), 0);
    std::vector<int> size(comp_label_.size(), 0);
    for (const std::int32_t r : comp_)
        if (r != kNoRegion) ++size[r];
    // Only the vertices of regions of few vertices can be flecks.
    std::vector<VertexId> small;
    for (const VertexId v : topo_.vertices()) {
        const std::int32_t r = comp_[v];
        if (r != kNoRegion && size[r] < in_.min_unsupported_vertices) small.push_back(v);
    }
    std::vector<double> image_area(comp_label_.size(), 0.0);
    for (const VertexId v : small) image_area[comp_[v]] += vertex_area(v);
    for (std::size_t r = 0; r < size.size(); ++r)
        supported[r] = size[r] >= in_.min_unsupported_vertices || image_area[r] >= in_.min_fleck_area_px;
    for (const VertexId v : small) {
        const std::int32_t r = comp_[v];
        if (supported[r]) continue;
        const auto ring = topo_.neighbours(v);
        const bool interior = !ring.empty() && std::all_of(ring.begin(), ring.end(), [&](VertexId w) { return label(w) == label(v); });
        supported[r] = interior;
    }
    std::vector<std::pair<VertexId, VertexLabel>> moves;
    for (const VertexId v : small) {
        const std::int32_t r = comp_[v];
        if (supported[r]) continue;
        VertexLabel best = label(v);
        int best_count = 0;
        const auto ring = topo_.neighbours(v);
        for (const VertexId w : ring) {
            if (comp_[w] == r) continue;
            const VertexLabel candidate = label(w);
            int count = 0;
            for (const VertexId u : ring) count += comp_[u] != r && label(u) == candidate;
            if (count > best_count || (count == best_count && candidate > best)) best = candidate, best_count = count;
        }
        if (best != label(v)) moves.emplace_back(v, best);
    }
    return moves;
}

void SnaxelMapBuilder::regrow_moved(const std::vector<std::pair<VertexId, VertexLabel>>& moves) {
    std::vector<std::int32_t> parent(comp_label_.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::int32_t r) {
        while (parent[r] != r) r = parent[r] = parent[parent[r]];
        return r;
    };
    constexpr std::int32_t kToGrow = -2;
    for (const auto& [v, l] : moves) {
        label_[v] = l;
        comp_[v] = kToGrow;
    }
    std::vector<VertexId> stack;
    for (const auto& [v0, l0] : moves) {
        if (comp_[v0] != kToGrow) continue;
        if (!l0.seen()) {
            comp_[v0] = kNoRegion;
            continue;
        }
        const auto id = std::int32_t(comp_label_.size());
        comp_label_.push_back(l0);
        parent.push_back(id);
        comp_[v0] = id;
        stack.push_back(v0);
        while (!stack.empty()) {
            const VertexId v = stack.back();
            stack.pop_back();
            for (const VertexId w : topo_.neighbours(v)) {
                if (label(w) != l0) continue;
                if (comp_[w] == kToGrow) {
                    comp_[w] = id;
                    stack.push_back(w);
                } else if (comp_[w] != kNoRegion) {
                    parent[find(comp_[w])] = find(id);
                }
            }
        }
    }
    std::vector<std::int32_t> index(comp_label_.size(), kNoRegion);
    std::vector<VertexLabel> labels;
    for (std::int32_t& r : comp_) {
        if (r == kNoRegion) continue;
        const std::int32_t root = find(r);
        if (index[root] == kNoRegion) {
            index[root] = std::int32_t(labels.size());
            labels.push_back(comp_label_[root]);
        }
        r = index[root];
    }
    comp_label_ = std::move(labels);
}

void SnaxelMapBuilder::place_edge_points() {
    // Found in parallel stretches of the edges, joined in edge order.
    constexpr std::size_t kStretches = 64;
    std::vector<std::vector<EdgeId>> cut(kStretches);
    const std::size_t n_edges = topo_.n_edges();
    parallel_for(kStretches, [&](std::size_t k) {
        for (std::size_t i = k * n_edges / kStretches; i < (k + 1) * n_edges / kStretches; ++i) {
            const EdgeId e{std::int32_t(i)};
            if (label(topo_.edge_vertices()[e][0]) != label(topo_.edge_vertices()[e][1]))
                cut[k].push_back(e); // both hidden: a junction may still use its middle
        }
    }, 1);
    for (const std::vector<EdgeId>& stretch : cut) cut_edges_.insert(cut_edges_.end(), stretch.begin(), stretch.end());
    edge_point_.assign(topo_.n_edges(), glm::dvec3(0.0));
    // Which faces are turned to the viewer (by their own winding).
    front_face_.assign(topo_.n_faces(), 0);
    parallel_for(topo_.faces(), [&](FaceId f) {
        const auto& fv = topo_.face_vertices()[f];
        const glm::dvec3 &p0 = position(fv[0]), &p1 = position(fv[1]), &p2 = position(fv[2]);
        front_face_[f] = glm::dot(glm::cross(p1 - p0, p2 - p0), camera_.to_viewer((p0 + p1 + p2) / 3.0)) > 0.0;
    }, 4096);
    const ContourImage occluder(engine_, visual_, projection_, near_, [&](const glm::dvec3& p) { return depth_of(p); });
    parallel_for(cut_edges_.size(), [&](std::size_t i) {
        const EdgeId e = cut_edges_[i];
        edge_point_[e] = edge_point(e, occluder);
    }, 64);
}

glm::dvec3 SnaxelMapBuilder::snaxel_point(const ContourResult& r, EdgeId e, VertexId a, VertexId b) const {
    const std::int32_t s = r.fronts.edge_snaxel.empty() ? kNoSnaxel : r.fronts.edge_snaxel[e];
    if (s != kNoSnaxel) return engine_.position(r.fronts.snaxels[s]);
    const double t = linear_root(r.vertex_f[a], r.vertex_f[b]);
    return glm::mix(position(a), position(b), t);
}

glm::dvec3 SnaxelMapBuilder::edge_point(EdgeId e, const ContourImage& occluder) const {
    const auto [a, b] = topo_.edge_vertices()[e];
    const VertexLabel la = label(a), lb = label(b);
    if (!la.seen() && !lb.seen()) return 0.5 * (position(a) + position(b));
    if (la.is_away() || lb.is_away()) return snaxel_point(visual_, e, a, b); // the visual contour (closed meshes)
    if (la.on_far_side() != lb.on_far_side() && la.seen() && lb.seen())
        return snaxel_point(visual_, e, a, b); // the visual contour between the two sides
    if (la.is_occluded() || lb.is_occluded()) return occlusion_point(e, occluder);
    if (la.on_far_side()) {
        // Two classes on the far side: the root of N.L at the level between them.
        const int top = std::max(la, lb).cls();
        const double level = levels_[std::max(top - 1, 0)];
        return glm::mix(position(a), position(b), linear_root(nl_[a] - level, nl_[b] - level));
    }
    // Two shading classes: the front of the brighter one's kind.
    const int top = std::max(la, lb).cls();
    const ContourResult* kind = top >= highlight_ ? in_.gleams[top - highlight_]
                                : top >= 2        ? in_.isophotes[top - 2]
                                                  : in_.shadow;
    return kind ? snaxel_point(*kind, e, a, b) : 0.5 * (position(a) + position(b));
}

glm::dvec3 SnaxelMapBuilder::occlusion_point(EdgeId e, const ContourImage& occluder) const {
    const auto [a, b] = topo_.edge_vertices()[e];
    const VertexId from = label(a).seen() ? a : b, to = label(a).seen() ? b : a;
    const glm::dvec3& p0 = position(from);
    // Toward a vertex the near plane cuts, the edge is seen at most up to the plane.
    const double reach = near_.cuts(position(to)) ? near_.crossing(p0, position(to)) : 1.0;
    const glm::dvec3 p1 = glm::mix(p0, position(to), reach);
    const double t = occluder.first_crossing(projection_.project(p0), projection_.project(p1),
                                             [&](double s) { return depth_of(glm::mix(p0, p1, s)); });
    if (t >= 0.0) return glm::mix(p0, p1, t);
    // Toward the near plane no ray can say where the edge is hidden (at
    // the plane nothing is nearer): unless a nearer outline crosses it
    // first, it is seen up to the plane.
    if (reach < 1.0) return p1;
    double lo = from == a ? 0.0 : 1.0, hi = 1.0 - lo; // lo visible, hi occluded
    const double pixels = glm::length(projection_.project(p0) - projection_.project(p1));
    const int steps =
        std::clamp(int(std::ceil(std::log2(std::max(pixels / in_.tolerance_px, 1.0)))), 1, in_.bisection_steps);
    for (int step = 0; step < steps; ++step) {
        const double mid = 0.5 * (lo + hi);
        (rays_.occluded(sampler_.edge_ray(e, mid)) ? hi : lo) = mid;
    }
    return glm::mix(position(a), position(b), 0.5 * (lo + hi));
}

} // namespace detail

VertexSight see_vertices(const MeshTopology& topology, const RayScene& rays, const Camera& camera, const Light& light,
                         const ContourSpec& visual) {
    VertexData<double> f;
    ContourFunction(visual, camera, light).evaluate_vertices(topology, f);
    const bool open = detail::is_open(topology);
    const VisibilitySampler sampler(rays, camera, detail::refined_scale());
    VertexSight sight;
    sight.code.assign(topology.n_vertices(), 0);
    sight.pose = topology.pose();
    sight.camera = camera;
    sight.open = open;
    parallel_for(topology.vertices(), [&](VertexId v) { sight.code[v] = detail::sight_of(rays, sampler, v, f[v] < 0.0, open); }, 256);
    return sight;
}

SnaxelMap build_snaxel_map(const SnaxelEngine& engine, const SnaxelMapInput& in, const RayScene& rays,
                           const ImageProjection& projection, const Camera& camera, const Light& light) {
    return detail::SnaxelMapBuilder(engine, in, rays, projection, camera, light).build();
}

} // namespace snaxels
