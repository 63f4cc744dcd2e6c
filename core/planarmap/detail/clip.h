#pragma once
/// Polygon clipping for the planar maps, on Clipper's integer grid
/// (1/1024 pixel): conversions, boolean operations and areas.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include <glm/glm.hpp>
#include <polyclipping/clipper.hpp>

namespace snaxels::clip {

using ClipperLib::Paths;

constexpr double kScale = 1024.0; ///< Clipper works in integers: 1/1024 pixel

Paths to_paths(const std::vector<std::vector<glm::dvec2>>& polygons);
std::vector<std::vector<glm::dvec2>> from_paths(const Paths& paths);
/// @p a op @p b, both filled non-zero.
Paths op(const Paths& a, const Paths& b, ClipperLib::ClipType type);
/// Square pixels covered (signed areas add up: holes wind the other way).
double area(const Paths& paths);
/// Pixels around every path (outlines and holes).
double perimeter(const Paths& paths);

/// @p path cut to the box [lo, hi] (Sutherland-Hodgman): under non-zero
/// fill the result covers exactly the part of the path's area in the box.
ClipperLib::Path crop(const ClipperLib::Path& path, const ClipperLib::IntPoint& lo, const ClipperLib::IntPoint& hi);

/// A bounding box on Clipper's grid, for skipping paths that cannot meet.
struct Box {
    ClipperLib::cInt x0 = std::numeric_limits<ClipperLib::cInt>::max(), y0 = x0;
    ClipperLib::cInt x1 = std::numeric_limits<ClipperLib::cInt>::min(), y1 = x1;
    void add(const ClipperLib::Path& path) {
        for (const auto& p : path) x0 = std::min(x0, p.X), y0 = std::min(y0, p.Y), x1 = std::max(x1, p.X), y1 = std::max(y1, p.Y);
    }
    void add(const Box& o) { x0 = std::min(x0, o.x0), y0 = std::min(y0, o.y0), x1 = std::max(x1, o.x1), y1 = std::max(y1, o.y1); }
    bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
    bool within(const Box& o) const { return x0 >= o.x0 && y0 >= o.y0 && x1 <= o.x1 && y1 <= o.y1; }
    /// Wider by @p units on every side.
    Box widened(ClipperLib::cInt units) const { return {x0 - units, y0 - units, x1 + units, y1 + units}; }
};

/// @p path (whose box is @p path_box) as it is where it lies within
/// @p to, else cut to it (crop).
ClipperLib::Path cropped(const ClipperLib::Path& path, const Box& path_box, const Box& to);

/// A point inside a polygon set and the width of the span it is the
/// middle of.
struct InsidePoint {
    double width; ///< pixels
    glm::dvec2 at; ///< pixels
};

/// Points inside @p piece (an outline and its holes, non-zero), best
/// first: the middles of the spans 15 rows across it cover, widest first.
std::vector<InsidePoint> inside_points(const Paths& piece);

/// @p a minus @p b (both non-zero; @p a alone, normalized, when @p b is
/// empty) as a tree of outlines and holes.
void difference_tree(const Paths& a, const Paths& b, ClipperLib::PolyTree& out);

/// The pieces of a normalized polygon set: each outline with its holes.
std::vector<Paths> pieces_of(const ClipperLib::PolyTree& tree);

/// The pieces of @p piece (an outline and its holes) opened by @p radius
/// pixels (shrunk, then grown back): what is thinner than twice the
/// radius is gone, the rest keeps its outline.
std::vector<Paths> pieces_of_opened(const Paths& piece, double radius);

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
        return op(to_paths(loops), {}, ClipperLib::ctUnion);
    }

  private:
    std::map<std::pair<std::int64_t, std::int64_t>, int> steps_;
};


} // namespace snaxels::clip
