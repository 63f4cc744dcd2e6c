#include "core/export/drawing.h"

namespace snaxels {

Drawing make_drawing(const SnaxelEngine& engine, const std::vector<ContourResult>& results,
                     const ImageProjection& projection) {
    Drawing drawing;
    drawing.width = projection.width();
    drawing.height = projection.height();
    for (const ContourResult& r : results) {
        DrawnContour contour;
        contour.spec = r.spec;
        for (const FrontLoop& loop : r.fronts.loops) {
            DrawnLoop drawn;
            drawn.closed = loop.closed;
            drawn.p.reserve(std::size_t(loop.size));
            drawn.q.reserve(std::size_t(loop.size));
            r.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                const glm::dvec3 p = engine.position(r.fronts.snaxels[s]);
                drawn.p.push_back(p);
                drawn.q.push_back(projection.project(p));
            });
            contour.loops.push_back(std::move(drawn));
        }
        drawing.contours.push_back(std::move(contour));
    }
    return drawing;
}

} // namespace snaxels
