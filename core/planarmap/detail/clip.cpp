#include "snaxels/planarmap/detail/clip.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace snaxels::clip {

Paths to_paths(const std::vector<std::vector<glm::dvec2>>& polygons) {
    Paths out;
    for (const auto& poly : polygons) {
        ClipperLib::Path path;
        for (const glm::dvec2& p : poly)
            path.push_back({ClipperLib::cInt(std::llround(p.x * kScale)), ClipperLib::cInt(std::llround(p.y * kScale))});
        if (path.size() >= 3) out.push_back(std::move(path));
    }
    return out;
}

std::vector<std::vector<glm::dvec2>> from_paths(const Paths& paths) {
    std::vector<std::vector<glm::dvec2>> out;
    for (const auto& path : paths) {
        std::vector<glm::dvec2> poly;
        for (const auto& p : path) poly.push_back({double(p.X) / kScale, double(p.Y) / kScale});
        out.push_back(std::move(poly));
    }
    return out;
}

Paths op(const Paths& a, const Paths& b, ClipperLib::ClipType type) {
    ClipperLib::Clipper c;
    c.AddPaths(a, ClipperLib::ptSubject, true);
    c.AddPaths(b, ClipperLib::ptClip, true);
    Paths out;
    c.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
}

double area(const Paths& paths) {
    double a = 0.0;
    for (const auto& p : paths) a += ClipperLib::Area(p);
    return std::abs(a) / (kScale * kScale);
}

double perimeter(const Paths& paths) {
    double length = 0.0;
    for (const auto& path : paths)
        for (std::size_t i = 0; i < path.size(); ++i) {
            const auto& a = path[i];
            const auto& b = path[(i + 1) % path.size()];
            length += std::hypot(double(b.X - a.X), double(b.Y - a.Y));
        }
    return length / kScale;
}

void difference_tree(const Paths& a, const Paths& b, ClipperLib::PolyTree& out) {
    ClipperLib::Clipper c;
    c.AddPaths(a, ClipperLib::ptSubject, true);
    if (!b.empty()) c.AddPaths(b, ClipperLib::ptClip, true);
    c.Execute(b.empty() ? ClipperLib::ctUnion : ClipperLib::ctDifference, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
}

std::vector<InsidePoint> inside_points(const Paths& piece) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& path : piece)
        for (const auto& p : path) lo = std::min(lo, double(p.Y)), hi = std::max(hi, double(p.Y));
    std::vector<InsidePoint> spans;
    if (!(hi > lo)) return {};
    for (int row = 1; row <= 15; ++row) {
        const double y = lo + (hi - lo) * row / 16.0;
        // Crossings with their winding, in order along the row.
        std::vector<std::pair<double, int>> crossings;
        for (const auto& path : piece)
            for (std::size_t i = 0; i < path.size(); ++i) {
                const auto& a = path[i];
                const auto& b = path[(i + 1) % path.size()];
                if ((double(a.Y) <= y) == (double(b.Y) <= y)) continue;
                const double t = (y - double(a.Y)) / double(b.Y - a.Y);
                crossings.push_back({double(a.X) + t * double(b.X - a.X), b.Y > a.Y ? 1 : -1});
            }
        std::sort(crossings.begin(), crossings.end());
        int winding = 0;
        for (std::size_t i = 0; i + 1 < crossings.size(); ++i) {
            winding += crossings[i].second;
            const double width = crossings[i + 1].first - crossings[i].first;
            if (winding != 0 && width > 0.0)
                spans.push_back({width / kScale, glm::dvec2(0.5 * (crossings[i].first + crossings[i + 1].first), y) / kScale});
        }
    }
    std::stable_sort(spans.begin(), spans.end(), [](const auto& a, const auto& b) { return a.width > b.width; });
    return spans;
}

std::vector<Paths> pieces_of(const ClipperLib::PolyTree& tree) {
    std::vector<Paths> out;
    for (const ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
        if (node->IsHole()) continue;
        Paths piece{node->Contour};
        for (const ClipperLib::PolyNode* hole : node->Childs) piece.push_back(hole->Contour);
        out.push_back(std::move(piece));
    }
    return out;
}

ClipperLib::Path cropped(const ClipperLib::Path& path, const Box& path_box, const Box& to) {
    return path_box.within(to) ? path : crop(path, {to.x0, to.y0}, {to.x1, to.y1});
}

std::vector<Paths> pieces_of_opened(const Paths& piece, double radius) {
    // Mitred joins (limit 2): an opening of a polygon keeps its corners
    // within the limit as they were.
    ClipperLib::ClipperOffset in(2.0);
    in.AddPaths(piece, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    Paths shrunk;
    in.Execute(shrunk, -radius * kScale);
    if (shrunk.empty()) return {};
    ClipperLib::ClipperOffset out(2.0);
    out.AddPaths(shrunk, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    ClipperLib::PolyTree tree;
    out.Execute(tree, radius * kScale);
    return pieces_of(tree);
}

ClipperLib::Path crop(const ClipperLib::Path& path, const ClipperLib::IntPoint& lo, const ClipperLib::IntPoint& hi) {
    ClipperLib::Path in = path, out;
    for (int side = 0; side < 4; ++side) {
        out.clear();
        const bool x_axis = side < 2;
        const ClipperLib::cInt bound = side == 0 ? lo.X : side == 1 ? hi.X : side == 2 ? lo.Y : hi.Y;
        auto value = [&](const ClipperLib::IntPoint& p) { return x_axis ? p.X : p.Y; };
        auto inside = [&](const ClipperLib::IntPoint& p) { return side % 2 == 0 ? value(p) >= bound : value(p) <= bound; };
        if (std::all_of(in.begin(), in.end(), inside)) continue; // nothing past this side: as it is
        for (std::size_t i = 0; i < in.size(); ++i) {
            const ClipperLib::IntPoint& a = in[i];
            const ClipperLib::IntPoint& b = in[(i + 1) % in.size()];
            if (inside(a)) out.push_back(a);
            if (inside(a) == inside(b)) continue;
            const double t = double(bound - value(a)) / double(value(b) - value(a));
            const auto other = [&](ClipperLib::cInt u, ClipperLib::cInt v) { return ClipperLib::cInt(std::llround(double(u) + t * double(v - u))); };
            out.push_back(x_axis ? ClipperLib::IntPoint(bound, other(a.Y, b.Y)) : ClipperLib::IntPoint(other(a.X, b.X), bound));
        }
        std::swap(in, out);
        if (in.size() < 3) return {};
    }
    return in;
}

} // namespace snaxels::clip
