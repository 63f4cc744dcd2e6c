// Reads an animated SVG the way a player does and measures how long its
// paths live: each path's frames shown (its display: an animate of display,
// discrete, or the attribute) and, in each frame shown, its drawn length
// (strokes) or area (fills), from its d animation (values interpolated
// number by number where the commands agree, as browsers do) or its d.
// Shares no code with the exporter it checks.
//
//   svg_persistence FILE.svg FRAMES [checks...]
// checks (each fails the run when it does not hold):
//   --strokes MIN_FRAMES SHARE   strokes: at least SHARE of length x frames is
//                                carried by paths shown MIN_FRAMES frames or more
//   --one-frame MAX_SHARE        stroke paths shown one frame only: at most MAX_SHARE of them
//   --fills MIN_FRAMES SHARE     fills: at least SHARE of area x frames likewise
//   --frame0-only                only paths shown at frame 0 are visible without SMIL
//   --framed MIN_SPAN            what the strokes draw over all frames is centred on the
//                                canvas (within 5% of its size) and spans at least MIN_SPAN
//                                of it across or down
// Fill paths are those inside <g id="fills">; stroke paths every other path.
// Strokes drawn as filled outlines (lines of varying width: a group with
// stroke="none" and a fill) are measured by their area, as fills are.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "tests/support/svg_player.h"

namespace {

using namespace snaxels::test::svg;

struct PathInfo {
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300; // drawn extent over the frames shown
    bool fill = false;
    std::vector<int> shown; // frames
    double measure = 0;     // length or area, summed over the frames shown
    bool visible_without_smil = true;
};

PathInfo measure(pugi::xml_node path, bool fill, bool outline, int frames) {
    PathInfo info;
    info.fill = fill;
    info.visible_without_smil = std::strcmp(path.attribute("display").value(), "none") != 0;
    for (int f = 0; f < frames; ++f) {
        // Display in the middle of the frame; the shape just after its start.
        const double mid = (f + 0.5) / frames, at = (f + 0.01) / frames;
        if (!shown_at(path, mid)) continue;
        info.shown.push_back(f);
        const auto subs = flatten(shape_at(path, at));
        const double m = fill || outline ? area_of(subs) : length_of(subs);
        info.measure += m;
        if (m > 0)
            for (const auto& sp : subs)
                for (const Pt& p : sp)
                    info.lo_x = std::min(info.lo_x, p.x), info.lo_y = std::min(info.lo_y, p.y),
                    info.hi_x = std::max(info.hi_x, p.x), info.hi_y = std::max(info.hi_y, p.y);
    }
    return info;
}

void collect(pugi::xml_node node, bool in_fills, bool outline, int frames, std::vector<PathInfo>& out) {
    for (pugi::xml_node c : node.children()) {
        if (std::strcmp(c.name(), "path") == 0) out.push_back(measure(c, in_fills, outline, frames));
        else if (std::strcmp(c.name(), "g") == 0)
            collect(c, in_fills || std::strcmp(c.attribute("id").value(), "fills") == 0,
                    outline || (std::strcmp(c.attribute("stroke").value(), "none") == 0 && c.attribute("fill") &&
                                std::strcmp(c.attribute("fill").value(), "none") != 0),
                    frames, out);
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: svg_persistence FILE.svg FRAMES [--strokes MIN SHARE] [--one-frame MAX] "
                             "[--fills MIN SHARE] [--frame0-only]\n");
        return 2;
    }
    pugi::xml_document doc;
    if (!doc.load_file(argv[1])) {
        std::fprintf(stderr, "%s: not readable XML\n", argv[1]);
        return 2;
    }
    const int frames = std::atoi(argv[2]);
    std::vector<PathInfo> paths;
    collect(doc.child("svg"), false, false, frames, paths);

    int failures = 0;
    auto share_of = [&](bool fill, int min_frames, double& total, std::size_t& count, std::size_t& long_count) {
        double carried = 0;
        total = 0;
        count = long_count = 0;
        for (const auto& p : paths) {
            if (p.fill != fill || p.shown.empty()) continue;
            ++count;
            total += p.measure;
            if (int(p.shown.size()) >= min_frames) carried += p.measure, ++long_count;
        }
        return total > 0 ? carried / total : 0.0;
    };
    std::size_t strokes = 0, one_frame = 0, fills = 0;
    std::map<std::size_t, std::size_t> life;
    for (const auto& p : paths) {
        if (p.shown.empty()) continue;
        if (p.fill) ++fills;
        else ++strokes, one_frame += p.shown.size() == 1, ++life[p.shown.size()];
    }
    double longest = 0, mean = 0;
    for (const auto& [frames_shown, n] : life) longest = double(frames_shown), mean += double(frames_shown * n);
    std::printf("stroke paths %zu (shown one frame only: %zu, %.1f%%), mean life %.1f frames, longest %.0f; fill paths %zu\n",
                strokes, one_frame, strokes ? 100.0 * double(one_frame) / double(strokes) : 0.0,
                strokes ? mean / double(strokes) : 0.0, longest, fills);
    for (int i = 3; i < argc; ++i) {
        const std::string opt = argv[i];
        if ((opt == "--strokes" || opt == "--fills") && i + 2 < argc) {
            const int min_frames = std::atoi(argv[i + 1]);
            const double want = std::atof(argv[i + 2]);
            i += 2;
            double total = 0;
            std::size_t count = 0, long_count = 0;
            const bool fill = opt == "--fills";
            const double share = share_of(fill, min_frames, total, count, long_count);
            const bool ok = share >= want && count > 0;
            std::printf("%s: %.1f%% of %s x frames carried by the %zu of %zu paths shown %d frames or more (need %.0f%%) %s\n",
                        fill ? "fills" : "strokes", 100 * share, fill ? "area" : "length", long_count, count,
                        min_frames, 100 * want, ok ? "ok" : "FAIL");
            failures += !ok;
        } else if (opt == "--one-frame" && i + 1 < argc) {
            const double max_share = std::atof(argv[++i]);
            const double share = strokes ? double(one_frame) / double(strokes) : 0.0;
            const bool ok = share <= max_share;
            std::printf("one-frame stroke paths: %.1f%% (at most %.0f%%) %s\n", 100 * share, 100 * max_share,
                        ok ? "ok" : "FAIL");
            failures += !ok;
        } else if (opt == "--frame0-only") {
            std::size_t wrong = 0;
            for (const auto& p : paths) {
                const bool at0 = !p.shown.empty() && p.shown.front() == 0;
                wrong += p.visible_without_smil != at0;
            }
            std::printf("paths whose SMIL-less visibility differs from frame 0: %zu %s\n", wrong, wrong ? "FAIL" : "ok");
            failures += wrong != 0;
        } else if (opt == "--framed" && i + 1 < argc) {
            const double min_span = std::atof(argv[++i]);
            const double w = doc.child("svg").attribute("width").as_double(), h = doc.child("svg").attribute("height").as_double();
            double lx = 1e300, ly = 1e300, hx = -1e300, hy = -1e300;
            for (const auto& p : paths)
                if (!p.fill) lx = std::min(lx, p.lo_x), ly = std::min(ly, p.lo_y), hx = std::max(hx, p.hi_x), hy = std::max(hy, p.hi_y);
            const double cx = 0.5 * (lx + hx) / w - 0.5, cy = 0.5 * (ly + hy) / h - 0.5;
            const double span = std::max((hx - lx) / w, (hy - ly) / h);
            const bool ok = w > 0 && h > 0 && std::abs(cx) <= 0.05 && std::abs(cy) <= 0.05 && span >= min_span;
            std::printf("drawn extent over all frames: x %.0f..%.0f, y %.0f..%.0f of %gx%g (centre off by %.1f%%, %.1f%%; spans %.0f%%, need %.0f%%) %s\n",
                        lx, hx, ly, hy, w, h, 100 * cx, 100 * cy, 100 * span, 100 * min_span, ok ? "ok" : "FAIL");
            failures += !ok;
        } else {
            std::fprintf(stderr, "unknown or incomplete check '%s'\n", opt.c_str());
            return 2;
        }
    }
    return failures ? 1 : 0;
}
