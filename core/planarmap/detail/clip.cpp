#include "snaxels/planarmap/detail/clip.h"

#include <cmath>

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

} // namespace snaxels::clip
