// Objects and materials in the drawing, checked against the test's own
// reading of the scene files (tests/support/scene_reader.h: its own glTF 1.0
// and Collada readers, which name each face's node and material), its own
// projection and its own brute-force ray casting; nothing of the oracle
// comes from core/.
//
// - A line set that selects one object draws no stroke outside that
//   object's screen area, and the object's lines that another object hides
//   are hidden; an object kept as an occluder only draws no line and still
//   hides.
// - Material lines lie on the mesh's material boundaries (every drawn point
//   within 0.5 px of a boundary edge's projection) and every boundary edge
//   the rays see is drawn.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <pugixml.hpp>

#include "snaxels/animation/still.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/sharp_edges.h"
#include "snaxels/style/style.h"
#include "tests/support/reference_raster.h"
#include "tests/support/segment_distance.h"
#include "tests/support/scene_reader.h"

namespace snaxels {
namespace {

std::string asset(const std::string& name) { return std::string(SNAXELS_TEST_ASSETS) + "/" + name; }

constexpr int kSize = 600;
constexpr double kMargin = 32.0;

// ---- The oracle: the test's own reading, projection and rays ----

struct OracleScene {
    ref::SceneMesh mesh;
    glm::dvec3 centre{0.0};
    double radius = 1.0;
};

OracleScene read_scene(const std::string& file) {
    OracleScene s;
    s.mesh = file.find(".dae") != std::string::npos ? ref::read_collada(file) : ref::read_gltf1(file);
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : s.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    s.centre = 0.5 * (lo + hi);
    s.radius = 0.5 * glm::length(hi - lo);
    return s;
}

/// An orthographic view along @p dir (up +Y), fitting the bounding sphere
/// within the margin, as the style's canvas says.
struct OracleView {
    glm::dvec3 fwd, right, up, centre;
    double scale;

    OracleView(const glm::dvec3& dir, const OracleScene& s) : fwd(glm::normalize(dir)), centre(s.centre) {
        glm::dvec3 world_up(0, 1, 0);
        if (std::abs(glm::dot(fwd, world_up)) > 0.999) world_up = glm::dvec3(0, 0, 1);
        right = glm::normalize(glm::cross(fwd, world_up));
        up = glm::cross(right, fwd);
        scale = (0.5 * kSize - kMargin) / s.radius;
    }
    glm::dvec2 project(const glm::dvec3& p) const {
        const glm::dvec3 d = p - centre;
        return {0.5 * kSize + scale * glm::dot(d, right), 0.5 * kSize - scale * glm::dot(d, up)};
    }
};

/// Möller-Trumbore: the ray's parameter at the triangle, or none.
std::optional<double> hit(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return std::nullopt;
    const glm::dvec3 t = o - a;
    const double u = glm::dot(t, p) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(t, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    return glm::dot(e2, q) / det;
}

/// Whether a face passing @p take lies between @p p and the viewer
/// (orthographic, toward -fwd), ignoring hits within @p near of p.
template <class Take>
bool occluded(const OracleScene& s, const OracleView& v, const glm::dvec3& p, double near, Take&& take) {
    const glm::dvec3 d = -v.fwd;
    for (std::size_t f = 0; f < s.mesh.faces.size(); ++f) {
        if (!take(f)) continue;
        const auto& t = s.mesh.faces[f];
        const auto at = hit(p, d, s.mesh.positions[std::size_t(t[0])], s.mesh.positions[std::size_t(t[1])],
                            s.mesh.positions[std::size_t(t[2])]);
        if (at && *at > near) return true;
    }
    return false;
}

/// Pixels covered by the faces passing @p take (no depth test), grown by
/// @p grow pixels.
template <class Take> std::vector<std::uint8_t> coverage(const OracleScene& s, const OracleView& v, int grow, Take&& take) {
    std::vector<std::uint8_t> mask(std::size_t(kSize) * kSize, 0);
    for (std::size_t f = 0; f < s.mesh.faces.size(); ++f) {
        if (!take(f)) continue;
        const auto& t = s.mesh.faces[f];
        const glm::dvec2 a = v.project(s.mesh.positions[std::size_t(t[0])]), b = v.project(s.mesh.positions[std::size_t(t[1])]),
                         c = v.project(s.mesh.positions[std::size_t(t[2])]);
        ref::for_each_pixel_in(a, b, c, kSize, kSize, [&](int x, int y, double, double, double) {
            mask[std::size_t(y) * kSize + std::size_t(x)] = 1;
        });
        // Thin faces cover few pixel centres: their corners count too.
        for (const glm::dvec2& q : {a, b, c})
            if (q.x >= 0 && q.y >= 0 && q.x < kSize && q.y < kSize) mask[std::size_t(q.y) * kSize + std::size_t(q.x)] = 1;
    }
    std::vector<std::uint8_t> grown = mask;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!mask[std::size_t(y) * kSize + std::size_t(x)]) continue;
            for (int dy = -grow; dy <= grow; ++dy)
                for (int dx = -grow; dx <= grow; ++dx) {
                    const int X = x + dx, Y = y + dy;
                    if (X >= 0 && Y >= 0 && X < kSize && Y < kSize) grown[std::size_t(Y) * kSize + std::size_t(X)] = 1;
                }
        }
    return grown;
}

using snaxels::test::segment_distance;

/// Points every half pixel along a polyline.
std::vector<glm::dvec2> dense(const std::vector<glm::dvec2>& q, bool closed) {
    std::vector<glm::dvec2> out;
    const std::size_t n = q.size();
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i) {
        const glm::dvec2 a = q[i], b = q[(i + 1) % n];
        const int steps = std::max(1, int(std::ceil(2.0 * glm::length(b - a))));
        for (int k = 0; k < steps; ++k) out.push_back(a + (b - a) * (double(k) / steps));
    }
    if (!q.empty()) out.push_back(closed ? q.front() : q.back());
    return out;
}

// ---- The product ----

/// Calls @p fn(p, qi) for every snaxel the drawing draws (visible or hidden).
template <class Fn> void for_each_drawn_snaxel(const StillOutput& out, Fn&& fn) {
    for (const DrawnContour& contour : out.drawing.contours)
        for (const DrawnLoop& loop : contour.loops)
            for (std::size_t k = 0; k < loop.p.size(); ++k)
                if (loop.qi[k] != kNotDrawn) fn(loop.p[k], loop.qi[k]);
}

StillOutput product_still(const std::string& file, const std::string& style_xml, const glm::dvec3& dir) {
    const LoadedMesh loaded = import_mesh(file);
    std::vector<StyleDiagnostic> warnings;
    Style style = parse_style(style_xml, "test style", &warnings);
    style.width = style.height = kSize;
    style.margin = kMargin;
    Camera camera;
    camera.view_dir = glm::normalize(dir);
    StillJob job = make_still_job(style, camera, std::nullopt);
    job.scene.visibility = true;
    std::optional<LoadedMesh> split;
    const LoadedMesh& surface = scene_surface(loaded, job.scene.style, split);
    const MeshTopology topology = engine_topology(surface, job.scene.refine);
    return render_still(surface, topology, nullptr, job);
}

std::vector<glm::dvec3> view_dirs() {
    std::vector<glm::dvec3> dirs = {glm::normalize(glm::dvec3(-0.5, -0.3, -0.8)), glm::normalize(glm::dvec3(0.7, -0.4, -0.6))};
    std::mt19937 rng(36);
    std::normal_distribution<double> normal;
    while (dirs.size() < 5) {
        const glm::dvec3 d(normal(rng), normal(rng), normal(rng));
        if (std::abs(glm::normalize(d).y) < 0.9) dirs.push_back(glm::normalize(d));
    }
    return dirs;
}

struct Case {
    std::string file;
    std::string pattern;  ///< the object the line set selects, as the style names it
    std::string object;   ///< that object as the oracle names it (glTF 1.0: the node's name, not its id)
    std::string occluder; ///< a pattern of an object kept as an occluder only
};

// Done-when 2: one object's lines, inside its screen area, hidden where
// other objects hide them; an occluder-only part draws nothing, still hides.
TEST(Parts, OneObjectsLinesStayOnItAndOthersHideThem) {
    const std::vector<Case> cases = {{"parts/parts.dae", "Ball", "Ball", "Post"},
                                     {"parts/parts.dae", "Cr*", "Crate", "Ball"},
                                     {"hard/CesiumMilkTruck.gltf", "*mesh001Node", "Wheels", "Geometry-mesh002Node"}};
    for (const Case& c : cases) {
        const std::string file = asset(c.file);
        const OracleScene scene = read_scene(file);
        const std::string style = "<style><contour kind=\"visual\" object=\"" + c.pattern + "\"/>"
                                  "<contour kind=\"crease\" object=\"" + c.pattern + "\"/>"
                                  "<object name=\"" + c.occluder + "\" draw=\"false\"/></style>";
        std::size_t points = 0, outside = 0, judged = 0, wrong = 0, occluded_by_others = 0;
        for (const glm::dvec3& dir : view_dirs()) {
            const OracleView view(dir, scene);
            const StillOutput out = product_still(file, style, dir);
            const auto mask = coverage(scene, view, 2, [&](std::size_t f) { return scene.mesh.face_object[f] == c.object; });
            for (const DrawnContour& contour : out.drawing.contours)
                for (const DrawnLoop& loop : contour.loops) {
                    for (const DrawnRun& run : loop.runs) {
                        if (run.qi == kNotDrawn) continue;
                        for (const glm::dvec2& q : dense(run.q, run.closed)) {
                            ++points;
                            const int x = int(q.x), y = int(q.y);
                            if (x < 0 || y < 0 || x >= kSize || y >= kSize || !mask[std::size_t(y) * kSize + std::size_t(x)])
                                ++outside;
                        }
                    }
                    // QI at each drawn snaxel against rays through the other
                    // objects (occluder-only ones included): where the rays
                    // clearly meet one (the point and points 3 px to either
                    // side agree: the product's rays start a fifth of an
                    // edge off the surface), the snaxel must be hidden.
                    for (std::size_t k = 0; k < loop.p.size(); ++k) {
                        if (loop.qi[k] == kNotDrawn) continue;
                        auto others = [&](std::size_t f) { return scene.mesh.face_object[f] != c.object; };
                        const double near = 1e-6 * scene.radius, px = 1.0 / view.scale;
                        const bool at = occluded(scene, view, loop.p[k], near, others);
                        bool clear = true;
                        for (const glm::dvec3& step : {view.right, -view.right, view.up, -view.up})
                            clear = clear && occluded(scene, view, loop.p[k] + 3.0 * px * step, near, others) == at;
                        if (!clear) continue;
                        ++judged;
                        occluded_by_others += at;
                        if (at && loop.qi[k] == 0) ++wrong;
                    }
                }
        }
        std::printf("%s, %s: %zu stroke points, %zu outside its area; %zu snaxels judged, %zu behind other objects, "
                    "%zu of those drawn visible\n",
                    c.file.c_str(), c.object.c_str(), points, outside, judged, occluded_by_others, wrong);
        EXPECT_GT(points, 500u) << c.file;
        EXPECT_EQ(outside, 0u) << c.file << " " << c.object;
        EXPECT_GT(judged, 100u) << c.file;
        EXPECT_GT(occluded_by_others, 0u) << c.file << ": no view where another object hides " << c.object;
        EXPECT_EQ(wrong, 0u) << c.file << " " << c.object;
    }
}

/// What a style does with the post of parts.dae: drawn snaxels, those on
/// the post, those clearly behind the post alone (it in front of them and
/// nothing else, at the point and 3 px to each side), and how many of
/// those are drawn visible.
struct PostJudgement {
    std::size_t drawn = 0, on_post = 0, behind_post_only = 0, drawn_visible = 0;
};

PostJudgement judge_post(const std::string& style) {
    const std::string file = asset("parts/parts.dae");
    const OracleScene scene = read_scene(file);
    PostJudgement j;
    for (const glm::dvec3& dir : view_dirs()) {
        const OracleView view(dir, scene);
        const StillOutput out = product_still(file, style, dir);
        auto post = [&](std::size_t f) { return scene.mesh.face_object[f] == "Post"; };
        // The others that could hide a line (the ball and the crate are
        // convex: their outlines hide nothing of themselves).
        auto others = [&](std::size_t f) { return scene.mesh.face_object[f] == "Crate" || scene.mesh.face_object[f] == "Ground"; };
        const double near = 1e-6 * scene.radius, px = 1.0 / view.scale;
        for_each_drawn_snaxel(out, [&](const glm::dvec3& p, int qi) {
            ++j.drawn;
            // The post is a cylinder of radius 0.25 about the vertical line x 0.5, z 1.4 (Y up), 2.4 tall.
            if (std::hypot(p.x - 0.5, p.z - 1.4) < 0.26 && p.y > -0.01 && p.y < 2.41) ++j.on_post;
            bool only_post = true;
            for (const glm::dvec3& step : {glm::dvec3(0.0), view.right, -view.right, view.up, -view.up}) {
                const glm::dvec3 q = p + 3.0 * px * step;
                only_post = only_post && occluded(scene, view, q, near, post) && !occluded(scene, view, q, near, others);
            }
            if (!only_post) return;
            ++j.behind_post_only;
            j.drawn_visible += qi == 0;
        });
    }
    std::printf("%s: %zu drawn snaxels, %zu on the post, %zu behind the post alone, %zu of those drawn visible\n",
                style.c_str(), j.drawn, j.on_post, j.behind_post_only, j.drawn_visible);
    return j;
}

// Done-when 2, the occluder: a part kept as an occluder only draws none of
// its lines, and what it hides stays hidden.
TEST(Parts, AnOccluderOnlyPartDrawsNothingAndStillHides) {
    const PostJudgement j =
        judge_post("<style><contour kind=\"visual\"/><contour kind=\"crease\"/><object name=\"Post\" draw=\"false\"/></style>");
    EXPECT_GT(j.drawn, 1000u);
    EXPECT_EQ(j.on_post, 0u);
    EXPECT_GT(j.behind_post_only, 20u);
    EXPECT_EQ(j.drawn_visible, 0u);
}

// A hidden part is left out of the scene: none of its lines is drawn and
// what only it would hide is drawn visible.
TEST(Parts, AHiddenPartIsLeftOutOfTheScene) {
    const PostJudgement j = judge_post("<style><contour kind=\"visual\"/><object name=\"Post\" hide=\"true\"/></style>");
    EXPECT_GT(j.drawn, 500u);
    EXPECT_EQ(j.on_post, 0u);
    EXPECT_GT(j.behind_post_only, 20u);
    EXPECT_EQ(j.drawn_visible, j.behind_post_only);
}

// The SVG groups strokes by object: inside each kind's group, an Inkscape
// layer per object holding that object's lines (every point of its paths
// within the object's screen area), and nothing else.
TEST(Parts, TheSvgGroupsStrokesByObject) {
    const std::string file = asset("parts/parts.dae");
    const OracleScene scene = read_scene(file);
    const glm::dvec3 dir = view_dirs().front();
    const OracleView view(dir, scene);
    const StillOutput out = product_still(file, "<style><contour kind=\"visual\"/><contour kind=\"crease\"/></style>", dir);
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(out.svg.c_str()));
    std::map<std::string, std::size_t> points_of;
    std::size_t groups = 0, outside = 0;
    for (const pugi::xpath_node g : doc.select_nodes("//g[@class='object']")) {
        ++groups;
        const std::string object = g.node().attribute("data-object").value();
        EXPECT_EQ(std::string(g.node().attribute("inkscape:label").value()), object);
        EXPECT_EQ(std::string(g.node().parent().attribute("class").value()), "contour") << "an object's layer lies in a kind's";
        const auto mask = coverage(scene, view, 2, [&](std::size_t f) { return scene.mesh.face_object[f] == object; });
        for (const pugi::xml_node path : g.node().children("path")) {
            std::string d = path.attribute("d").value();
            for (char& ch : d)
                if (ch == 'M' || ch == 'L' || ch == 'Z' || ch == ',') ch = ' ';
            std::istringstream in(d);
            for (double x, y; in >> x >> y;) {
                ++points_of[object];
                const int px = int(x), py = int(y);
                outside += px < 0 || py < 0 || px >= kSize || py >= kSize || !mask[std::size_t(py) * kSize + std::size_t(px)];
            }
        }
    }
    EXPECT_GE(groups, 6u); // visible and hidden, each with the ball, the crate and the post (the ground has no lines here)
    for (const char* object : {"Ball", "Crate", "Post"}) EXPECT_GT(points_of[object], 20u) << object;
    EXPECT_EQ(outside, 0u);
    // Every stroke is in an object's layer: none lies in a kind's group outside one.
    EXPECT_TRUE(doc.select_nodes("//g[@class='contour']/path").empty());
}

// Done-when 3: material lines lie on the material boundaries, and every
// boundary edge the rays see is drawn.
TEST(Parts, MaterialLinesLieOnTheMaterialBoundaries) {
    for (const std::string name : {"parts/parts.dae", "hard/CesiumMilkTruck.gltf"}) {
        const std::string file = asset(name);
        const OracleScene scene = read_scene(file);
        // The boundary edges: edges of two faces of two materials (positions welded).
        std::map<std::pair<int, int>, std::vector<std::size_t>> edge_faces;
        for (std::size_t f = 0; f < scene.mesh.faces.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const int a = scene.mesh.faces[f][std::size_t(k)], b = scene.mesh.faces[f][std::size_t((k + 1) % 3)];
                edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
            }
        std::vector<std::pair<int, int>> boundary;
        for (const auto& [edge, faces] : edge_faces) {
            bool differ = false;
            for (const std::size_t f : faces) differ = differ || scene.mesh.face_material[f] != scene.mesh.face_material[faces[0]];
            if (differ) boundary.push_back(edge);
        }
        ASSERT_GT(boundary.size(), 20u) << name;
        std::size_t points = 0, off = 0, seen = 0, missed = 0;
        double worst = 0.0;
        for (const glm::dvec3& dir : view_dirs()) {
            const OracleView view(dir, scene);
            const StillOutput out = product_still(file, "<style><contour kind=\"material\"/></style>", dir);
            std::vector<std::pair<glm::dvec2, glm::dvec2>> projected, drawn;
            for (const auto& [a, b] : boundary)
                projected.push_back({view.project(scene.mesh.positions[std::size_t(a)]), view.project(scene.mesh.positions[std::size_t(b)])});
            for (const DrawnContour& contour : out.drawing.contours)
                for (const DrawnLoop& loop : contour.loops)
                    for (const DrawnRun& run : loop.runs) {
                        if (run.qi != 0) continue;
                        for (std::size_t i = 0; i + 1 < run.q.size(); ++i) drawn.push_back({run.q[i], run.q[i + 1]});
                        for (const glm::dvec2& q : dense(run.q, run.closed)) {
                            double d = std::numeric_limits<double>::infinity();
                            for (const auto& [a, b] : projected) d = std::min(d, segment_distance(q, a, b));
                            ++points;
                            worst = std::max(worst, d);
                            off += d > 0.5;
                        }
                    }
            // Every boundary edge point the rays clearly see (it and points
            // 2 px along the edge either way) is within a pixel of a drawn
            // visible stroke.
            const double near = 1e-6 * scene.radius;
            auto all = [](std::size_t) { return true; };
            for (const auto& [ia, ib] : boundary) {
                const glm::dvec3 a = scene.mesh.positions[std::size_t(ia)], b = scene.mesh.positions[std::size_t(ib)];
                const double length_px = glm::length(view.project(b) - view.project(a));
                const int samples = int(length_px / 3.0);
                for (int s = 1; s < samples; ++s) {
                    const double t = double(s) / samples, dt = std::min(0.5, 2.0 / std::max(length_px, 1e-9));
                    if (t - dt <= 0.0 || t + dt >= 1.0) continue;
                    auto point = [&](double u) { return a + u * (b - a); };
                    const bool visible = !occluded(scene, view, point(t), near, all);
                    if (!visible || occluded(scene, view, point(t - dt), near, all) || occluded(scene, view, point(t + dt), near, all))
                        continue;
                    ++seen;
                    const glm::dvec2 q = view.project(point(t));
                    double d = std::numeric_limits<double>::infinity();
                    for (const auto& [p0, p1] : drawn) d = std::min(d, segment_distance(q, p0, p1));
                    missed += d > 1.0;
                }
            }
        }
        std::printf("%s: %zu drawn points, %zu farther than 0.5 px from a boundary edge (worst %.3g px); %zu boundary "
                    "points seen, %zu not drawn\n",
                    name.c_str(), points, off, worst, seen, missed);
        EXPECT_GT(points, 200u) << name;
        EXPECT_EQ(off, 0u) << name;
        EXPECT_GT(seen, 50u) << name;
        EXPECT_LE(double(missed), 0.01 * double(seen)) << name;
    }
}

/// The oracle's own z-buffer of which object each pixel shows (-1: none).
std::vector<int> object_image(const OracleScene& s, const OracleView& v) {
    std::map<std::string, int> ids;
    std::vector<int> object(std::size_t(kSize) * kSize, -1);
    std::vector<double> depth(object.size(), std::numeric_limits<double>::infinity());
    for (std::size_t f = 0; f < s.mesh.faces.size(); ++f) {
        const int id = ids.emplace(s.mesh.face_object[f], int(ids.size())).first->second;
        const auto& t = s.mesh.faces[f];
        const glm::dvec3 &a = s.mesh.positions[std::size_t(t[0])], &b = s.mesh.positions[std::size_t(t[1])],
                         &c = s.mesh.positions[std::size_t(t[2])];
        const double da = glm::dot(a, v.fwd), db = glm::dot(b, v.fwd), dc = glm::dot(c, v.fwd);
        ref::for_each_pixel_in(v.project(a), v.project(b), v.project(c), kSize, kSize,
                               [&](int x, int y, double wa, double wb, double wc) {
                                   const std::size_t at = std::size_t(y) * kSize + std::size_t(x);
                                   const double d = wa * da + wb * db + wc * dc;
                                   if (d < depth[at]) depth[at] = d, object[at] = id;
                               });
    }
    return object;
}

// The outline of each object against the others (over="objects"): every
// visible stroke point lies where two objects meet in the oracle's image
// (pixels of two objects within 3 px), so nothing is drawn against the
// background or an object's own body; and where two objects meet in the
// image (a pixel of one beside a pixel of another) and the visual contour
// passes (within 2.5 px), the selected stretches pass too, visible: an
// object resting on a floor is outlined along it (the floor passes through
// the outline there and does not hide it).
TEST(Parts, ObjectOutlinesLieWhereObjectsMeetInTheImage) {
    for (const std::string name : {"parts/parts.dae", "hard/CesiumMilkTruck.gltf"}) {
        const std::string file = asset(name);
        const OracleScene scene = read_scene(file);
        std::size_t points = 0, alone = 0, meeting = 0, missed = 0, views = 0;
        for (const glm::dvec3& dir : view_dirs()) {
            // From above, as a scene is seen (from under the parts scene's
            // floor its edge, a border, is the outline over the objects:
            // kind="border" draws it).
            if (dir.y >= 0.0) continue;
            ++views;
            const OracleView view(dir, scene);
            const std::vector<int> object = object_image(scene, view);
            const StillOutput out =
                product_still(file, "<style><contour kind=\"visual\" over=\"objects\"><hidden draw=\"false\"/></contour></style>", dir);
            // Where the whole visual contour passes (the line the selector
            // takes its stretches from).
            const StillOutput whole = product_still(file, "<style><contour kind=\"visual\"/></style>", dir);
            std::vector<std::uint8_t> near_stroke(object.size(), 0), near_contour(object.size(), 0);
            auto mark = [&](std::vector<std::uint8_t>& mask, const glm::dvec2& q) {
                const int x = int(std::floor(q.x)), y = int(std::floor(q.y));
                for (int dy = -3; dy <= 3; ++dy)
                    for (int dx = -3; dx <= 3; ++dx)
                        if (x + dx >= 0 && y + dy >= 0 && x + dx < kSize && y + dy < kSize &&
                            glm::length(glm::dvec2(x + dx + 0.5, y + dy + 0.5) - q) <= 2.5)
                            mask[std::size_t(y + dy) * kSize + std::size_t(x + dx)] = 1;
            };
            for (const DrawnContour& contour : whole.drawing.contours)
                for (const DrawnLoop& loop : contour.loops)
                    for (const DrawnRun& run : loop.runs)
                        if (run.qi != kNotDrawn)
                            for (const glm::dvec2& q : dense(run.q, run.closed)) mark(near_contour, q);
            auto at = [&](int x, int y) { return x >= 0 && y >= 0 && x < kSize && y < kSize ? object[std::size_t(y) * kSize + std::size_t(x)] : -1; };
            for (const DrawnContour& contour : out.drawing.contours)
                for (const DrawnLoop& loop : contour.loops)
                    for (const DrawnRun& run : loop.runs) {
                        if (run.qi != 0) continue;
                        for (const glm::dvec2& q : dense(run.q, run.closed)) {
                            const int x = int(std::floor(q.x)), y = int(std::floor(q.y));
                            ++points;
                            std::set<int> seen;
                            for (int dy = -3; dy <= 3; ++dy)
                                for (int dx = -3; dx <= 3; ++dx)
                                    if (const int o = at(x + dx, y + dy); o >= 0) seen.insert(o);
                            alone += seen.size() < 2;
                            mark(near_stroke, q);
                        }
                    }
            std::vector<unsigned char> debug(object.size() * 3, 0);
            for (std::size_t i = 0; i < object.size(); ++i)
                if (object[i] >= 0) debug[3 * i] = debug[3 * i + 1] = debug[3 * i + 2] = (unsigned char)(60 + 40 * object[i]);
            for (int y = 1; y + 1 < kSize; ++y)
                for (int x = 1; x + 1 < kSize; ++x) {
                    const int o = at(x, y);
                    if (o < 0) continue;
                    bool meets = false;
                    for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}})
                        meets = meets || (at(x + dx, y + dy) >= 0 && at(x + dx, y + dy) != o);
                    if (!meets || !near_contour[std::size_t(y) * kSize + std::size_t(x)]) continue;
                    ++meeting;
                    const bool miss = !near_stroke[std::size_t(y) * kSize + std::size_t(x)];
                    missed += miss;
                    unsigned char* px = &debug[3 * (std::size_t(y) * kSize + std::size_t(x))];
                    px[0] = miss ? 255 : 0, px[1] = miss ? 0 : 255, px[2] = 0;
                }
            if (const char* dir_out = getenv("SNAXELS_DEBUG_PARTS_DIR")) {
                static int n = 0;
                FILE* f = std::fopen((std::string(dir_out) + "/over-" + std::to_string(n++) + ".ppm").c_str(), "wb");
                std::fprintf(f, "P6 %d %d 255\n", kSize, kSize);
                std::fwrite(debug.data(), 1, debug.size(), f);
                std::fclose(f);
            }
        }
        std::printf("%s, %zu views: %zu visible stroke points, %zu without two objects within 3 px; %zu pixels where two "
                    "objects meet by the visual contour, %zu without a stroke of the line set within 2.5 px\n",
                    name.c_str(), views, points, alone, meeting, missed);
        EXPECT_GE(views, 3u) << name;
        EXPECT_GT(points, 500u) << name;
        EXPECT_LE(double(alone), 0.01 * double(points)) << name;
        EXPECT_GT(meeting, 500u) << name;
        EXPECT_LE(double(missed), 0.03 * double(meeting)) << name;
    }
}

} // namespace
} // namespace snaxels
