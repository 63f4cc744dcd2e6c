// The animated SVG's parts: the SMIL writer, key and vertex reduction,
// visibility spans, and whole animations built by hand whose contours and
// regions go through each kind of event. Paths are read back from the text
// with a small reader of this file's own (no exporter code).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <map>
#include <set>
#include <regex>
#include <string>

#include "snaxels/export/detail/animated_fills.h"
#include "snaxels/export/detail/animated_strokes.h"
#include "snaxels/export/animated_svg.h"
#include "snaxels/export/animation_writer.h"
#include "snaxels/export/detail/path_keys.h"
#include "snaxels/export/detail/smil.h"
#include "tests/support/coverage.h"
#include "tests/support/drawn_frames.h"

using namespace snaxels;

namespace {

std::vector<double> split_numbers(const std::string& s) {
    std::vector<double> out;
    std::size_t at = 0;
    while (at <= s.size()) {
        const std::size_t end = s.find(';', at);
        out.push_back(std::atof(s.substr(at, end - at).c_str()));
        if (end == std::string::npos) break;
        at = end + 1;
    }
    return out;
}

/// One <path> of the document: its attributes and its animations' attributes.
struct ReadPath {
    std::string attributes, display_times, display_values, d_times, d_values;
    std::string group; ///< the innermost layer id it sits in
};

std::string attribute(const std::string& tag, const std::string& name) {
    const std::regex re(" " + name + "=\"([^\"]*)\"");
    std::smatch m;
    return std::regex_search(tag, m, re) ? m[1].str() : std::string();
}

std::vector<ReadPath> read_paths(const std::string& svg) {
    std::vector<ReadPath> out;
    std::vector<std::string> groups;
    const std::regex tag("<(/?)(g|path|animate)([^>]*?)(/?)>");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tag); it != std::sregex_iterator(); ++it) {
        const std::string closing = (*it)[1], name = (*it)[2], attrs = (*it)[3];
        if (name == "g") {
            if (closing.empty()) groups.push_back(attribute(attrs, "id"));
            else groups.pop_back();
        } else if (name == "path" && closing.empty()) {
            out.push_back({attrs, "", "", "", "", groups.empty() ? "" : groups.back()});
        } else if (name == "animate" && !out.empty()) {
            const std::string what = attribute(attrs, "attributeName");
            if (what == "display") out.back().display_times = attribute(attrs, "keyTimes"), out.back().display_values = attribute(attrs, "values");
            if (what == "d") out.back().d_times = attribute(attrs, "keyTimes"), out.back().d_values = attribute(attrs, "values");
        }
    }
    return out;
}

/// Frames [first, last] in which the path shows (from its display animation).
std::pair<int, int> shown(const ReadPath& p, int frames) {
    int first = -1, last = -1;
    for (int f = 0; f < frames; ++f) {
        bool on = attribute(p.attributes, "display") != "none";
        if (!p.display_times.empty()) {
            const std::vector<double> t = split_numbers(p.display_times);
            std::vector<std::string> v;
            std::size_t at = 0;
            for (;;) {
                const std::size_t end = p.display_values.find(';', at);
                v.push_back(p.display_values.substr(at, end - at));
                if (end == std::string::npos) break;
                at = end + 1;
            }
            std::size_t k = 0;
            while (k + 1 < t.size() && t[k + 1] <= (f + 0.5) / frames) ++k;
            on = v[k] != "none";
        }
        if (on) {
            if (first < 0) first = f;
            last = f;
        }
    }
    return {first, last};
}

using test::circle_loop;
using test::frame_with;
using test::ids;

std::size_t count_in(const std::vector<ReadPath>& paths, const std::string& group) {
    std::size_t n = 0;
    for (const auto& p : paths) n += p.group == group;
    return n;
}

} // namespace

// keyTimes stay strictly increasing as printed, even a thousandth of a
// frame apart, and the path's display follows the frames it is shown in.
TEST(Smil, KeyTimesAndDisplay) {
    const smil::Clock clock{360, 24.0};
    const std::vector<double> t = split_numbers(smil::key_times({0.0, 10.0, 10.0 + anim::kSwitch, 359.0}, clock));
    ASSERT_EQ(t.size(), 4u);
    for (std::size_t k = 1; k < t.size(); ++k) EXPECT_GT(t[k], t[k - 1]);
    EXPECT_NEAR(t[2] * 360.0, 10.001, 1e-4);

    smil::AnimatedPath p;
    p.times = {5.0, 9.0};
    p.values = {"m1 1l1 0", "m2 2l1 0"};
    p.shown = {{5, 9}};
    std::string out;
    EXPECT_EQ(smil::append_path(out, "", p, smil::Clock{20, 10.0}), 2u);
    const auto paths = read_paths(out);
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_EQ(attribute(paths[0].attributes, "display"), "none"); // not at frame 0: hidden without SMIL
    EXPECT_EQ(shown(paths[0], 20), std::make_pair(5, 9));
    EXPECT_EQ(paths[0].d_values, "m1 1l1 0;m1 1l1 0;m2 2l1 0;m2 2l1 0"); // held before and after

    // Shown from frame 0: drawn without SMIL, with its first shape.
    p.shown = {{0, 19}};
    p.times = {0.0, 9.0};
    out.clear();
    smil::append_path(out, "", p, smil::Clock{20, 10.0});
    const auto always = read_paths(out);
    EXPECT_EQ(attribute(always[0].attributes, "display"), "");
    EXPECT_EQ(attribute(always[0].attributes, "d"), "m1 1l1 0");
    EXPECT_TRUE(always[0].display_times.empty());
}

// Keys that linear interpolation reproduces go; a change of pace stays.
TEST(PathKeys, ReduceKeysKeepsOnlyWhatInterpolationMisses) {
    anim::Segment seg;
    for (int k = 0; k <= 10; ++k) {
        seg.times.push_back(k);
        const double x = k <= 5 ? 2.0 * k : 10.0 + 10.0 * (k - 5); // faster after frame 5
        seg.shapes.push_back({anim::Subpath{{glm::dvec2(x, 0), glm::dvec2(x + 10, 0)}, false}});
    }
    const auto keep = anim::reduce_keys(seg, 0.25);
    std::vector<int> kept;
    for (int k = 0; k <= 10; ++k)
        if (keep[std::size_t(k)]) kept.push_back(k);
    EXPECT_EQ(kept, (std::vector<int>{0, 5, 10}));
}

// Vertices every key reproduces go, from every key at once; a bend that
// one key has keeps its vertex in all.
TEST(PathKeys, ReduceVerticesIsJointOverKeys) {
    anim::Segment seg;
    for (int k = 0; k < 3; ++k) {
        anim::Subpath sp;
        for (int v = 0; v <= 10; ++v) sp.pts.push_back(glm::dvec2(v, (k == 2 && v == 7) ? 3.0 : 0.0));
        seg.times.push_back(k);
        seg.shapes.push_back({sp});
    }
    anim::reduce_vertices(seg, 0.25, 0.0);
    // The ends, the spike and its foot on each side, in every key.
    for (const auto& shape : seg.shapes) ASSERT_EQ(shape[0].pts.size(), 5u);
    EXPECT_EQ(seg.shapes[0][0].pts[2], glm::dvec2(7, 0));
    EXPECT_EQ(seg.shapes[2][0].pts[2], glm::dvec2(7, 3));
    EXPECT_EQ(seg.shapes[1][0].pts[1], glm::dvec2(6, 0));
}

// Visibility flicker shorter than the minimum takes its neighbour's class;
// a closed loop left with one class is whole.
TEST(ClassSpans, FlickerJoinsItsNeighbours) {
    // Visible, a hidden sliver of 1% at u 0.3, then hidden from 0.6 to 0.9.
    constexpr StrokeClass V = StrokeClass::Visible, H = StrokeClass::Hidden;
    const auto spans = class_spans({{0.3, H}, {0.31, V}, {0.6, H}, {0.9, V}}, V, true, 0.02);
    ASSERT_EQ(spans.size(), 2u);
    for (const auto& s : spans) {
        EXPECT_FALSE(s.whole);
        if (s.cls == H) {
            EXPECT_NEAR(s.u1 - s.u0, 0.3, 1e-12);
        }
    }
    const auto whole = class_spans({{0.3, H}, {0.305, V}}, V, true, 0.02);
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_TRUE(whole[0].whole);
}

// A contour whose visibility changes keeps one visible and one hidden path
// for its whole life: a hidden stretch appears, grows, shrinks and goes.
TEST(AnimatedStrokes, VisibilityChangesDoNotEndPaths) {
    std::vector<AnimationFrame> frames;
    const int n = 200;
    for (int f = 0; f < 30; ++f) {
        // Hidden around angle pi, half-width growing to 0.8 rad by frame 15, gone by 25.
        const double w = f < 5 ? 0.0 : f < 15 ? 0.08 * (f - 5) : f < 25 ? 0.08 * (25 - f) : 0.0;
        const glm::dvec2 centre(200.0 + f, 200.0); // moving right
        frames.push_back(frame_with({{circle_loop(centre, 100.0, n, [&](double a) { return std::abs(a - M_PI) < w; }), ids(1, 1000, n)}}));
    }
    AnimatedSvgStats stats;
    const std::string svg = to_animated_svg(frames, 24.0, {}, default_style(), &stats);
    const auto paths = read_paths(svg);
    ASSERT_EQ(count_in(paths, "visible-visual"), 1u);
    ASSERT_EQ(count_in(paths, "hidden-visual"), 1u);
    for (const auto& p : paths) EXPECT_EQ(shown(p, 30), std::make_pair(0, 29)) << p.group;
    EXPECT_EQ(stats.paths, 2u);
    for (const auto& ps : stats.path_stats) EXPECT_EQ(ps.frames_shown, 30u);
}

// Contour sequences: a loop that is created, one annihilated, one that
// changes abruptly (most of its snaxels replaced) and one that lives a
// single frame.
TEST(AnimatedStrokes, EachSequenceIsOnePathForItsLife) {
    const int n = 120;
    auto none = [](double) { return false; };
    std::vector<AnimationFrame> frames;
    for (int f = 0; f < 20; ++f) {
        std::vector<std::pair<DrawnLoop, AnimatedLoop>> loops;
        // Sequence 1 all along; from frame 10 its snaxels are new ones and it is
        // half the size (an abrupt change), still sequence 1.
        loops.push_back({circle_loop({200, 200}, f < 10 ? 80.0 : 40.0, n, none), ids(1, f < 10 ? 1000 : 5000, n)});
        if (f >= 4) loops.push_back({circle_loop({80, 80}, 20.0 + f, n, none), ids(2, 2000, n)});   // created at 4
        if (f < 12) loops.push_back({circle_loop({320, 320}, 30.0 - f, n, none), ids(3, 3000, n)}); // annihilated after 11
        if (f == 7) loops.push_back({circle_loop({320, 80}, 3.0, 12, none), ids(4, 4000, 12)});     // one frame
        frames.push_back(frame_with(std::move(loops)));
    }
    const std::string svg = to_animated_svg(frames, 24.0);
    const auto paths = read_paths(svg);
    std::multiset<std::pair<int, int>> lives;
    std::size_t brief = 0;
    for (const auto& p : paths) {
        lives.insert(shown(p, 20));
        brief += attribute(p.attributes, "class") == "brief";
    }
    EXPECT_EQ(paths.size(), 4u);
    EXPECT_EQ(lives.count({0, 19}), 1u); // sequence 1 through its abrupt change
    EXPECT_EQ(lives.count({4, 19}), 1u); // created
    EXPECT_EQ(lives.count({0, 11}), 1u); // annihilated
    EXPECT_EQ(brief, 1u);                // the one-frame loop, in the path of brief contours
    EXPECT_EQ(lives.count({7, 7}), 1u);
}

// Fills: a region keeps one path while a hole opens and closes in it and
// while it gains and loses a second outline; it ends when it goes.
TEST(AnimatedFills, OneRegionOnePath) {
    auto square = [](glm::dvec2 lo, double size, bool hole) {
        std::vector<glm::dvec2> s = {lo, lo + glm::dvec2(size, 0), lo + glm::dvec2(size, size), lo + glm::dvec2(0, size)};
        if (hole) std::reverse(s.begin(), s.end());
        return s;
    };
    Style style = default_style();
    style.regions.push_back({RegionClass::Lit, 0.0, "#ffcc00", 1.0, 0.0});
    std::vector<AnimationFrame> frames;
    for (int f = 0; f < 24; ++f) {
        AnimationFrame fr = frame_with({});
        MapRegion r;
        r.cls = RegionClass::Lit;
        r.polygons.push_back(square({100.0 + f, 100.0}, 150.0, false));
        if (f >= 6 && f < 12) r.polygons.push_back(square({150.0 + f, 150.0}, 4.0 * (f - 5), true)); // a hole opens, grows
        if (f >= 14) r.polygons.push_back(square({300.0, 300.0 - f}, 30.0, false));               // an island appears
        fr.regions.push_back(r);
        fr.region_tracks.push_back(7);
        if (f < 10) { // a second region that ends at frame 9
            MapRegion gone;
            gone.cls = RegionClass::Lit;
            gone.polygons.push_back(square({20.0, 300.0}, 40.0, false));
            fr.regions.push_back(gone);
            fr.region_tracks.push_back(8);
        }
        frames.push_back(std::move(fr));
    }
    const auto paths = read_paths(to_animated_svg(frames, 24.0, {}, style));
    std::multiset<std::pair<int, int>> lives;
    for (const auto& p : paths)
        if (p.group == "fills") lives.insert(shown(p, 24));
    EXPECT_EQ(lives, (std::multiset<std::pair<int, int>>{{0, 23}, {0, 9}}));
}

// Loops match by nearness and winding: an outline never matches a hole.
TEST(AnimatedFills, MatchLoops) {
    const std::vector<glm::dvec2> a = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    std::vector<glm::dvec2> hole = a;
    std::reverse(hole.begin(), hole.end());
    std::vector<glm::dvec2> moved = a;
    for (auto& p : moved) p += glm::dvec2(3, 0);
    std::vector<glm::dvec2> far = a;
    for (auto& p : far) p += glm::dvec2(100, 0);
    const auto pairs = match_loops({a, hole}, {far, moved}, 4.0);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0], std::make_pair(std::size_t(0), std::size_t(1)));
}

// The animation is encoded in chunks of AnimationWriter::kChunkFrames frames
// (docs/animation.md): paths go on across them. Over 150 frames (four
// chunks) circles of known centre and radius come and go around the chunks'
// shared frames (48, 96, 144); each life is one path, and at every frame
// every shown stroke lies on its circle of that frame, with no path drawn
// twice.
TEST(AnimationWriter, PathsGoOnAcrossChunks) {
    ASSERT_EQ(AnimationWriter::kChunkFrames, 48u);
    const int frames = 150, n = 90;
    struct Circle {
        std::uint64_t sequence;
        int first, last;
        glm::dvec2 centre;
        double radius;
    };
    // Sequence 1 moves two pixels a frame, a quarter of it hidden.
    auto centre1 = [](int f) { return glm::dvec2(80.0 + 2.0 * f * 0.5, 200.0); };
    const std::vector<Circle> others = {
        {2, 47, 97, {300, 80}, 30},  // across two chunk starts, ends a frame after the second
        {3, 40, 48, {300, 320}, 25}, // ends on a shared frame
        {4, 48, 48, {60, 60}, 8},    // one frame: the shared one
        {5, 96, 140, {80, 330}, 35}, // starts on a shared frame
    };
    std::vector<AnimationFrame> fs;
    for (int f = 0; f < frames; ++f) {
        std::vector<std::pair<DrawnLoop, AnimatedLoop>> loops;
        const double turn = 0.02 * f;
        loops.push_back({circle_loop(centre1(f), 60.0, n, [turn](double a) { return std::fmod(a + turn, 2 * M_PI) < M_PI / 2; }),
                         ids(1, 1000, n)});
        for (const Circle& c : others)
            if (f >= c.first && f <= c.last)
                loops.push_back({circle_loop(c.centre + glm::dvec2(0.0, 0.3 * (f - c.first)), c.radius, n, [](double) { return false; }),
                                 ids(c.sequence, c.sequence * 1000, n)});
        fs.push_back(frame_with(std::move(loops)));
    }
    const std::string svg = to_animated_svg(fs, 24.0);
    // The paths, read without std::regex (whose recursion overflows the
    // stack on attribute values this long).
    auto attr = [](const std::string& tag, const std::string& name) {
        const std::size_t at = tag.find(" " + name + "=\"");
        if (at == std::string::npos) return std::string();
        const std::size_t from = at + name.size() + 3;
        return tag.substr(from, tag.find('"', from) - from);
    };
    std::vector<ReadPath> paths;
    for (std::size_t at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) {
        const std::size_t open_end = svg.find('>', at);
        ReadPath p;
        p.attributes = svg.substr(at + 5, open_end - at - 5);
        // d is kept apart (in group, unused here): shown() reads the rest with std::regex.
        p.group = attr(p.attributes, "d");
        if (const std::size_t d = p.attributes.find(" d=\""); d != std::string::npos)
            p.attributes.erase(d, p.attributes.find('"', d + 4) + 1 - d);
        const std::size_t close = svg.find("</path>", open_end);
        const std::string body = svg.substr(open_end + 1, close - open_end - 1);
        for (std::size_t a = body.find("<animate"); a != std::string::npos; a = body.find("<animate", a + 1)) {
            const std::string anim = body.substr(a, body.find("/>", a) - a);
            const std::string what = attr(anim, "attributeName");
            if (what == "display") p.display_times = attr(anim, "keyTimes"), p.display_values = attr(anim, "values");
            if (what == "d") p.d_times = attr(anim, "keyTimes"), p.d_values = attr(anim, "values");
        }
        paths.push_back(std::move(p));
    }
    std::multiset<std::pair<int, int>> lives;
    for (const auto& p : paths) lives.insert(shown(p, frames));
    EXPECT_EQ(lives.count({0, frames - 1}), 2u); // sequence 1, visible and hidden, one path each
    EXPECT_EQ(lives.count({47, 97}), 1u);
    EXPECT_EQ(lives.count({40, 48}), 1u);
    EXPECT_EQ(lives.count({96, 140}), 1u);
    EXPECT_EQ(lives.count({48, 48}), 1u); // the brief one
    EXPECT_EQ(paths.size(), 6u);

    // The shape a path draws at frame f (keyTimes and values: linear between
    // keys of one structure, else the earlier key's).
    auto shape_at = [&](const ReadPath& p, int f) {
        if (p.d_times.empty()) return test::parse_path(p.group);
        const std::vector<double> t = split_numbers(p.d_times);
        std::vector<std::string> v;
        for (std::size_t at = 0;;) {
            const std::size_t end = p.d_values.find(';', at);
            v.push_back(p.d_values.substr(at, end - at));
            if (end == std::string::npos) break;
            at = end + 1;
        }
        const double x = double(f) / frames;
        std::size_t k = 0;
        while (k + 1 < t.size() && t[k + 1] <= x) ++k;
        test::Loops a = test::parse_path(v[k]);
        if (k + 1 >= t.size()) return a;
        const test::Loops b = test::parse_path(v[k + 1]);
        bool same = a.size() == b.size();
        for (std::size_t s = 0; same && s < a.size(); ++s) same = a[s].size() == b[s].size();
        if (!same) return a;
        const double u = std::clamp((x - t[k]) / std::max(t[k + 1] - t[k], 1e-12), 0.0, 1.0);
        for (std::size_t s = 0; s < a.size(); ++s)
            for (std::size_t i = 0; i < a[s].size(); ++i) a[s][i] = (1.0 - u) * a[s][i] + u * b[s][i];
        return a;
    };
    int checked = 0;
    for (int f = 0; f < frames; ++f) {
        std::vector<std::pair<glm::dvec2, double>> circles{{centre1(f), 60.0}};
        for (const Circle& c : others)
            if (f >= c.first && f <= c.last) circles.push_back({c.centre + glm::dvec2(0.0, 0.3 * (f - c.first)), c.radius});
        std::vector<int> drawn(circles.size(), 0);
        for (const auto& p : paths) {
            const auto [first, last] = shown(p, frames);
            if (f < first || f > last) continue;
            const test::Loops shape = shape_at(p, f);
            // The circle it lies on: every point within 0.6 px of it.
            int on = -1;
            for (std::size_t c = 0; c < circles.size() && on < 0; ++c) {
                bool all = true;
                for (const auto& loop : shape)
                    for (const glm::dvec2& q : loop) all &= std::abs(glm::length(q - circles[c].first) - circles[c].second) < 0.6;
                if (all) on = int(c);
            }
            ASSERT_GE(on, 0) << "frame " << f << ": a path drawn off every circle (" << attr(p.attributes, "class") << ")";
            ++drawn[std::size_t(on)];
            ++checked;
        }
        EXPECT_EQ(drawn[0], 2) << "frame " << f; // visible and hidden parts of sequence 1
        for (std::size_t c = 1; c < circles.size(); ++c) EXPECT_EQ(drawn[c], 1) << "frame " << f << " circle " << c;
    }
    EXPECT_GT(checked, 400);
}
