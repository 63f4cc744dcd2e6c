#include "snaxels/export/drawing.h"

namespace snaxels {

bool has_hidden_lines(const Drawing& drawing) {
    if (drawing.hidden_lines) return true;
    for (const DrawnContour& c : drawing.contours)
        for (const DrawnLoop& loop : c.loops)
            for (const int qi : loop.qi)
                if (qi > 0) return true;
    return false;
}

Drawing make_drawing(const SnaxelEngine& engine, const std::vector<ContourResult>& results,
                     const ImageProjection& projection,
                     const std::vector<ContourVisibility>* visibility) {
    Drawing drawing;
    drawing.width = projection.width();
    drawing.height = projection.height();
    drawing.hidden_lines = visibility != nullptr;
    for (std::size_t c = 0; c < results.size(); ++c) {
        const ContourResult& r = results[c];
        const ContourVisibility parts = visibility ? ContourVisibility{} : drawn_parts(engine, r);
        const ContourVisibility* cut = visibility ? &(*visibility)[c] : parts.loops.empty() ? nullptr : &parts;
        DrawnContour contour;
        contour.spec = r.spec;
        for (std::size_t l = 0; l < r.fronts.loops.size(); ++l) {
            const FrontLoop& loop = r.fronts.loops[l];
            DrawnLoop drawn;
            drawn.closed = loop.closed;
            drawn.p.reserve(loop.size);
            drawn.q.reserve(loop.size);
            r.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                const glm::dvec3 p = engine.position(r.fronts.snaxels[s]);
                drawn.p.push_back(p);
                drawn.q.push_back(projection.project(p));
            });
            if (cut) {
                const LoopVisibility& lv = cut->loops[l];
                drawn.qi = lv.snaxel_qi;
                drawn.change_before.reserve(lv.change_before.size());
                for (const glm::dvec3& point : lv.change_before)
                    drawn.change_before.push_back(projection.project(point));
                for (const VisibilityRun& run : lv.runs) {
                    DrawnRun dr{run.qi, run.closed, {}};
                    dr.q.reserve(run.points.size());
                    for (const glm::dvec3& p : run.points) dr.q.push_back(projection.project(p));
                    drawn.runs.push_back(std::move(dr));
                }
            }
            contour.loops.push_back(std::move(drawn));
        }
        drawing.contours.push_back(std::move(contour));
    }
    return drawing;
}

} // namespace snaxels
