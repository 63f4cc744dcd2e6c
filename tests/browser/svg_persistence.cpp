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

namespace {

struct Token {
    char cmd = 0; // a command letter, or 0 for a number
    double v = 0.0;
};

std::vector<Token> tokenize(const std::string& d) {
    std::vector<Token> out;
    const char* s = d.c_str();
    while (*s) {
        if (std::strchr("MmLlHhVvCcSsQqTtZzAa", *s)) {
            out.push_back({*s, 0.0});
            ++s;
        } else if (std::strchr("+-.0123456789", *s)) {
            char* end = nullptr;
            const double v = std::strtod(s, &end);
            if (end == s) { ++s; continue; }
            out.push_back({0, v});
            s = end;
        } else {
            ++s;
        }
    }
    return out;
}

bool compatible(const std::vector<Token>& a, const std::vector<Token>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].cmd != b[i].cmd) return false;
    return true;
}

struct Pt {
    double x = 0, y = 0;
};

// Subpaths of the path, curves flattened.
std::vector<std::vector<Pt>> flatten(const std::vector<Token>& t) {
    std::vector<std::vector<Pt>> subs;
    Pt cur, start, last_ctrl;
    char cmd = 0, prev_cmd = 0;
    std::size_t i = 0;
    auto num = [&]() { return i < t.size() && t[i].cmd == 0 ? t[i++].v : 0.0; };
    auto line_to = [&](Pt p) {
        if (subs.empty()) subs.push_back({cur});
        subs.back().push_back(p);
        cur = p;
    };
    auto cubic = [&](Pt c1, Pt c2, Pt p) {
        const Pt p0 = cur;
        for (int k = 1; k <= 16; ++k) {
            const double u = k / 16.0, w = 1 - u;
            line_to({w * w * w * p0.x + 3 * w * w * u * c1.x + 3 * w * u * u * c2.x + u * u * u * p.x,
                     w * w * w * p0.y + 3 * w * w * u * c1.y + 3 * w * u * u * c2.y + u * u * u * p.y});
        }
        last_ctrl = c2;
    };
    while (i < t.size()) {
        if (t[i].cmd) cmd = t[i++].cmd;
        else if (cmd == 'M') cmd = 'L';
        else if (cmd == 'm') cmd = 'l';
        const bool rel = std::islower(static_cast<unsigned char>(cmd));
        const Pt base = rel ? cur : Pt{};
        switch (std::toupper(static_cast<unsigned char>(cmd))) {
        case 'M': {
            const double x = num(), y = num();
            cur = start = {base.x + x, base.y + y};
            subs.push_back({cur});
            break;
        }
        case 'L': { const double x = num(), y = num(); line_to({base.x + x, base.y + y}); break; }
        case 'H': { const double x = num(); line_to({base.x + x, cur.y}); break; }
        case 'V': { const double y = num(); line_to({cur.x, base.y + y}); break; }
        case 'C': {
            const double a = num(), b = num(), c = num(), d = num(), e = num(), f = num();
            cubic({base.x + a, base.y + b}, {base.x + c, base.y + d}, {base.x + e, base.y + f});
            break;
        }
        case 'S': {
            const bool smooth = std::strchr("CcSs", prev_cmd) != nullptr;
            const Pt c1 = smooth ? Pt{2 * cur.x - last_ctrl.x, 2 * cur.y - last_ctrl.y} : cur;
            const double c = num(), d = num(), e = num(), f = num();
            cubic(c1, {base.x + c, base.y + d}, {base.x + e, base.y + f});
            break;
        }
        case 'Q': {
            const double a = num(), b = num(), e = num(), f = num();
            const Pt q{base.x + a, base.y + b}, p{base.x + e, base.y + f}, p0 = cur;
            cubic({p0.x + 2.0 / 3 * (q.x - p0.x), p0.y + 2.0 / 3 * (q.y - p0.y)},
                  {p.x + 2.0 / 3 * (q.x - p.x), p.y + 2.0 / 3 * (q.y - p.y)}, p);
            break;
        }
        case 'Z':
            if (!subs.empty()) subs.back().push_back(start);
            cur = start;
            break;
        default: // arcs are not written by the exporter: take their end point
            if (std::toupper(static_cast<unsigned char>(cmd)) == 'A') {
                for (int k = 0; k < 5; ++k) num();
                const double x = num(), y = num();
                line_to({base.x + x, base.y + y});
            } else {
                ++i;
            }
        }
        prev_cmd = cmd;
    }
    return subs;
}

double length_of(const std::vector<std::vector<Pt>>& subs) {
    double l = 0;
    for (const auto& s : subs)
        for (std::size_t k = 1; k < s.size(); ++k) l += std::hypot(s[k].x - s[k - 1].x, s[k].y - s[k - 1].y);
    return l;
}

double area_of(const std::vector<std::vector<Pt>>& subs) {
    double a = 0; // signed: holes wound the other way subtract (non-zero rule)
    for (const auto& s : subs)
        for (std::size_t k = 0; k < s.size(); ++k) {
            const Pt& p = s[k];
            const Pt& q = s[(k + 1) % s.size()];
            a += p.x * q.y - q.x * p.y;
        }
    return std::abs(a) / 2;
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out(1);
    for (const char c : s) {
        if (c == sep) out.emplace_back();
        else out.back() += c;
    }
    return out;
}

struct PathInfo {
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300; // drawn extent over the frames shown
    bool fill = false;
    std::vector<int> shown; // frames
    double measure = 0;     // length or area, summed over the frames shown
    bool visible_without_smil = true;
};

pugi::xml_node animate_of(pugi::xml_node path, const char* attribute) {
    for (pugi::xml_node a : path.children("animate"))
        if (std::strcmp(a.attribute("attributeName").value(), attribute) == 0) return a;
    return {};
}

// The value list entry in force at normalized time t (discrete).
std::size_t interval_at(const std::vector<double>& times, double t) {
    std::size_t k = 0;
    while (k + 1 < times.size() && times[k + 1] <= t) ++k;
    return k;
}

std::vector<double> numbers(const std::string& s) {
    std::vector<double> out;
    for (const auto& p : split(s, ';')) out.push_back(std::atof(p.c_str()));
    return out;
}

PathInfo measure(pugi::xml_node path, bool fill, bool outline, int frames) {
    PathInfo info;
    info.fill = fill;
    const std::string display = path.attribute("display").value();
    info.visible_without_smil = display != "none";
    std::vector<double> dtimes;
    std::vector<std::string> dvalues;
    if (pugi::xml_node a = animate_of(path, "d")) {
        dtimes = numbers(a.attribute("keyTimes").value());
        dvalues = split(a.attribute("values").value(), ';');
    }
    std::vector<double> show_times;
    std::vector<std::string> show_values;
    if (pugi::xml_node a = animate_of(path, "display")) {
        show_times = numbers(a.attribute("keyTimes").value());
        show_values = split(a.attribute("values").value(), ';');
    }
    for (int f = 0; f < frames; ++f) {
        // Display in the middle of the frame; the shape just after its start.
        const double mid = (f + 0.5) / frames, at = (f + 0.01) / frames;
        bool shown = info.visible_without_smil;
        if (!show_times.empty()) shown = show_values[interval_at(show_times, mid)] != "none";
        if (!shown) continue;
        info.shown.push_back(f);
        std::vector<Token> shape;
        if (dtimes.size() >= 2 && dtimes.size() == dvalues.size()) {
            const std::size_t k = interval_at(dtimes, at);
            const std::size_t k1 = std::min(k + 1, dtimes.size() - 1);
            const std::vector<Token> a = tokenize(dvalues[k]), b = tokenize(dvalues[k1]);
            const double span = dtimes[k1] - dtimes[k];
            const double u = span > 0 ? std::clamp((at - dtimes[k]) / span, 0.0, 1.0) : 0.0;
            shape = a;
            if (compatible(a, b))
                for (std::size_t i = 0; i < a.size(); ++i) shape[i].v = (1 - u) * a[i].v + u * b[i].v;
        } else {
            shape = tokenize(path.attribute("d").value());
        }
        const auto subs = flatten(shape);
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
