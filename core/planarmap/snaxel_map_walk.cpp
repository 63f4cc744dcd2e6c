// The snaxel-defined planar map, its later stages: the faces walked into
// outline steps, the rim past creases taken, steps walked both ways
// cancelled, the outlines chained and the regions classed and ranked by
// depth (the first stages: snaxel_map.cpp).
#include "snaxels/planarmap/detail/snaxel_map_builder.h"

namespace snaxels::detail {

glm::dvec3 SnaxelMapBuilder::point_of(PointId id) const {
    switch (ids_.kind(id)) {
    case PointKind::Vertex: return position(ids_.vertex_of(id));
    case PointKind::EdgePoint: return edge_point_[ids_.edge_of(id)];
    case PointKind::Junction: {
        const auto& fe = topo_.face_edges()[ids_.face_of(id)];
        return (edge_point_[fe[0]] + edge_point_[fe[1]] + edge_point_[fe[2]]) / 3.0;
    }
    default: return extra_point_.at(id.value);
    }
}

double SnaxelMapBuilder::nl_on_edge(EdgeId e) const {
    const auto [u, w] = topo_.edge_vertices()[e];
    const double len = glm::length(position(w) - position(u));
    const double t = len > 0.0 ? glm::length(edge_point_[e] - position(u)) / len : 0.5;
    return glm::mix(nl_[u], nl_[w], std::clamp(t, 0.0, 1.0));
}

double SnaxelMapBuilder::nl_of(PointId id) const {
    switch (ids_.kind(id)) {
    case PointKind::Vertex: return nl_[ids_.vertex_of(id)];
    case PointKind::EdgePoint: return nl_on_edge(ids_.edge_of(id));
    default: {
        const auto& fe = topo_.face_edges()[ids_.face_of(id)];
        return (nl_on_edge(fe[0]) + nl_on_edge(fe[1]) + nl_on_edge(fe[2])) / 3.0;
    }
    }
}

void SnaxelMapBuilder::select_faces() {
    folded_.assign(topo_.n_faces(), 0);
    FaceData<char> walked(topo_.n_faces(), 0);
    parallel_for(topo_.faces(), [&](FaceId f) {
        const auto& fv = topo_.face_vertices()[f];
        const auto& fe = topo_.face_edges()[f];
        bool near_side = false;
        for (const VertexId v : fv) {
            const std::int32_t r = comp_[v];
            near_side = near_side || (r != kNoRegion && !comp_label_[r].on_far_side());
        }
        folded_[f] = near_side && !front_face_[f];
        // Only faces with a cut edge or a seen mesh-boundary edge, and
        // folded faces, have such steps.
        bool walk = folded_[f];
        for (std::size_t k = 0; k < 3 && !walk; ++k) {
            const VertexLabel la = label(fv[k]), lb = label(fv[(k + 1) % 3]);
            walk = la != lb || (la.seen() && topo_.is_boundary_edge(fe[k]));
        }
        walked[f] = walk;
    }, 4096);
    faces_.reserve(2 * cut_edges_.size());
    for (const FaceId f : topo_.faces())
        if (walked[f]) faces_.push_back(f);
}

void SnaxelMapBuilder::walk_faces() {
    const auto first_strip = std::int32_t(comp_label_.size());
    // Strip regions are added while other threads read the labels: room
    // for one per class is made first, so adding one never moves them.
    comp_label_.reserve(comp_label_.size() + std::size_t(classes_.count()));
    const std::size_t chunks = std::max<std::size_t>(1, std::thread::hardware_concurrency());
    std::vector<WalkOut> walk(chunks);
    parallel_for(chunks, [&](std::size_t chunk) {
        for (std::size_t fi = chunk * faces_.size() / chunks; fi < (chunk + 1) * faces_.size() / chunks; ++fi)
            walk_face(faces_[fi], walk[chunk]);
    }, 1);
    for (WalkOut& w : walk) {
        steps_.insert(steps_.end(), w.steps.begin(), w.steps.end());
        rim_faces_.insert(rim_faces_.end(), w.rim_faces.begin(), w.rim_faces.end());
    }
    number_strips_by_class(first_strip);
}

void SnaxelMapBuilder::number_strips_by_class(std::int32_t first_strip) {
    if (outline_regions_.empty()) return;
    std::vector<std::pair<int, std::int32_t>> by_class(outline_regions_.begin(), outline_regions_.end());
    std::sort(by_class.begin(), by_class.end());
    std::vector<std::int32_t> renumbered(comp_label_.size());
    std::iota(renumbered.begin(), renumbered.end(), 0);
    for (std::size_t i = 0; i < by_class.size(); ++i) {
        const std::int32_t id = first_strip + std::int32_t(i);
        renumbered[by_class[i].second] = id;
        comp_label_[id] = VertexLabel::near_side(by_class[i].first);
        outline_regions_[by_class[i].first] = id;
    }
    for (Step& step : steps_) step = Step(renumbered[step.region()], step.from(), step.to);
    for (auto& [r, f] : vertexless_faces_) r = renumbered[r];
}

void SnaxelMapBuilder::walk_face(FaceId f, WalkOut& out) {
    const auto& fv = topo_.face_vertices()[f];
    const auto& fe = topo_.face_edges()[f];
    FaceWalk w{f, fv, fe, {label(fv[0]), label(fv[1]), label(fv[2])}, {comp_[fv[0]], comp_[fv[1]], comp_[fv[2]]}, false, {}, {}};
    if (!w.l[0].seen() && !w.l[1].seen() && !w.l[2].seen()) return;
    const bool uniform = w.l[0] == w.l[1] && w.l[1] == w.l[2];
    const bool rim = topo_.is_boundary_edge(fe[0]) || topo_.is_boundary_edge(fe[1]) || topo_.is_boundary_edge(fe[2]);
    if (uniform && !rim && !folded_[f]) return;
    w.three = w.l[0] != w.l[1] && w.l[1] != w.l[2] && w.l[0] != w.l[2];
    for (int owner = 0; owner < 3; ++owner) {
        const std::int32_t r = w.c[owner];
        if (r == kNoRegion) continue;
        bool seen = false; // each region once per face
        for (int k = 0; k < owner; ++k) seen = seen || w.c[k] == r;
        if (seen) continue;
        const int n = piece(w, [&](int k) { return w.c[k] == r; });
        // A folded piece: walked forwards and backwards its steps across
        // the face and along the mesh's boundary cancel; its steps
        // along interior edges remain, backwards.
        const bool backwards = folded_[f] && !comp_label_[r].on_far_side();
        for (int i = 0; i < n; ++i) {
            const PointId a = w.ids[i], b = w.ids[(i + 1) % n];
            const bool across = w.along[i] < 0 || (ids_.kind(a) != PointKind::Vertex && ids_.kind(b) != PointKind::Vertex);
            const bool outline = across || topo_.is_boundary_edge(fe[w.along[i]]);
            if (backwards) {
                if (!outline) out.steps.emplace_back(r, b, a);
            } else if (outline) {
                out.steps.emplace_back(r, a, b);
            }
        }
    }
    walk_part_past_contour(w, out);
}

void SnaxelMapBuilder::walk_part_past_contour(FaceWalk& w, WalkOut& out) {
    int away = 0, front = 0, most = 0;
    std::int32_t region = kNoRegion;
    for (int k = 0; k < 3; ++k) {
        if (w.l[k].is_away()) ++away;
        if (w.c[k] == kNoRegion) continue;
        ++front;
        int count = 0;
        for (int j = 0; j < 3; ++j) count += w.c[j] == w.c[k];
        if (count > most) most = count, region = w.c[k];
    }
    if (away == 0 || front == 0 || away + front != 3) return; // no hidden corner
    if (region == kNoRegion || !front_face_[w.f]) return;
    // Only where the face itself is seen (past a fold it may lie behind the nearer sheet).
    if (face_hidden(w.f)) return;
    const int n = piece(w, [&](int k) { return w.l[k].is_away(); });
    // The part keeps its region's class where the shading there agrees.
    double nls[7];
    bool one_class = true;
    for (int k = 0; k < n; ++k) {
        nls[k] = nl_of(w.ids[k]);
        one_class = one_class && VertexLabel::near_side(class_of(nls[k])) == comp_label_[region];
    }
    if (one_class) { // the usual case: no level crosses the part
        for (int k = 0; k < n; ++k) out.steps.emplace_back(region, w.ids[k], w.ids[(k + 1) % n]);
    } else {
        std::vector<RimPoint> part;
        for (int k = 0; k < n; ++k) part.push_back({w.ids[k], w.along[k], point_of(w.ids[k]), nls[k]});
        split_part_by_class(std::move(part), w.f, region, out);
    }
    out.rim_faces.emplace_back(w.f, region);
}

void SnaxelMapBuilder::split_part_by_class(std::vector<RimPoint> part, FaceId f, std::int32_t region, WalkOut& out) {
    const std::lock_guard<std::mutex> lock(shared_points_);
    const auto& fe = topo_.face_edges()[f];
    std::vector<std::size_t> levels;
    for (std::size_t level = in_.shadow ? 0 : 1; level < levels_.size(); ++level) levels.push_back(level);
    const auto parts = detail::cut_polygon(std::move(part), levels, [&](const std::vector<RimPoint>& poly, std::size_t level) {
        return split_rim(poly, f, level, fe);
    });
    for (const auto& poly : parts) {
        double mid_nl = 0.0;
        for (const RimPoint& q : poly) mid_nl += q.nl;
        mid_nl /= double(poly.size());
        const int cls = class_of(mid_nl);
        const std::int32_t target =
            VertexLabel::near_side(cls) == comp_label_[region] ? region : outline_region(cls);
        if (target != region) vertexless_faces_.emplace_back(target, f);
        for (std::size_t k = 0; k < poly.size(); ++k) out.steps.emplace_back(target, poly[k].id, poly[(k + 1) % poly.size()].id);
    }
}

std::int32_t SnaxelMapBuilder::outline_region(int cls) {
    const auto it = outline_regions_.find(cls);
    if (it != outline_regions_.end()) return it->second;
    const auto id = std::int32_t(comp_label_.size());
    comp_label_.push_back(VertexLabel::near_side(cls));
    outline_regions_[cls] = id;
    return id;
}

std::pair<std::vector<RimPoint>, std::vector<RimPoint>> SnaxelMapBuilder::split_rim(const std::vector<RimPoint>& poly, FaceId f,
                                                                  std::size_t level, const std::array<EdgeId, 3>& fe) {
    const double value = levels_[level];
    auto crossing = [&](const RimPoint& a, const RimPoint& b, std::size_t k) {
        RimPoint q;
        q.along = a.along;
        if (a.along >= 0) {
            // On face edge a.along: the edge's own root, the same for both faces.
            const EdgeId e = fe[a.along];
            const auto [u, w] = topo_.edge_vertices()[e];
            const double t = linear_root(nl_[u] - value, nl_[w] - value);
            q.id = ids_.level(e, level);
            q.p = glm::mix(position(u), position(w), t);
        } else {
            const double t = std::clamp((value - a.nl) / (b.nl - a.nl), 0.0, 1.0);
            q.id = ids_.across(f, level, k);
            q.p = glm::mix(a.p, b.p, t);
        }
        q.nl = value;
        extra_point_[q.id.value] = q.p;
        return q;
    };
    return detail::split_polygon(poly, [&](const RimPoint& q) { return q.nl < value; }, crossing,
                                 [](RimPoint&, RimPoint&, bool) {});
}

void SnaxelMapBuilder::take_rim_rings() {
    std::unordered_map<FaceId, std::int32_t> taken;
    for (const auto& [f, r] : rim_faces_) taken[f] = r;
    std::vector<std::pair<FaceId, std::int32_t>> ring = rim_faces_;
    for (int step = 0; step < 3 && !ring.empty(); ++step) {
        std::vector<std::pair<FaceId, std::int32_t>> next;
        for (const auto& [f, r] : ring)
            for (const EdgeId e : topo_.face_edges()[f])
                for (const FaceId g : topo_.edge_faces()[e]) {
                    if (g == MeshTopology::kNone || taken.count(g)) continue;
                    const auto& gv = topo_.face_vertices()[g];
                    if (!label(gv[0]).is_away() || !label(gv[1]).is_away() || !label(gv[2]).is_away() || !front_face_[g])
                        continue;
                    if (face_hidden(g)) continue;
                    taken[g] = r;
                    next.emplace_back(g, r);
                    for (std::size_t k = 0; k < 3; ++k) steps_.emplace_back(r, ids_.vertex(gv[k]), ids_.vertex(gv[(k + 1) % 3]));
                }
        ring = std::move(next);
    }
}

void SnaxelMapBuilder::cancel_opposite_steps() {
    // Sorted in parallel halves, then merged.
    const auto middle = steps_.begin() + std::ptrdiff_t(steps_.size() / 2);
    parallel_for(2, [&](std::size_t half) {
        if (half == 0) std::sort(steps_.begin(), middle);
        else std::sort(middle, steps_.end());
    }, 1);
    std::inplace_merge(steps_.begin(), middle, steps_.end());
    std::vector<char> gone(steps_.size(), 0);
    for (std::size_t i = 0; i < steps_.size(); ++i) {
        if (gone[i]) continue;
        const Step back(steps_[i].region(), steps_[i].to, steps_[i].from());
        auto it = std::lower_bound(steps_.begin(), steps_.end(), back);
        while (it != steps_.end() && *it == back && gone[it - steps_.begin()]) ++it;
        if (it != steps_.end() && *it == back) gone[i] = gone[it - steps_.begin()] = 1;
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < steps_.size(); ++i)
        if (!gone[i]) steps_[kept++] = steps_[i];
    steps_.resize(kept);
}

void SnaxelMapBuilder::chain_outlines() {
    regions_.assign(comp_label_.size(), MapRegion{});
    std::vector<char> used(steps_.size(), 0);
    for (std::size_t i = 0; i < steps_.size(); ++i) {
        if (used[i]) continue;
        const std::int32_t r = steps_[i].region();
        const PointId first = steps_[i].from();
        std::vector<glm::dvec2> loop;
        std::size_t at = i;
        while (true) {
            used[at] = 1;
            loop.push_back(projection_.project(point_of(steps_[at].from())));
            const PointId to = steps_[at].to;
            if (to == first) break;
            auto it = std::lower_bound(steps_.begin(), steps_.end(), Step(r, to, PointId{-1}));
            while (it != steps_.end() && it->region() == r && it->from() == to && used[it - steps_.begin()]) ++it;
            if (it == steps_.end() || it->region() != r || it->from() != to) { // an outline that does not close
                ++map_.stats.open_outlines;
                break;
            }
            at = std::size_t(it - steps_.begin());
        }
        if (loop.size() >= 3) regions_[r].polygons.push_back(std::move(loop));
    }
}

void SnaxelMapBuilder::class_and_rank_regions() {
    std::vector<double> depth_sum(comp_label_.size(), 0.0);
    std::vector<std::size_t> depth_n(comp_label_.size(), 0);
    auto add_depth = [&](std::int32_t r, const glm::dvec3& p) {
        depth_sum[r] += camera_.orthographic() ? glm::dot(p, camera_.forward()) : glm::length(p - camera_.eye);
        ++depth_n[r];
    };
    for (const VertexId v : topo_.vertices())
        if (comp_[v] != kNoRegion) add_depth(comp_[v], position(v));
    for (const auto& [r, f] : vertexless_faces_) {
        const auto& fv = topo_.face_vertices()[f];
        add_depth(r, (position(fv[0]) + position(fv[1]) + position(fv[2])) / 3.0);
    }
    std::vector<std::size_t> order(regions_.size());
    for (std::size_t r = 0; r < regions_.size(); ++r) {
        const int cls = comp_label_[r].cls();
        MapRegion& region = regions_[r];
        region.cls = classes_.region_class(cls);
        region.k = classes_.level(cls);
        double signed_area = 0.0;
        for (const auto& poly : region.polygons)
            for (std::size_t j = 0; j < poly.size(); ++j) {
                const glm::dvec2& p = poly[j];
                const glm::dvec2& q = poly[(j + 1) % poly.size()];
                signed_area += p.x * q.y - q.x * p.y;
            }
        region.area = 0.5 * std::abs(signed_area);
        order[r] = r;
    }
    auto mean = [&](std::size_t r) { return depth_sum[r] / double(std::max<std::size_t>(depth_n[r], 1)); };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mean(a) < mean(b); });
    for (std::size_t i = 0; i < order.size(); ++i) regions_[order[i]].depth = std::int32_t(i);
    map_.regions = std::move(regions_);
}

} // namespace snaxels::detail
