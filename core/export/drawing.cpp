#include "snaxels/export/drawing.h"

#include <algorithm>

#include "snaxels/snaxel/feature_edges.h"

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
    const MeshTopology& topo = engine.topology();
    drawing.parts = topo.connectivity()->parts;
    const bool several = drawing.parts && drawing.parts->several();
    for (std::size_t c = 0; c < results.size(); ++c) {
        const ContourResult& r = results[c];
        const ContourVisibility runs = visibility ? ContourVisibility{} : drawn_parts(engine, r, &projection.camera());
        const ContourVisibility* cut = visibility ? &(*visibility)[c] : runs.loops.empty() ? nullptr : &runs;
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
                    DrawnRun dr{run.qi, run.closed, {}, run.first, run.from_change};
                    dr.q.reserve(run.points.size());
                    for (const glm::dvec3& p : run.points) dr.q.push_back(projection.project(p));
                    drawn.runs.push_back(std::move(dr));
                }
            }
            if (several) {
                const FaceParts& parts = *drawing.parts;
                const bool along_edges = r.spec.along_edges();
                std::vector<std::uint32_t> count(parts.objects.size() + 1, 0);
                auto on_face = [&](FaceId f) {
                    drawn.objects.push_back(parts.object[f]);
                    drawn.materials.push_back(parts.material[f]);
                    ++count[std::min<std::size_t>(parts.object[f], parts.objects.size())];
                };
                r.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                    const EdgeId e = r.fronts.snaxels[s].edge;
                    for (const FaceId f : along_edges ? faces_beside(topo, e) : topo.edge_faces()[e])
                        if (f.valid()) on_face(f);
                    // An intersection line lies on the surface it pierces too.
                    if (s < std::int32_t(r.snaxel_pierced.size()) && r.snaxel_pierced[s].valid()) on_face(r.snaxel_pierced[s]);
                });
                const auto most = std::max_element(count.begin(), count.end() - 1);
                if (most != count.end() - 1 && *most > 0) drawn.object = std::int32_t(most - count.begin());
                for (auto* list : {&drawn.objects, &drawn.materials}) {
                    std::sort(list->begin(), list->end());
                    list->erase(std::unique(list->begin(), list->end()), list->end());
                }
            }
            contour.loops.push_back(std::move(drawn));
        }
        drawing.contours.push_back(std::move(contour));
    }
    return drawing;
}

} // namespace snaxels
