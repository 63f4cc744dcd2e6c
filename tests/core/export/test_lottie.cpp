// The Lottie export read back with a JSON parser and a small Lottie
// evaluator of this file's own (no exporter code): the structure players
// need (every keyframe of a shape with the first's vertex count and closed
// flag, layers in and out in a chain), the paths' lives, the geometry at
// frame times, and the style's strokes and fills.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "snaxels/export/animated_svg.h"
#include "snaxels/export/lottie.h"
#include "tests/support/drawn_frames.h"

using namespace snaxels;
using nlohmann::json;

namespace {

using test::circle_loop;
using test::frame_with;
using test::ids;

/// A shape layer's path: its name without the segment number.
std::string path_of(const json& layer) {
    const std::string name = layer.at("nm");
    const auto dot = name.rfind('.');
    return dot == std::string::npos ? name : name.substr(0, dot);
}

/// One subpath as evaluated at a time: its vertices (tangents ignored: the
/// tests' strokes are polylines) and closed flag.
struct Evaluated {
    std::vector<glm::dvec2> v;
    bool closed = false;
};

std::vector<glm::dvec2> vertices(const json& bezier) {
    std::vector<glm::dvec2> out;
    for (const json& p : bezier.at("v")) out.emplace_back(p.at(0).get<double>(), p.at(1).get<double>());
    return out;
}

/// The value of a shape (`sh`) at frame @p t: static, or linear between
/// the keyframes around t (held before the first and after the last).
Evaluated evaluate(const json& sh, double t) {
    const json& ks = sh.at("ks");
    if (ks.at("a") == 0) return {vertices(ks.at("k")), ks.at("k").at("c").get<bool>()};
    const json& kf = ks.at("k");
    std::size_t i = 0;
    while (i + 1 < kf.size() && kf[i + 1].at("t").get<double>() <= t) ++i;
    const json& a = kf[i].at("s").at(0);
    Evaluated e{vertices(a), a.at("c").get<bool>()};
    if (i + 1 < kf.size() && t > kf[i].at("t").get<double>()) {
        const double t0 = kf[i].at("t"), t1 = kf[i + 1].at("t");
        const std::vector<glm::dvec2> b = vertices(kf[i + 1].at("s").at(0));
        const double u = (t - t0) / (t1 - t0);
        for (std::size_t k = 0; k < e.v.size(); ++k) e.v[k] = (1.0 - u) * e.v[k] + u * b[k];
    }
    return e;
}

/// Every subpath shown at frame @p t by the layers whose stroke or fill
/// colour is @p colour (r, g, b in 0..1).
std::vector<Evaluated> shown_at(const json& doc, double t, const std::function<bool(const json&)>& style_matches) {
    std::vector<Evaluated> out;
    for (const json& layer : doc.at("layers")) {
        if (layer.at("ty") != 4) continue;
        if (!(layer.at("ip").get<double>() <= t && t < layer.at("op").get<double>())) continue;
        const json& shapes = layer.at("shapes");
        if (!style_matches(shapes.back())) continue;
        for (const json& s : shapes)
            if (s.at("ty") == "sh") out.push_back(evaluate(s, t));
    }
    return out;
}

double point_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    const double t = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

/// Checks what every player relies on and returns the document.
json read_checked(const std::string& text, int frames, int width, int height) {
    const json doc = json::parse(text);
    EXPECT_EQ(doc.at("op").get<double>(), double(frames));
    EXPECT_EQ(doc.at("ip").get<double>(), 0.0);
    EXPECT_EQ(doc.at("w").get<int>(), width);
    EXPECT_EQ(doc.at("h").get<int>(), height);
    std::set<int> inds;
    for (const json& layer : doc.at("layers")) {
        EXPECT_TRUE(inds.insert(layer.at("ind").get<int>()).second);
        EXPECT_LT(layer.at("ip").get<double>(), layer.at("op").get<double>());
        EXPECT_EQ(layer.at("st").get<double>(), 0.0);
        if (layer.at("ty") != 4) continue;
        for (const json& s : layer.at("shapes")) {
            if (s.at("ty") != "sh" || s.at("ks").at("a") == 0) continue;
            const json& kf = s.at("ks").at("k");
            const json& first = kf.at(0).at("s").at(0);
            double t = -1e9;
            for (std::size_t k = 0; k < kf.size(); ++k) {
                const json& b = kf[k].at("s").at(0);
                EXPECT_EQ(b.at("v").size(), first.at("v").size()) << layer.at("nm");
                EXPECT_EQ(b.at("i").size(), first.at("v").size());
                EXPECT_EQ(b.at("o").size(), first.at("v").size());
                EXPECT_EQ(b.at("c"), first.at("c"));
                EXPECT_GT(kf[k].at("t").get<double>(), t);
                t = kf[k].at("t");
                if (k + 1 < kf.size()) { // linear easing to the next keyframe
                    EXPECT_EQ(kf[k].at("o").at("x").get<double>(), 0.0);
                    EXPECT_EQ(kf[k].at("i").at("x").get<double>(), 1.0);
                }
            }
        }
    }
    return doc;
}

/// The life [first ip, last op) of each path, checking that its layers
/// follow each other without a gap or an overlap.
std::multiset<std::pair<double, double>> lives(const json& doc, const std::string& prefix) {
    std::map<std::string, std::vector<std::pair<double, double>>> chains;
    for (const json& layer : doc.at("layers"))
        if (layer.at("ty") == 4 && layer.at("nm").get<std::string>().rfind(prefix, 0) == 0)
            chains[path_of(layer)].push_back({layer.at("ip"), layer.at("op")});
    std::multiset<std::pair<double, double>> out;
    for (auto& [name, chain] : chains) {
        std::sort(chain.begin(), chain.end());
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) EXPECT_EQ(chain[k].second, chain[k + 1].first) << name;
        out.insert({chain.front().first, chain.back().second});
    }
    return out;
}

bool colour_is(const json& style, double r, double g, double b) {
    const json& c = style.at("c").at("k");
    return std::abs(c.at(0).get<double>() - r) < 1e-3 && std::abs(c.at(1).get<double>() - g) < 1e-3 &&
           std::abs(c.at(2).get<double>() - b) < 1e-3;
}

} // namespace

// A circle moving right whose hidden arc grows and shrinks: at every frame
// the shown vertices lie on that frame's circle, visible ones outside the
// hidden arc and hidden ones inside it, and together they cover the circle.
TEST(Lottie, StrokesFollowTheFramesWithTheirVisibility) {
    std::vector<AnimationFrame> frames;
    const int n = 200, count = 30;
    auto width_at = [](int f) { return f < 5 ? 0.0 : f < 15 ? 0.08 * (f - 5) : f < 25 ? 0.08 * (25 - f) : 0.0; };
    for (int f = 0; f < count; ++f) {
        const double w = width_at(f);
        frames.push_back(frame_with({{circle_loop({200.0 + f, 200.0}, 100.0, n, [&](double a) { return std::abs(a - M_PI) < w; }),
                                      ids(1, 1000, n)}}));
    }
    AnimatedSvgStats stats;
    // Hidden lines solid, so that together the strokes cover the circle
    // (dashes are pieces of the line: FillsAndDashes).
    Style style = default_style();
    ContourStyle solid = style.contour(ContourSpec{});
    solid.hidden.dash.clear();
    style.contours = {solid};
    const json doc = read_checked(to_lottie(frames, 24.0, {}, style, &stats), count, 400, 400);
    EXPECT_EQ(doc.at("fr").get<double>(), 24.0);
    EXPECT_EQ(stats.paths, 2u);
    EXPECT_EQ(lives(doc, "visual visible"), (std::multiset<std::pair<double, double>>{{0.0, 30.0}}));
    const auto hidden_lives = lives(doc, "visual hidden");
    ASSERT_EQ(hidden_lives.size(), 1u);
    // The background is the bottom layer, in the style's colour.
    EXPECT_EQ(doc.at("layers").back().at("ty"), 1);
    EXPECT_EQ(doc.at("layers").back().at("sc"), "#ffffff");

    const ContourStyle& cs = solid;
    auto grey = [](const std::string& hex) { return double(std::stoul(hex.substr(1, 2), nullptr, 16)) / 255.0; };
    // Told apart by width (hidden lines are thinner); their dashes are pieces of the line.
    auto is_hidden = [&](const json& st) {
        return st.at("ty") == "st" && std::abs(st.at("w").at("k").get<double>() - cs.hidden.width) < 1e-9;
    };
    auto is_visible = [&](const json& st) { return st.at("ty") == "st" && !is_hidden(st); };
    for (const json& layer : doc.at("layers")) {
        if (layer.at("ty") != 4) continue;
        const json& st = layer.at("shapes").back();
        const StrokeStyle& s = is_hidden(st) ? cs.hidden : cs.visible;
        EXPECT_TRUE(colour_is(st, grey(s.colour), grey(s.colour), grey(s.colour)));
        EXPECT_NEAR(st.at("w").at("k").get<double>(), s.width, 1e-9);
        EXPECT_NEAR(st.at("o").at("k").get<double>(), 100.0 * s.opacity, 1e-6);
    }
    for (int f = 0; f < count; ++f) {
        const glm::dvec2 centre(200.0 + f, 200.0);
        const double w = width_at(f);
        std::vector<glm::dvec2> all;
        std::vector<std::pair<glm::dvec2, glm::dvec2>> segments;
        for (const bool hidden : {false, true}) {
            for (const Evaluated& e : shown_at(doc, f, hidden ? std::function<bool(const json&)>(is_hidden) : is_visible)) {
                for (std::size_t k = 0; k < e.v.size(); ++k) {
                    const glm::dvec2 p = e.v[k];
                    EXPECT_NEAR(glm::length(p - centre), 100.0, 0.5) << "frame " << f;
                    const double a = std::atan2(p.y - centre.y, p.x - centre.x);
                    const double from_pi = std::abs(std::abs(a) - M_PI);
                    // Run ends may lie up to the min run (3 px) and a segment off the arc's ends.
                    if (hidden) EXPECT_LT(from_pi, w + 0.06) << "frame " << f;
                    else EXPECT_GT(from_pi, w - 0.06) << "frame " << f;
                    if (k + 1 < e.v.size() || e.closed) segments.push_back({p, e.v[(k + 1) % e.v.size()]});
                }
            }
        }
        // Every point of the frame's circle is drawn by some shown segment.
        for (int k = 0; k < 360; ++k) {
            const double a = 2.0 * M_PI * k / 360.0;
            const glm::dvec2 p = centre + 100.0 * glm::dvec2(std::cos(a), std::sin(a));
            double best = 1e9;
            for (const auto& [x, y] : segments) best = std::min(best, point_segment(p, x, y));
            EXPECT_LT(best, 0.5) << "frame " << f << " angle " << a;
        }
    }
}

// Sequences created, annihilated, changed abruptly and seen one frame only:
// each path's layers chain over exactly its life.
TEST(Lottie, EachSequenceIsAChainOfLayersOverItsLife) {
    const int n = 120;
    auto none = [](double) { return false; };
    std::vector<AnimationFrame> frames;
    for (int f = 0; f < 20; ++f) {
        std::vector<std::pair<DrawnLoop, AnimatedLoop>> loops;
        loops.push_back({circle_loop({200, 200}, f < 10 ? 80.0 : 40.0, n, none), ids(1, f < 10 ? 1000 : 5000, n)});
        if (f >= 4) loops.push_back({circle_loop({80, 80}, 20.0 + f, n, none), ids(2, 2000, n)});
        if (f < 12) loops.push_back({circle_loop({320, 320}, 30.0 - f, n, none), ids(3, 3000, n)});
        if (f == 7) loops.push_back({circle_loop({320, 80}, 3.0, 12, none), ids(4, 4000, 12)});
        frames.push_back(frame_with(std::move(loops)));
    }
    const json doc = read_checked(to_lottie(frames, 30.0), 20, 400, 400);
    EXPECT_EQ(lives(doc, "visual visible"),
              (std::multiset<std::pair<double, double>>{{0.0, 20.0}, {4.0, 20.0}, {0.0, 12.0}, {7.0, 8.0}}));
    // The abrupt change at frame 10: the big circle until then, the small one after.
    for (const auto& [f, radius] : {std::pair{9, 80.0}, std::pair{10, 40.0}}) {
        bool found = false;
        for (const Evaluated& e : shown_at(doc, f, [](const json&) { return true; }))
            found |= !e.v.empty() && std::abs(glm::length(e.v[0] - glm::dvec2(200, 200)) - radius) < 0.5;
        EXPECT_TRUE(found) << "frame " << f;
    }
}

// Fills: one chain of layers per region track, in the region's colour and
// opacity, under the strokes; surface-fastened dashes are pieces of the line.
TEST(Lottie, FillsAndDashes) {
    auto square = [](glm::dvec2 lo, double size) {
        return std::vector<glm::dvec2>{lo, lo + glm::dvec2(size, 0), lo + glm::dvec2(size, size), lo + glm::dvec2(0, size)};
    };
    Style style = default_style();
    style.background = "none";
    style.regions.push_back({RegionClass::Lit, 0.0, "#ffcc00", 0.5, 0.0});
    ContourStyle cs = style.contour(ContourSpec{});
    cs.visible.dash = {6.0, 4.0, 2.0};
    cs.visible.dash_on_surface = true;
    style.contours = {cs};
    std::vector<AnimationFrame> frames;
    for (int f = 0; f < 24; ++f) {
        AnimationFrame fr = frame_with({{circle_loop({200.0 + 2 * f, 200.0}, 60.0, 90, [](double) { return false; }), ids(1, 1000, 90)}});
        MapRegion r;
        r.cls = RegionClass::Lit;
        r.polygons.push_back(square({100.0 + f, 100.0}, 150.0));
        fr.regions.push_back(r);
        fr.region_tracks.push_back(7);
        frames.push_back(std::move(fr));
    }
    const json doc = read_checked(to_lottie(frames, 24.0, {}, style), 24, 400, 400);
    EXPECT_EQ(doc.at("layers").back().at("ty"), 4); // no background layer
    EXPECT_EQ(lives(doc, "fill lit"), (std::multiset<std::pair<double, double>>{{0.0, 24.0}}));
    bool seen_fill = false, seen_stroke = false;
    for (const json& layer : doc.at("layers")) {
        const json& style_item = layer.at("shapes").back();
        if (style_item.at("ty") == "fl") {
            seen_fill = true;
            EXPECT_TRUE(colour_is(style_item, 1.0, 0.8, 0.0));
            EXPECT_NEAR(style_item.at("o").at("k").get<double>(), 50.0, 1e-6);
            EXPECT_EQ(style_item.at("r"), 1);
        } else {
            EXPECT_FALSE(seen_fill) << "a stroke under a fill (Lottie lists the topmost layer first)";
            seen_stroke = true;
            // Dashes are pieces of the line, one shape each: no dash array.
            EXPECT_FALSE(style_item.contains("d"));
            std::size_t pieces = 0;
            for (const json& item : layer.at("shapes")) pieces += item.at("ty") == "sh";
            EXPECT_GE(pieces, 20u); // a circle of 377 px, a dash every 12 px
        }
    }
    EXPECT_TRUE(seen_fill);
    EXPECT_TRUE(seen_stroke);
    // The fill at frame 12 is that frame's square.
    const auto fills = shown_at(doc, 12.0, [](const json& s) { return s.at("ty") == "fl"; });
    ASSERT_EQ(fills.size(), 1u);
    for (const glm::dvec2& p : fills[0].v) {
        const double dx = std::min(std::abs(p.x - 112.0), std::abs(p.x - 262.0));
        const double dy = std::min(std::abs(p.y - 100.0), std::abs(p.y - 250.0));
        EXPECT_LT(std::min(dx, dy), 0.3);
    }
}

TEST(Lottie, EmptyAnimation) {
    const json doc = json::parse(to_lottie({}, 24.0));
    EXPECT_EQ(doc.at("layers").size(), 1u); // the background only
    EXPECT_EQ(doc.at("op").get<double>(), 1.0);
}
