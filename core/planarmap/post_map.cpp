#include "snaxels/planarmap/post_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <unordered_map>

#include "snaxels/planarmap/detail/clip.h"
#include "snaxels/planarmap/detail/polygon_cut.h"
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
VertexData<std::int32_t> patch_labels(const MeshTopology& topo, const ContourResult& visual) {
    if (visual.vertex_region.size() == topo.n_vertices()) return visual.vertex_region;
    VertexData<std::int32_t> label;
    grow_vertex_sets(topo, label, [](VertexId) { return true; }, [&](VertexId v, VertexId w) {
        return (visual.vertex_f[v] >= 0.0) == (visual.vertex_f[w] >= 0.0);
    });
    return label;
}

// The projected loops of each positive region of `result`, grouped by the
// visual patch the region lies in (its vertices face the viewer).
// A loop the near plane @p near cuts keeps what lies past it, closed along the plane.
std::map<std::int32_t, Paths> regions_by_patch(const SnaxelEngine& engine, const ContourResult& result,
                                                const VertexData<std::int32_t>& patch_of, const ImageProjection& projection,
                                                const NearPlane& near) {
    std::map<std::int32_t, std::vector<std::vector<glm::dvec2>>> loops;
    std::vector<glm::dvec3> points;
    for (const FrontLoop& loop : result.fronts.loops) {
        const Snaxel& first = result.fronts.snaxels[loop.first];
        const std::int32_t patch = patch_of[first.inside];
        points.clear();
        result.fronts.for_each_in_loop(loop, [&](std::int32_t s) { points.push_back(engine.position(result.fronts.snaxels[s])); });
        std::vector<glm::dvec2> poly;
        for (const glm::dvec3& p : near.clip(points)) poly.push_back(projection.project(p));
        if (!poly.empty()) loops[patch].push_back(std::move(poly));
    }
    std::map<std::int32_t, Paths> out;
    for (auto& [patch, polys] : loops) out[patch] = clip::op(to_paths(polys), {}, ClipperLib::ctUnion);
    return out;
}

} // namespace

namespace {

/// The post-processed map's construction as named stages: which faces show,
/// the shown faces cut into classes, the patches clipped nearest first, the
/// shown faces no patch covers, and the silhouette band.
class PostMapBuilder {
  public:
    PostMapBuilder(const SnaxelEngine& engine, const PostMapInput& in, const RayScene& rays,
                   const ImageProjection& projection, const Camera& camera, const Light& light)
        : engine_(engine), in_(in), rays_(rays), projection_(projection), camera_(camera), light_(light),
          visual_(*in.visual), topo_(engine.topology()), classes_(shading_classes(in)), bands_n_(classes_.bands()),
          highlight_(classes_.first_highlight()), count_(classes_.count()), near_(camera, topo_) {}

    std::vector<MapRegion> build() {
        classify_faces();
        cut_shown_faces();
        find_replaced();
        order_patches();
        clip_patches();
        fill_uncovered_shown();
        fill_silhouette_band();
        fill_partly_hidden();
        return std::move(regions_);
    }

  private:
    void add_region(int cls, const Paths& paths, int depth) {
        const double a = area(paths);
        if (a > 0.0) regions_.push_back({classes_.region_class(cls), classes_.level(cls), depth, from_paths(paths), a});
    }
    /// What of @p paths nothing covers yet joins the map as class @p cls
    /// (the last stages: shown faces, the silhouette band, partly hidden
    /// faces), and is covered from then on.
    void add_uncovered(int cls, const Paths& paths) {
        if (paths.empty()) return;
        const Paths rest = clip::op(paths, covered_, ClipperLib::ctDifference);
        covered_ = clip::op(covered_, paths, ClipperLib::ctUnion);
        add_region(cls, rest, depth_);
    }
    bool facing(const std::array<VertexId, 3>& f) const {
        const glm::dvec3 &a = topo_.positions()[f[0]], &b = topo_.positions()[f[1]], &c = topo_.positions()[f[2]];
        return glm::dot(glm::cross(b - a, c - a), camera_.to_viewer((a + b + c) / 3.0)) > 0.0;
    }
    bool corners_face_viewer(const std::array<VertexId, 3>& f) const {
        return visual_.vertex_f[f[0]] >= 0.0 && visual_.vertex_f[f[1]] >= 0.0 && visual_.vertex_f[f[2]] >= 0.0;
    }
    /// The mean N.L of a face's corners.
    double face_nl(const std::array<VertexId, 3>& f) const {
        double nl = 0.0;
        for (const auto v : f) nl += glm::dot(topo_.normals()[v], light_.to_light(topo_.positions()[v]));
        return nl / 3.0;
    }

    // Outlines are walked between point ids: a vertex's id is its index, a
    // cut point on an edge follows the vertices (one per edge and function),
    // and cut points inside faces follow those.
    static std::int64_t point_of(VertexId v) { return v.index(); }
    static VertexId vertex_at(std::int64_t point) { return VertexId(std::int32_t(point)); }
    std::int64_t edge_point_of(EdgeId e, std::size_t function) const {
        return std::int64_t(topo_.n_vertices()) + std::int64_t(e.index()) * std::int64_t(value_.size()) + std::int64_t(function);
    }

    // ---- which faces show -------------------------------------------------

    enum : char { kHidden = 0, kShown = 1, kUnder = 2, kBackShown = 3, kFold = 4 }; // kUnder: inside a patch, hidden

    /// The faces that show: turned to the viewer (by their winding) and not
    /// hidden at their centre, or (open meshes) turned away and seen from
    /// behind; these last are classed whole by their N.L (face_class_).
    void classify_faces() {
        const VisibilitySampler sampler(rays_, camera_);
        shows_.assign(topo_.n_faces(), kHidden);
        face_class_.assign(topo_.n_faces(), 1);
        const auto edges = topo_.edges();
        const bool open = std::any_of(edges.begin(), edges.end(), [&](EdgeId e) { return topo_.is_boundary_edge(e); });
        parallel_for(topo_.faces(), [&](FaceId i) {
            const auto& f = topo_.face_vertices()[i];
            const glm::dvec3 &a = topo_.positions()[f[0]], &b = topo_.positions()[f[1]], &c = topo_.positions()[f[2]];
            if (topo_.has_strips() && !face_has_area(topo_, i)) return; // a sharp edge's strip covers nothing: hidden
            const auto middle = middle_past_near(i);
            if (!middle) return; // all of it nearer than the near plane: cut
            const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
            if (!facing(f)) {
                // Turned away inside a patch (its corners face the viewer by
                // their normals): the patch folds over itself there.
                // Turned away, seen from behind through a hole of an open mesh:
                // classed by N.L alone, as the snaxel map does.
                if (!open || rays_.occluded(sampler.face_ray(i, *middle, -n))) {
                    if (corners_face_viewer(f)) shows_[i] = kFold;
                    return;
                }
                shows_[i] = kBackShown;
                face_class_[i] = classes_.from_nl(face_nl(f));
                return;
            }
            if (rays_.occluded(sampler.face_ray(i, *middle, n))) {
                shows_[i] = corners_face_viewer(f) ? kUnder : kHidden;
                return;
            }
            shows_[i] = kShown; // classed by its parts (shown_class_ below)
        }, 1024);
    }

    /// The image of a set of faces (those seen from behind walked the way
    /// they wind in the image), as its outline.
    template <class Take> Paths outline_of(Take&& take) const {
        clip::Outline outline;
        std::unordered_map<std::int64_t, glm::dvec3> crossing; // where the near plane cuts a face's side
        std::vector<NearPlane::FacePoint> cut;
        for (const FaceId i : topo_.faces()) {
            if (!take(i)) continue;
            near_.cut_face(topo_, i, cut); // ids: a vertex's index, or past them where a side meets the plane
            if (shows_[i] == kBackShown) std::reverse(cut.begin(), cut.end());
            for (std::size_t k = 0; k < cut.size(); ++k) {
                if (cut[k].id >= std::int64_t(topo_.n_vertices())) crossing[cut[k].id] = cut[k].p;
                outline.walk(cut[k].id, cut[(k + 1) % cut.size()].id);
            }
        }
        return outline.paths([&](std::int64_t point) {
            return projection_.project(point < std::int64_t(topo_.n_vertices()) ? topo_.positions()[vertex_at(point)]
                                                                                : crossing.at(point));
        });
    }

    /// The middle of what of face @p i lies past the near plane; none when it is all cut.
    std::optional<glm::dvec3> middle_past_near(FaceId i) const {
        const auto& f = topo_.face_vertices()[i];
        const glm::dvec3 &a = topo_.positions()[f[0]], &b = topo_.positions()[f[1]], &c = topo_.positions()[f[2]];
        if (!near_.cuts(a) && !near_.cuts(b) && !near_.cuts(c)) return (a + b + c) / 3.0;
        std::vector<NearPlane::FacePoint> cut;
        near_.cut_face(topo_, i, cut);
        if (cut.empty()) return std::nullopt;
        glm::dvec3 sum(0.0);
        for (const NearPlane::FacePoint& q : cut) sum += q.p;
        return sum / double(cut.size());
    }

    // ---- the shown faces cut into classes -----------------------------------

    struct Corner {
        std::int64_t id;
        int along; // the face edge it leads along (-1: across the face)
        glm::dvec3 p;
        std::vector<double> f;
    };

    /// The kinds' functions per vertex, in class order, without the N.V
    /// clamp (faces past the contour of interpolated normals can show): N.L
    /// for the shadow, N.L - k for an isophote, V.R - k for a gleam.
    void shading_values() {
        VertexData<double> nl(topo_.n_vertices()), rv(topo_.n_vertices());
        for (const VertexId v : topo_.vertices()) {
            const glm::dvec3& n = topo_.normals()[v];
            const glm::dvec3 l = light_.to_light(topo_.positions()[v]);
            nl[v] = glm::dot(n, l);
            rv[v] = glm::dot(camera_.to_viewer(topo_.positions()[v]), 2.0 * nl[v] * n - l);
        }
        auto minus = [](VertexData<double> x, double k) {
            for (double& value : x) value -= k;
            return x;
        };
        if (in_.shadow) value_.push_back(nl);
        for (const ContourResult* r : in_.isophotes) value_.push_back(minus(nl, r->spec.k));
        for (const ContourResult* r : in_.gleams) value_.push_back(minus(rv, r->spec.k));
    }

    /// The class of a point from its functions' values (in value_'s order).
    int class_at(const std::vector<double>& f) const {
        const std::size_t band0 = in_.shadow ? 1 : 0, highlight0 = band0 + std::size_t(bands_n_);
        return classes_.classify(in_.shadow && f[0] < 0.0, [&](int b) { return f[band0 + std::size_t(b)] >= 0.0; },
                                 [&](int h) { return f[highlight0 + std::size_t(h)] >= 0.0; });
    }

    /// The shown faces' parts of each class: faces turned to the viewer are
    /// cut along the lines where each kind's function (linear between the
    /// face's corners) crosses zero, as a marching-triangles pass would;
    /// faces seen from behind keep their own N.L class whole. Cut points on
    /// a mesh edge are shared by its two faces, so the parts' outlines
    /// cancel between neighbours as whole faces' do. Per class, faces turned
    /// to the viewer [cls] and faces seen from behind [classes + cls]: the
    /// latter only show where none of the former do (past an open mesh's
    /// outline, a face seen from behind can pass the ray test beside the
    /// nearer sheet).
    void cut_shown_faces() {
        shading_values();
        const std::vector<Paths> outlines = class_parts([&](FaceId i) { return shows_[i] == kShown || shows_[i] == kBackShown; });
        for (int cls = 0; cls < count_; ++cls)
            front_.insert(front_.end(), outlines[cls].begin(), outlines[cls].end());
        front_ = clip::op(front_, {}, ClipperLib::ctUnion);
        shown_class_.assign(outlines.begin(), outlines.begin() + count_);
        for (int cls = 0; cls < count_; ++cls)
            if (const Paths& behind = outlines[count_ + cls]; !behind.empty())
                shown_class_[cls] = clip::op(shown_class_[cls], clip::op(behind, front_, ClipperLib::ctDifference),
                                             ClipperLib::ctUnion);
    }

    /// The parts of each class of the faces @p take accepts, as outlines:
    /// [cls] of faces turned to the viewer, cut where the functions cross
    /// zero, [classes + cls] of faces seen from behind (kBackShown), whole.
    template <class Take> std::vector<Paths> class_parts(Take&& take) const {
        std::unordered_map<std::int64_t, glm::dvec3> point;
        const auto K = std::int64_t(value_.size());
        std::int64_t inner = edge_point_of(EdgeId(topo_.n_edges()), 0); // ids of cut points inside faces
        std::vector<clip::Outline> steps(static_cast<std::size_t>(2 * count_));
        auto add_piece = [&](int cls, const std::vector<Corner>& piece) {
            for (std::size_t k = 0; k < piece.size(); ++k) {
                point.emplace(piece[k].id, piece[k].p);
                steps[cls].walk(piece[k].id, piece[(k + 1) % piece.size()].id);
            }
        };
        for (const FaceId i : topo_.faces()) {
            if (!take(i)) continue;
            if (shows_[i] == kBackShown) {
                const auto& f = topo_.face_vertices()[i];
                std::vector<Corner> piece;
                for (int k = 0; k < 3; ++k) piece.push_back({point_of(f[k]), k, topo_.positions()[f[k]], {}});
                cut_at_near(i, piece);
                std::reverse(piece.begin(), piece.end()); // seen from behind: walked the way it winds in the image
                if (!piece.empty()) add_piece(count_ + face_class_[i], piece);
                continue;
            }
            for (const auto& part : cut_face(i, inner)) {
                std::vector<double> mid(std::size_t(K), 0.0);
                for (const Corner& c : part)
                    for (std::int64_t m = 0; m < K; ++m) mid[m] += c.f[m] / double(part.size());
                add_piece(class_at(mid), part);
            }
        }
        std::vector<Paths> outlines(steps.size());
        for (std::size_t cls = 0; cls < steps.size(); ++cls)
            outlines[cls] = steps[cls].paths([&](std::int64_t id) { return projection_.project(point.at(id)); });
        return outlines;
    }

    /// Face @p i cut where each function crosses zero; @p inner numbers the
    /// cut points inside faces.
    std::vector<std::vector<Corner>> cut_face(FaceId i, std::int64_t& inner) const {
        const auto& fv = topo_.face_vertices()[i];
        std::vector<Corner> poly;
        for (int k = 0; k < 3; ++k) {
            const VertexId v = fv[k];
            Corner c{point_of(v), k, topo_.positions()[v], {}};
            for (const auto& fn : value_) c.f.push_back(fn[v]);
            poly.push_back(std::move(c));
        }
        cut_at_near(i, poly);
        if (poly.empty()) return {};
        std::vector<std::size_t> functions(value_.size());
        for (std::size_t j = 0; j < functions.size(); ++j) functions[j] = j;
        return detail::cut_polygon(std::move(poly), functions,
                                   [&](const std::vector<Corner>& part, std::size_t j) { return split_part(part, i, j, inner); });
    }

    /// Face @p i's corners @p poly cut to what lies past the near plane: a
    /// side that crosses it ends there, on a point both faces beside the
    /// edge share (a negative id, by the edge), and the cut runs across the
    /// face along the plane. Nothing where all of it is cut.
    void cut_at_near(FaceId i, std::vector<Corner>& poly) const {
        if (std::none_of(poly.begin(), poly.end(), [&](const Corner& c) { return near_.cuts(c.p); })) return;
        const auto& fe = topo_.face_edges()[i];
        std::vector<Corner> out;
        for (std::size_t k = 0; k < 3; ++k) {
            const Corner &a = poly[k], &b = poly[(k + 1) % 3];
            const bool in_a = !near_.cuts(a.p), in_b = !near_.cuts(b.p);
            if (in_a) out.push_back(a);
            if (in_a == in_b) continue;
            // From the edge's own first vertex, so that both faces agree.
            const auto [u, w] = topo_.edge_vertices()[fe[k]];
            const double t = near_.crossing(topo_.positions()[u], topo_.positions()[w]);
            Corner q{-1 - std::int64_t(fe[k].index()), in_a ? -1 : int(k), glm::mix(topo_.positions()[u], topo_.positions()[w], t), {}};
            for (const auto& fn : value_) q.f.push_back(glm::mix(fn[u], fn[w], t));
            out.push_back(std::move(q));
        }
        poly = out.size() >= 3 ? std::move(out) : std::vector<Corner>{};
    }

    /// A part of face @p i split where function @p j crosses zero.
    std::pair<std::vector<Corner>, std::vector<Corner>> split_part(const std::vector<Corner>& part, FaceId i,
                                                                   std::size_t j, std::int64_t& inner) const {
        const auto& fe = topo_.face_edges()[i];
        const std::size_t K = value_.size();
        auto crossing = [&](const Corner& a, const Corner& b, std::size_t) {
            Corner q;
            q.along = a.along;
            q.f.resize(K);
            if (a.along >= 0) {
                // On a mesh edge: the edge's own root, the same for both faces.
                const EdgeId e = fe[a.along];
                const auto [u, w] = topo_.edge_vertices()[e];
                const double fu = value_[j][u], fw = value_[j][w];
                const double t = fu == fw ? 0.5 : std::clamp(fu / (fu - fw), 0.0, 1.0);
                q.id = edge_point_of(e, j);
                q.p = glm::mix(topo_.positions()[u], topo_.positions()[w], t);
                for (std::size_t m = 0; m < K; ++m) q.f[m] = glm::mix(value_[m][u], value_[m][w], t);
            } else {
                const double fa = a.f[j], fb = b.f[j];
                const double t = std::clamp(fa / (fa - fb), 0.0, 1.0);
                q.id = inner++;
                q.p = glm::mix(a.p, b.p, t);
                for (std::size_t m = 0; m < K; ++m) q.f[m] = glm::mix(a.f[m], b.f[m], t);
            }
            q.f[j] = 0.0;
            return q;
        };
        // The cut runs across the face between the two new points.
        auto sides = [](Corner& lower, Corner& upper, bool a_below) { (a_below ? lower : upper).along = -1; };
        return detail::split_polygon(part, [&](const Corner& c) { return c.f[j] < 0.0; }, crossing, sides);
    }

    // ---- patches, nearest first ---------------------------------------------

    /// Where a patch hides part of itself (or of another patch), the classes
    /// of its projected regions may come from the hidden sheet: there the
    /// shown faces' classes replace them. So does the inside of an open
    /// mesh seen through a hole in a patch. (A patch folded over itself,
    /// where faces turn away inside it, is treated as hidden there too: its
    /// projected classes may come from either side of the fold.)
    void find_replaced() {
        const Paths under = outline_of([&](FaceId i) { return shows_[i] == kUnder || shows_[i] == kFold; });
        const Paths back = outline_of([&](FaceId i) { return shows_[i] == kBackShown; });
        if (under.empty() && back.empty()) return;
        // A hole is where faces seen from behind show and no face turned to
        // the viewer does (at the contour, hidden sides graze it).
        const Paths shown_all = back.empty() ? front_ : clip::op(front_, back, ClipperLib::ctUnion);
        replaced_ = clip::op(clip::op(under, shown_all, ClipperLib::ctIntersection),
                             clip::op(back, front_, ClipperLib::ctDifference), ClipperLib::ctUnion);
    }

    /// The patches, where a contour ends on the mesh's boundary, and their
    /// order by the mean depth of each patch's contour.
    void order_patches() {
        patch_of_ = patch_labels(topo_, visual_);
        patches_ = regions_by_patch(engine_, visual_, patch_of_, projection_, near_);
        // Patches where a contour ends on the mesh's boundary (open meshes):
        // an open loop's polygon closes across the patch, not along the
        // boundary, so there the shown faces give the classes, and where the
        // visual contour itself is open, the patch's faces give its outline.
        auto mark_open = [&](const ContourResult& r, char how) {
            for (const FrontLoop& loop : r.fronts.loops)
                if (!loop.closed) {
                    char& o = open_patch_[patch_of_[r.fronts.snaxels[loop.first].inside]];
                    o = std::max(o, how);
                }
        };
        mark_open(visual_, 2);
        if (in_.shadow) mark_open(*in_.shadow, 1);
        for (const ContourResult* r : in_.isophotes) mark_open(*r, 1);
        for (const ContourResult* r : in_.gleams) mark_open(*r, 1);
        for (const auto& [patch, paths] : patches_) {
            double depth = 0.0;
            std::size_t n = 0;
            for (const FrontLoop& loop : visual_.fronts.loops) {
                if (patch_of_[visual_.fronts.snaxels[loop.first].inside] != patch) continue;
                visual_.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                    const glm::dvec3 p = engine_.position(visual_.fronts.snaxels[s]);
                    depth += camera_.orthographic() ? glm::dot(p, camera_.forward()) : glm::length(p - camera_.eye);
                    ++n;
                });
            }
            order_.push_back({n ? depth / double(n) : 0.0, patch});
        }
        std::sort(order_.begin(), order_.end());
    }

    static Paths of(const std::map<std::int32_t, Paths>& m, std::int32_t patch) {
        const auto it = m.find(patch);
        return it == m.end() ? Paths{} : it->second;
    }

    /// Each patch, nearest first, keeps what no nearer patch covers, split
    /// into its classes.
    void clip_patches() {
        std::map<std::int32_t, Paths> lit;
        if (in_.shadow) lit = regions_by_patch(engine_, *in_.shadow, patch_of_, projection_, near_);
        std::vector<std::map<std::int32_t, Paths>> bands;
        for (const ContourResult* iso : in_.isophotes) bands.push_back(regions_by_patch(engine_, *iso, patch_of_, projection_, near_));
        std::vector<std::map<std::int32_t, Paths>> highlights;
        for (const ContourResult* g : in_.gleams) highlights.push_back(regions_by_patch(engine_, *g, patch_of_, projection_, near_));
        for (const auto& entry : order_) {
            const std::int32_t patch = entry.second; // a variable, so the lambda below may capture it
            const auto found = open_patch_.find(patch);
            const char how = found == open_patch_.end() ? 0 : found->second;
            const Paths shape = how == 2 ? outline_of([&](FaceId i) {
                const auto& f = topo_.face_vertices()[i];
                return facing(f) && patch_of_[f[0]] == patch && patch_of_[f[1]] == patch && patch_of_[f[2]] == patch;
            }) : patches_.at(patch);
            const Paths visible = clip::op(shape, covered_, ClipperLib::ctDifference);
            covered_ = clip::op(covered_, shape, ClipperLib::ctUnion);
            if (visible.empty()) continue;
            std::vector<Paths> levels;
            levels.push_back(in_.shadow ? clip::op(visible, of(lit, patch), ClipperLib::ctIntersection) : visible);
            for (const auto& band : bands) levels.push_back(clip::op(levels.back(), of(band, patch), ClipperLib::ctIntersection));
            std::vector<Paths> glint_levels;
            for (const auto& h : highlights)
                glint_levels.push_back(clip::op(glint_levels.empty() ? visible : glint_levels.back(), of(h, patch), ClipperLib::ctIntersection));
            split_patch(visible, levels, glint_levels, how);
            ++depth_;
        }
    }

    /// The visible part of a patch split into classes: nested class sets
    /// lit ⊇ band 1 ⊇ band 2 ... (@p levels), and nested highlight levels
    /// (@p glint_levels), each level clipped to the one before (on the
    /// surface they nest, but their projected polylines are separate
    /// discretizations).
    void split_patch(const Paths& visible, const std::vector<Paths>& levels, const std::vector<Paths>& glint_levels, char how) {
        const Paths glints = glint_levels.empty() ? Paths{} : glint_levels.front();
        std::vector<Paths> parts(static_cast<std::size_t>(count_)); // per class
        auto emit = [&](int cls, const Paths& paths) {
            parts[cls] = glints.empty() || cls >= highlight_ ? paths : clip::op(paths, glints, ClipperLib::ctDifference);
        };
        emit(0, clip::op(visible, levels[0], ClipperLib::ctDifference));
        for (std::size_t i = 0; i < levels.size(); ++i) {
            const Paths next = i + 1 < levels.size() ? levels[i + 1] : Paths{};
            emit(int(i) + 1, next.empty() ? levels[i] : clip::op(levels[i], next, ClipperLib::ctDifference));
        }
        for (std::size_t g = 0; g < glint_levels.size(); ++g)
            emit(highlight_ + int(g), g + 1 < glint_levels.size() && !glint_levels[g + 1].empty()
                                          ? clip::op(glint_levels[g], glint_levels[g + 1], ClipperLib::ctDifference)
                                          : glint_levels[g]);
        // Occlusion within the patch: where it covers hidden faces, the
        // shown faces decide the class.
        const Paths here = how ? visible : replaced_.empty() ? Paths{} : clip::op(replaced_, visible, ClipperLib::ctIntersection);
        for (int cls = 0; cls < count_; ++cls) {
            Paths part = std::move(parts[cls]);
            if (!here.empty()) {
                part = clip::op(part, here, ClipperLib::ctDifference);
                const Paths seen = clip::op(shown_class_[cls], here, ClipperLib::ctIntersection);
                if (!seen.empty()) part = clip::op(part, seen, ClipperLib::ctUnion);
            }
            add_region(cls, part, depth_);
        }
    }

    /// Shown faces that no patch covers (a part of an open mesh turned to
    /// the viewer with no contour of its own, the strip between the contour
    /// of interpolated normals and the mesh's own outline) fill with the
    /// classes of their parts.
    void fill_uncovered_shown() {
        for (int cls = count_ - 1; cls >= 0; --cls) add_uncovered(cls, shown_class_[cls]);
    }

    // ---- the silhouette band ------------------------------------------------

    /// What is left of the silhouette band (faces hidden at their centre but
    /// seen in part). The visual contour follows the interpolated normals,
    /// the mesh's outline its faces: where they differ (creases, coarse
    /// meshes) faces turned to the viewer reach past the contour, and faces
    /// turned away inside a patch fold its outline over itself, so the
    /// loop's polygon misses what lies under the fold. The band is every
    /// face turned to the viewer that has a vertex with N.V < 0 (a face
    /// whose vertices all face the viewer lies inside a patch) or lies
    /// within two rings of the contour or of a fold; what of it no patch
    /// covers joins the map, classed by the face's own N.L.
    void fill_silhouette_band() {
        const VertexData<char> fold = near_folds();
        const int shading = 2 + bands_n_; // the band's classes: shadow, lit, bands
        FaceData<int> nl_class(topo_.n_faces(), -1);
        for (const FaceId i : topo_.faces()) {
            const auto& f = topo_.face_vertices()[i];
            if (corners_face_viewer(f) && !fold[f[0]] && !fold[f[1]] && !fold[f[2]]) continue;
            if (!facing(f)) continue; // turned away: hidden on closed meshes
            int cls = 1;
            if (in_.shadow) {
                const double nl = face_nl(f);
                cls = nl < 0.0 ? 0 : 1;
                for (std::size_t k = 0; k < in_.isophotes.size(); ++k)
                    if (nl >= in_.isophotes[k]->spec.k) cls = 2 + int(k);
            }
            nl_class[i] = cls;
        }
        for (int cls = shading - 1; cls >= 0; --cls) // brighter classes first
            add_uncovered(cls, outline_of([&](FaceId i) { return nl_class[i] == cls; }));
    }

    /// Faces turned to the viewer but hidden at their centre, beside a shown
    /// face, can still show in part: a large face (a floor of a few faces)
    /// whose middle an object in front of it hides. What of them nothing
    /// else covers joins the map, cut into classes as the shown faces are.
    void fill_partly_hidden() {
        VertexData<char> by_shown(topo_.n_vertices(), 0);
        for (const FaceId i : topo_.faces())
            if (shows_[i] == kShown)
                for (const VertexId v : topo_.face_vertices()[i]) by_shown[v] = 1;
        auto take = [&](FaceId i) {
            if (shows_[i] != kHidden && shows_[i] != kUnder) return false;
            const auto& f = topo_.face_vertices()[i];
            if (!(by_shown[f[0]] || by_shown[f[1]] || by_shown[f[2]]) || !facing(f)) return false;
            return !topo_.has_strips() || face_has_area(topo_, i);
        };
        const std::vector<Paths> parts = class_parts(take);
        for (int cls = count_ - 1; cls >= 0; --cls) add_uncovered(cls, parts[cls]);
    }

    /// Per vertex: within two rings of the contour or of a fold. Seeds: both
    /// ends of the contour's edges (past them the surface may fold back
    /// under the patch) and the corners of faces turned away inside a patch.
    VertexData<char> near_folds() const {
        VertexData<char> fold(topo_.n_vertices(), 0);
        std::vector<VertexId> frontier;
        auto mark = [&](VertexId v) {
            if (!fold[v]) fold[v] = 1, frontier.push_back(v);
        };
        for (const Snaxel& s : visual_.fronts.snaxels) mark(s.inside), mark(s.outside);
        for (const auto& f : topo_.face_vertices()) {
            if (!corners_face_viewer(f) || facing(f)) continue;
            for (const auto v : f) mark(v);
        }
        for (int ring = 0; ring < 2; ++ring) {
            std::vector<VertexId> next;
            for (const VertexId v : frontier)
                for (const VertexId w : topo_.neighbours(v))
                    if (!fold[w]) fold[w] = 1, next.push_back(w);
            frontier = std::move(next);
        }
        return fold;
    }

    const SnaxelEngine& engine_;
    const PostMapInput& in_;
    const RayScene& rays_;
    const ImageProjection& projection_;
    const Camera& camera_;
    const Light& light_;
    const ContourResult& visual_;
    const MeshTopology& topo_;
    const ShadingClasses classes_;
    const int bands_n_, highlight_, count_; ///< of classes_
    const NearPlane near_; ///< what lies nearer the eye is cut: faces and loops keep what lies past it

    FaceData<char> shows_;     ///< kHidden ... kFold
    FaceData<int> face_class_; ///< of a face seen from behind: its N.L class
    std::vector<VertexData<double>> value_; ///< [function][vertex]
    std::vector<Paths> shown_class_;         ///< per class: the shown faces' parts of it
    Paths front_;                            ///< every shown face turned to the viewer
    Paths replaced_;                         ///< where the shown faces' classes replace the patches'
    VertexData<std::int32_t> patch_of_;
    std::map<std::int32_t, Paths> patches_;
    std::map<std::int32_t, char> open_patch_; ///< 1: a shading loop open, 2: the visual contour open
    std::vector<std::pair<double, std::int32_t>> order_; ///< (mean depth, patch), nearest first
    Paths covered_;                                      ///< the image the regions so far cover
    int depth_ = 0;                                      ///< the next region's depth
    std::vector<MapRegion> regions_;
};

} // namespace

std::vector<MapRegion> build_post_map(const SnaxelEngine& engine, const PostMapInput& in, const RayScene& rays,
                                      const ImageProjection& projection, const Camera& camera, const Light& light) {
    return PostMapBuilder(engine, in, rays, projection, camera, light).build();
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
