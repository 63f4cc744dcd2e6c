#include "snaxels/planarmap/post_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "snaxels/planarmap/detail/clip.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {
namespace {

using clip::area;
using clip::from_paths;
using clip::Paths;
using clip::to_paths;

// The region of the visual contour every vertex lies in: the engine's own
// labels, or (for tracked contours, which carry none) the connected sets of
// equal sign of f.
std::vector<std::int32_t> patch_labels(const MeshTopology& topo, const ContourResult& visual) {
    if (visual.vertex_region.size() == topo.n_vertices()) return visual.vertex_region;
    std::vector<std::int32_t> label;
    grow_vertex_sets(topo, label, [](std::int32_t) { return true; }, [&](std::int32_t v, std::int32_t w) {
        return (visual.vertex_f[std::size_t(v)] >= 0.0) == (visual.vertex_f[std::size_t(w)] >= 0.0);
    });
    return label;
}

// The projected loops of each positive region of `result`, grouped by the
// visual patch the region lies in (its vertices face the viewer).
std::map<std::int32_t, Paths> regions_by_patch(const SnaxelEngine& engine, const ContourResult& result,
                                                const std::vector<std::int32_t>& patch_of, const ImageProjection& projection) {
    std::map<std::int32_t, std::vector<std::vector<glm::dvec2>>> loops;
    for (const FrontLoop& loop : result.fronts.loops) {
        const Snaxel& first = result.fronts.snaxels[loop.first];
        const std::int32_t patch = patch_of[std::size_t(first.inside)];
        std::vector<glm::dvec2> poly;
        result.fronts.for_each_in_loop(loop, [&](std::int32_t s) { poly.push_back(projection.project(engine.position(result.fronts.snaxels[s]))); });
        loops[patch].push_back(std::move(poly));
    }
    std::map<std::int32_t, Paths> out;
    for (auto& [patch, polys] : loops) out[patch] = clip::op(to_paths(polys), {}, ClipperLib::ctUnion);
    return out;
}

/// The outline of a set of polygons that all wind one way in the image,
/// walked step by step between point ids: a step walked back along one
/// already taken cancels it (an edge two pieces of the set share), so what
/// remains fills (non-zero) as the pieces do, at a fraction of the
/// clipping cost.
class Outline {
  public:
    void walk(std::int64_t from, std::int64_t to) {
        const auto back = steps_.find({to, from});
        if (back != steps_.end()) {
            if (--back->second == 0) steps_.erase(back);
        } else {
            ++steps_[{from, to}];
        }
    }
    /// Chained into closed loops (any pairing where several steps meet
    /// gives the same winding numbers), each point placed by @p at.
    template <class At> Paths paths(At&& at) const {
        std::multimap<std::int64_t, std::int64_t> next;
        for (const auto& [step, count] : steps_)
            for (int c = 0; c < count; ++c) next.emplace(step.first, step.second);
        std::vector<std::vector<glm::dvec2>> loops;
        while (!next.empty()) {
            auto it = next.begin();
            const std::int64_t start = it->first;
            std::vector<glm::dvec2> loop;
            std::int64_t v = start;
            while (it != next.end()) {
                loop.push_back(at(v));
                v = it->second;
                next.erase(it);
                if (v == start) break;
                it = next.find(v);
            }
            loops.push_back(std::move(loop));
        }
        return clip::op(to_paths(loops), {}, ClipperLib::ctUnion);
    }

  private:
    std::map<std::pair<std::int64_t, std::int64_t>, int> steps_;
};

} // namespace

const char* region_class_name(RegionClass cls) {
    switch (cls) {
    case RegionClass::Shadow: return "shadow";
    case RegionClass::Lit: return "lit";
    case RegionClass::Band: return "band";
    case RegionClass::Highlight: return "highlight";
    }
    return "lit";
}

std::vector<MapRegion> build_post_map(const SnaxelEngine& engine, const PostMapInput& in, const RayScene& rays,
                                      const ImageProjection& projection, const Camera& camera, const Light& light) {
    std::vector<MapRegion> regions;
    const ContourResult& visual = *in.visual;
    const MeshTopology& topo = engine.topology();
    auto facing = [&](const std::array<std::int32_t, 3>& f) {
        const glm::dvec3 &a = topo.positions[f[0]], &b = topo.positions[f[1]], &c = topo.positions[f[2]];
        return glm::dot(glm::cross(b - a, c - a), camera.to_viewer((a + b + c) / 3.0)) > 0.0;
    };
    // Classes: 0 shadow, 1 lit, 2.. bands, then the highlight levels.
    const int bands_n = int(in.isophotes.size());
    const int highlight = 2 + bands_n;
    const int classes = highlight + int(in.gleams.size());
    auto region_class = [&](int cls) { return cls == 0 ? RegionClass::Shadow : cls == 1 ? RegionClass::Lit : cls < highlight ? RegionClass::Band : RegionClass::Highlight; };
    auto class_k = [&](int cls) { return cls >= highlight ? in.gleams[std::size_t(cls - highlight)]->spec.k : cls >= 2 ? in.isophotes[std::size_t(cls - 2)]->spec.k : 0.0; };
    // The faces that show: turned to the viewer (by their winding) and not
    // hidden at their centre, or (open meshes) turned away and seen from
    // behind; these last are classed whole by their N.L (face_class).
    const VisibilitySampler sampler(rays, camera);
    enum : char { kHidden = 0, kShown = 1, kUnder = 2, kBackShown = 3, kFold = 4 }; // kUnder: inside a patch, hidden
    std::vector<char> shows(topo.n_faces(), kHidden);
    std::vector<int> face_class(topo.n_faces(), 1);
    bool open = false;
    for (std::size_t e = 0; e < topo.n_edges() && !open; ++e) open = topo.is_boundary_edge(std::int32_t(e));
    parallel_for(topo.n_faces(), [&](std::size_t i) {
        const auto& f = topo.face_vertices[i];
        const glm::dvec3 &a = topo.positions[f[0]], &b = topo.positions[f[1]], &c = topo.positions[f[2]];
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        if (!facing(f)) {
            // Turned away inside a patch (its corners face the viewer by
            // their normals): the patch folds over itself there.
            const bool in_patch = visual.vertex_f[std::size_t(f[0])] >= 0.0 && visual.vertex_f[std::size_t(f[1])] >= 0.0 &&
                                  visual.vertex_f[std::size_t(f[2])] >= 0.0;
            // Turned away, seen from behind through a hole of an open mesh:
            // classed by N.L alone, as the snaxel map does.
            if (!open || rays.occluded(sampler.face_ray(std::int32_t(i), (a + b + c) / 3.0, -n))) {
                if (in_patch) shows[i] = kFold;
                return;
            }
            shows[i] = kBackShown;
            double nl = 0.0;
            for (const auto v : f) nl += glm::dot(topo.normals[v], light.to_light(topo.positions[v]));
            nl /= 3.0;
            int cls = in.shadow && nl < 0.0 ? 0 : 1;
            for (int k = 0; k < bands_n; ++k)
                if (cls != 0 && nl >= in.isophotes[std::size_t(k)]->spec.k) cls = 2 + k;
            face_class[i] = cls;
            return;
        }
        const bool hidden = rays.occluded(sampler.face_ray(std::int32_t(i), (a + b + c) / 3.0, n));
        if (hidden) {
            const bool in_patch = visual.vertex_f[std::size_t(f[0])] >= 0.0 && visual.vertex_f[std::size_t(f[1])] >= 0.0 &&
                                  visual.vertex_f[std::size_t(f[2])] >= 0.0;
            shows[i] = in_patch ? kUnder : kHidden;
            return;
        }
        shows[i] = kShown; // classed by its parts (shown_class below)
    }, 1024);
    // The image of a set of faces (those seen from behind walked the way
    // they wind in the image), as its outline.
    auto outline_of = [&](auto&& take) {
        Outline outline;
        for (std::size_t i = 0; i < topo.n_faces(); ++i) {
            if (!take(i)) continue;
            auto f = topo.face_vertices[i];
            if (shows[i] == kBackShown) std::swap(f[1], f[2]);
            for (int k = 0; k < 3; ++k) outline.walk(f[std::size_t(k)], f[std::size_t((k + 1) % 3)]);
        }
        return outline.paths([&](std::int64_t v) { return projection.project(topo.positions[std::size_t(v)]); });
    };
    // Where a patch hides part of itself (or of another patch), the classes
    // of its projected regions may come from the hidden sheet: there the
    // shown faces' classes replace them.
    // So does the inside of an open mesh seen through a hole in a patch.
    // (A patch folded over itself, where faces turn away inside it, is
    // treated as hidden there too: its projected classes may come from
    // either side of the fold.)
    const Paths under = outline_of([&](std::size_t i) { return shows[i] == kUnder || shows[i] == kFold; });
    const Paths back = outline_of([&](std::size_t i) { return shows[i] == kBackShown; });
    // The shown faces' parts of each class: faces turned to the viewer are
    // cut along the lines where each kind's function (linear between the
    // face's corners) crosses zero, as a marching-triangles pass would;
    // faces seen from behind keep their own N.L class whole. Cut points on
    // a mesh edge are shared by its two faces, so the parts' outlines
    // cancel between neighbours as whole faces' do.
    // The functions are the kinds' own without the N.V clamp (faces past the
    // contour of interpolated normals can show): N.L for the shadow, N.L - k
    // for an isophote, V.R - k for a gleam; per vertex, in class order.
    std::vector<std::vector<double>> value; // [function][vertex]
    {
        std::vector<double> nl(topo.n_vertices()), rv(topo.n_vertices());
        for (std::size_t v = 0; v < topo.n_vertices(); ++v) {
            const glm::dvec3& n = topo.normals[v];
            const glm::dvec3 l = light.to_light(topo.positions[v]);
            nl[v] = glm::dot(n, l);
            rv[v] = glm::dot(camera.to_viewer(topo.positions[v]), 2.0 * nl[v] * n - l);
        }
        auto minus = [](const std::vector<double>& x, double k) {
            std::vector<double> out(x.size());
            for (std::size_t i = 0; i < x.size(); ++i) out[i] = x[i] - k;
            return out;
        };
        if (in.shadow) value.push_back(nl);
        for (const ContourResult* r : in.isophotes) value.push_back(minus(nl, r->spec.k));
        for (const ContourResult* r : in.gleams) value.push_back(minus(rv, r->spec.k));
    }
    const auto K = std::int64_t(value.size());
    const auto V = std::int64_t(topo.n_vertices()), E = std::int64_t(topo.n_edges());
    struct Corner {
        std::int64_t id;
        int along; // the face edge it leads along (-1: across the face)
        glm::dvec3 p;
        std::vector<double> f;
    };
    auto class_at = [&](const std::vector<double>& f) {
        std::size_t j = 0;
        int cls = 1;
        if (in.shadow) cls = f[j++] < 0.0 ? 0 : 1;
        for (int k = 0; k < bands_n; ++k, ++j)
            if (cls != 0 && f[j] >= 0.0) cls = 2 + k;
        for (std::size_t g = 0; g < in.gleams.size(); ++g, ++j)
            if (f[j] >= 0.0) cls = highlight + int(g);
        return cls;
    };
    // Per class, faces turned to the viewer [cls] and faces seen from behind
    // [classes + cls]: the latter only show where none of the former do
    // (past an open mesh's outline, a face seen from behind can pass the
    // ray test beside the nearer sheet).
    std::vector<Paths> shown_class(static_cast<std::size_t>(classes));
    Paths front; // every shown face turned to the viewer
    {
        std::unordered_map<std::int64_t, glm::dvec3> point;
        std::int64_t inner = V + E * K; // ids of cut points inside faces
        std::vector<Outline> steps(static_cast<std::size_t>(2 * classes));
        auto add_piece = [&](int cls, const std::vector<Corner>& piece) {
            for (std::size_t k = 0; k < piece.size(); ++k) {
                point.emplace(piece[k].id, piece[k].p);
                steps[std::size_t(cls)].walk(piece[k].id, piece[(k + 1) % piece.size()].id);
            }
        };
        for (std::size_t i = 0; i < topo.n_faces(); ++i) {
            if (shows[i] == kBackShown) {
                auto f = topo.face_vertices[i];
                std::swap(f[1], f[2]); // seen from behind: walked the way it winds in the image
                std::vector<Corner> piece;
                for (const auto v : f) piece.push_back({v, -1, topo.positions[std::size_t(v)], {}});
                add_piece(classes + face_class[i], piece);
                continue;
            }
            if (shows[i] != kShown) continue;
            const auto& fv = topo.face_vertices[i];
            const auto& fe = topo.face_edges[i];
            std::vector<Corner> poly;
            for (int k = 0; k < 3; ++k) {
                Corner c{fv[std::size_t(k)], k, topo.positions[std::size_t(fv[std::size_t(k)])], {}};
                for (const auto& fn : value) c.f.push_back(fn[std::size_t(fv[std::size_t(k)])]);
                poly.push_back(std::move(c));
            }
            std::vector<std::vector<Corner>> parts{std::move(poly)};
            for (std::int64_t j = 0; j < K; ++j) {
                std::vector<std::vector<Corner>> next;
                for (const auto& part : parts) {
                    std::vector<Corner> below, above;
                    const std::size_t n = part.size();
                    for (std::size_t k = 0; k < n; ++k) {
                        const Corner& a = part[k];
                        const Corner& b = part[(k + 1) % n];
                        (a.f[std::size_t(j)] < 0.0 ? below : above).push_back(a);
                        if ((a.f[std::size_t(j)] < 0.0) == (b.f[std::size_t(j)] < 0.0)) continue;
                        Corner q;
                        q.along = a.along;
                        if (a.along >= 0) {
                            // On a mesh edge: the edge's own root, the same for both faces.
                            const std::int32_t e = fe[std::size_t(a.along)];
                            const std::int32_t u = topo.edge_vertices[e][0], w = topo.edge_vertices[e][1];
                            const double fu = value[std::size_t(j)][std::size_t(u)], fw = value[std::size_t(j)][std::size_t(w)];
                            const double t = fu == fw ? 0.5 : std::clamp(fu / (fu - fw), 0.0, 1.0);
                            q.id = V + std::int64_t(e) * K + j;
                            q.p = glm::mix(topo.positions[std::size_t(u)], topo.positions[std::size_t(w)], t);
                            q.f.resize(std::size_t(K));
                            for (std::int64_t m = 0; m < K; ++m)
                                q.f[std::size_t(m)] = glm::mix(value[std::size_t(m)][std::size_t(u)], value[std::size_t(m)][std::size_t(w)], t);
                            q.f[std::size_t(j)] = 0.0;
                        } else {
                            const double fa = a.f[std::size_t(j)], fb = b.f[std::size_t(j)];
                            const double t = std::clamp(fa / (fa - fb), 0.0, 1.0);
                            q.id = inner++;
                            q.p = glm::mix(a.p, b.p, t);
                            q.f.resize(std::size_t(K));
                            for (std::int64_t m = 0; m < K; ++m) q.f[std::size_t(m)] = glm::mix(a.f[std::size_t(m)], b.f[std::size_t(m)], t);
                            q.f[std::size_t(j)] = 0.0;
                        }
                        below.push_back(q);
                        above.push_back(q);
                        // The cut runs across the face between the two new points.
                        below.back().along = (a.f[std::size_t(j)] < 0.0) ? -1 : a.along;
                        above.back().along = (a.f[std::size_t(j)] < 0.0) ? a.along : -1;
                    }
                    if (below.size() >= 3) next.push_back(std::move(below));
                    if (above.size() >= 3) next.push_back(std::move(above));
                }
                parts = std::move(next);
            }
            for (const auto& part : parts) {
                std::vector<double> mid(std::size_t(K), 0.0);
                for (const Corner& c : part)
                    for (std::int64_t m = 0; m < K; ++m) mid[std::size_t(m)] += c.f[std::size_t(m)] / double(part.size());
                add_piece(class_at(mid), part);
            }
        }
        std::vector<Paths> outlines(steps.size());
        for (std::size_t cls = 0; cls < steps.size(); ++cls)
            outlines[cls] = steps[cls].paths([&](std::int64_t id) { return projection.project(point.at(id)); });
        for (int cls = 0; cls < classes; ++cls) front.insert(front.end(), outlines[std::size_t(cls)].begin(), outlines[std::size_t(cls)].end());
        front = clip::op(front, {}, ClipperLib::ctUnion);
        for (int cls = 0; cls < classes; ++cls) {
            const Paths& behind = outlines[std::size_t(classes + cls)];
            shown_class[std::size_t(cls)] = behind.empty() ? outlines[std::size_t(cls)]
                                                           : clip::op(outlines[std::size_t(cls)], clip::op(behind, front, ClipperLib::ctDifference),
                                                                      ClipperLib::ctUnion);
        }
    }
    Paths replaced;
    if (!under.empty() || !back.empty()) {
        // A hole is where faces seen from behind show and no face turned to
        // the viewer does (at the contour, hidden sides graze it).
        const Paths shown_all = back.empty() ? front : clip::op(front, back, ClipperLib::ctUnion);
        replaced = clip::op(clip::op(under, shown_all, ClipperLib::ctIntersection),
                            clip::op(back, front, ClipperLib::ctDifference), ClipperLib::ctUnion);
    }
    const std::vector<std::int32_t> patch_of = patch_labels(engine.topology(), visual);
    const std::map<std::int32_t, Paths> patches = regions_by_patch(engine, visual, patch_of, projection);
    // Patches where a contour ends on the mesh's boundary (open meshes): an
    // open loop's polygon closes across the patch, not along the boundary,
    // so there the shown faces give the classes, and where the visual
    // contour itself is open, the patch's faces give its outline.
    std::map<std::int32_t, char> open_patch; // 1: a shading loop open, 2: the visual contour open
    auto mark_open = [&](const ContourResult& r, char how) {
        for (const FrontLoop& loop : r.fronts.loops)
            if (!loop.closed) {
                char& o = open_patch[patch_of[std::size_t(r.fronts.snaxels[loop.first].inside)]];
                o = std::max(o, how);
            }
    };
    mark_open(visual, 2);
    if (in.shadow) mark_open(*in.shadow, 1);
    for (const ContourResult* r : in.isophotes) mark_open(*r, 1);
    for (const ContourResult* r : in.gleams) mark_open(*r, 1);
    // Nearest first, by the mean depth of each patch's contour.
    std::vector<std::pair<double, std::int32_t>> order;
    for (const auto& [patch, paths] : patches) {
        double depth = 0.0;
        std::size_t n = 0;
        for (const FrontLoop& loop : visual.fronts.loops) {
            if (patch_of[std::size_t(visual.fronts.snaxels[loop.first].inside)] != patch) continue;
            visual.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                const glm::dvec3 p = engine.position(visual.fronts.snaxels[s]);
                depth += camera.orthographic() ? glm::dot(p, camera.forward()) : glm::length(p - camera.eye);
                ++n;
            });
        }
        order.push_back({n ? depth / double(n) : 0.0, patch});
    }
    std::sort(order.begin(), order.end());

    std::map<std::int32_t, Paths> lit;
    if (in.shadow) lit = regions_by_patch(engine, *in.shadow, patch_of, projection);
    std::vector<std::map<std::int32_t, Paths>> bands;
    for (const ContourResult* iso : in.isophotes) bands.push_back(regions_by_patch(engine, *iso, patch_of, projection));
    std::vector<std::map<std::int32_t, Paths>> highlights;
    for (const ContourResult* g : in.gleams) highlights.push_back(regions_by_patch(engine, *g, patch_of, projection));
    auto of = [](const std::map<std::int32_t, Paths>& m, std::int32_t patch) {
        const auto it = m.find(patch);
        return it == m.end() ? Paths{} : it->second;
    };

    Paths covered;
    int depth = 0;
    for (const auto& entry : order) {
        const std::int32_t patch = entry.second; // a variable, so the lambda below may capture it
        const auto found = open_patch.find(patch);
        const char how = found == open_patch.end() ? 0 : found->second;
        const Paths shape = how == 2 ? outline_of([&](std::size_t i) {
            const auto& f = topo.face_vertices[i];
            return facing(f) && patch_of[std::size_t(f[0])] == patch && patch_of[std::size_t(f[1])] == patch &&
                   patch_of[std::size_t(f[2])] == patch;
        }) : patches.at(patch);
        Paths visible = clip::op(shape, covered, ClipperLib::ctDifference);
        covered = clip::op(covered, shape, ClipperLib::ctUnion);
        if (visible.empty()) continue;
        // Nested class sets inside the visible part: lit ⊇ band 1 ⊇ band 2 ...
        // Each level is clipped to the one before: on the surface they nest,
        // but their projected polylines are separate discretizations.
        std::vector<Paths> levels;
        levels.push_back(in.shadow ? clip::op(visible, of(lit, patch), ClipperLib::ctIntersection) : visible);
        for (const auto& band : bands) levels.push_back(clip::op(levels.back(), of(band, patch), ClipperLib::ctIntersection));
        // Highlight levels nest too: each clipped to the one before.
        std::vector<Paths> glint_levels;
        for (const auto& h : highlights)
            glint_levels.push_back(clip::op(glint_levels.empty() ? visible : glint_levels.back(), of(h, patch), ClipperLib::ctIntersection));
        const Paths glints = glint_levels.empty() ? Paths{} : glint_levels.front();
        std::vector<Paths> parts(static_cast<std::size_t>(classes)); // per class
        auto emit = [&](int cls, const Paths& paths) {
            parts[std::size_t(cls)] = glints.empty() || cls >= highlight ? paths : clip::op(paths, glints, ClipperLib::ctDifference);
        };
        emit(0, clip::op(visible, levels[0], ClipperLib::ctDifference));
        for (std::size_t i = 0; i < levels.size(); ++i) {
            const Paths next = i + 1 < levels.size() ? levels[i + 1] : Paths{};
            emit(int(i) + 1, next.empty() ? levels[i] : clip::op(levels[i], next, ClipperLib::ctDifference));
        }
        for (std::size_t g = 0; g < glint_levels.size(); ++g)
            emit(highlight + int(g), g + 1 < glint_levels.size() && !glint_levels[g + 1].empty()
                                         ? clip::op(glint_levels[g], glint_levels[g + 1], ClipperLib::ctDifference)
                                         : glint_levels[g]);
        // Occlusion within the patch: where it covers hidden faces, the
        // shown faces decide the class.
        const Paths here = how ? visible : replaced.empty() ? Paths{} : clip::op(replaced, visible, ClipperLib::ctIntersection);
        for (int cls = 0; cls < classes; ++cls) {
            Paths part = std::move(parts[std::size_t(cls)]);
            if (!here.empty()) {
                part = clip::op(part, here, ClipperLib::ctDifference);
                const Paths seen = clip::op(shown_class[std::size_t(cls)], here, ClipperLib::ctIntersection);
                if (!seen.empty()) part = clip::op(part, seen, ClipperLib::ctUnion);
            }
            const double a = area(part);
            if (a > 0.0) regions.push_back({region_class(cls), class_k(cls), depth, from_paths(part), a});
        }
        ++depth;
    }

    // Shown faces that no patch covers (a part of an open mesh turned to the
    // viewer with no contour of its own, the strip between the contour of
    // interpolated normals and the mesh's own outline) fill with the classes
    // of their parts.
    for (int cls = classes - 1; cls >= 0; --cls) {
        const Paths& faces = shown_class[std::size_t(cls)];
        if (faces.empty()) continue;
        const Paths rest = clip::op(faces, covered, ClipperLib::ctDifference);
        covered = clip::op(covered, faces, ClipperLib::ctUnion);
        const double a = area(rest);
        if (a > 0.0) regions.push_back({region_class(cls), class_k(cls), depth, from_paths(rest), a});
    }
    // What is left of the silhouette band (faces hidden at their centre but
    // seen in part). The visual contour follows the interpolated
    // normals, the mesh's outline its faces: where they differ (creases,
    // coarse meshes) faces turned to the viewer reach past the contour, and
    // faces turned away inside a patch fold its outline over itself, so
    // the loop's polygon misses what lies under the fold. The band is every
    // face turned to the viewer that has a vertex with N.V < 0 (a face
    // whose vertices all face the viewer lies inside a patch) or lies
    // within two rings of the contour or of a fold; what of it no patch
    // covers joins the map, classed by the face's own N.L.
    std::vector<char> fold(topo.n_vertices(), 0);
    std::vector<std::int32_t> frontier;
    auto mark = [&](std::int32_t v) {
        if (!fold[v]) fold[v] = 1, frontier.push_back(v);
    };
    // Seeds: both ends of the contour's edges (past them the surface may
    // fold back under the patch) and the corners of faces turned away
    // inside a patch.
    for (const Snaxel& s : visual.fronts.snaxels) mark(s.inside), mark(s.outside);
    for (const auto& f : topo.face_vertices) {
        if (visual.vertex_f[f[0]] < 0.0 || visual.vertex_f[f[1]] < 0.0 || visual.vertex_f[f[2]] < 0.0) continue;
        if (facing(f)) continue;
        for (const auto v : f) mark(v);
    }
    for (int ring = 0; ring < 2; ++ring) {
        std::vector<std::int32_t> next;
        for (const std::int32_t v : frontier)
            for (std::int32_t i = topo.ring_start[v]; i < topo.ring_start[v + 1]; ++i)
                if (!fold[topo.ring[i]]) fold[topo.ring[i]] = 1, next.push_back(topo.ring[i]);
        frontier = std::move(next);
    }
    const int shading = 2 + bands_n; // the band's classes: shadow, lit, bands
    std::vector<int> nl_class(topo.n_faces(), -1);
    for (std::size_t i = 0; i < topo.n_faces(); ++i) {
        const auto& f = topo.face_vertices[i];
        const bool outside = visual.vertex_f[f[0]] < 0.0 || visual.vertex_f[f[1]] < 0.0 || visual.vertex_f[f[2]] < 0.0;
        if (!outside && !fold[f[0]] && !fold[f[1]] && !fold[f[2]]) continue;
        if (!facing(f)) continue; // turned away: hidden on closed meshes
        int cls = 1;
        if (in.shadow) {
            double nl = 0.0;
            for (const auto v : f) nl += glm::dot(topo.normals[v], light.to_light(topo.positions[v]));
            nl /= 3.0;
            cls = nl < 0.0 ? 0 : 1;
            for (std::size_t k = 0; k < in.isophotes.size(); ++k)
                if (nl >= in.isophotes[k]->spec.k) cls = 2 + int(k);
        }
        nl_class[i] = cls;
    }
    for (int cls = shading - 1; cls >= 0; --cls) { // brighter classes first
        const Paths united = outline_of([&](std::size_t i) { return nl_class[i] == cls; });
        if (united.empty()) continue;
        const Paths rest = clip::op(united, covered, ClipperLib::ctDifference);
        covered = clip::op(covered, united, ClipperLib::ctUnion);
        const double a = area(rest);
        if (a > 0.0) regions.push_back({region_class(cls), class_k(cls), depth, from_paths(rest), a});
    }
    return regions;
}

std::vector<std::vector<glm::dvec2>> erode(const std::vector<std::vector<glm::dvec2>>& polygons, double pixels) {
    if (pixels <= 0.0) return polygons;
    // Clipper's offset takes the winding of the lowest loop it is given as
    // that of outlines: a sliver hole lowest of all would turn erosion into
    // growth. So the region is filled (non-zero) into outlines with their
    // holes first, and each outline is shrunk with its own holes.
    ClipperLib::Clipper c;
    c.AddPaths(to_paths(polygons), ClipperLib::ptSubject, true);
    ClipperLib::PolyTree tree;
    c.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    Paths out;
    for (ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
        if (node->IsHole()) continue;
        // Round joins within a hundredth of a pixel (Clipper's default, a
        // quarter of a grid unit, is 1/4096 px: hundreds of points per
        // rounded corner that the drawing simplifies away again).
        ClipperLib::ClipperOffset offset(2.0, 0.01 * clip::kScale);
        offset.AddPath(node->Contour, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
        for (const ClipperLib::PolyNode* hole : node->Childs) offset.AddPath(hole->Contour, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
        Paths part;
        offset.Execute(part, -pixels * clip::kScale);
        out.insert(out.end(), part.begin(), part.end());
    }
    return from_paths(out);
}

} // namespace snaxels
