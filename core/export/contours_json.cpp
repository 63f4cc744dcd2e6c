#include "snaxels/export/contours_json.h"

namespace snaxels {
namespace {

nlohmann::json stats_json(const ContourStats& s) {
    return {{"seeds", s.seeds},     {"iterations", s.iterations}, {"fanouts", s.fanouts},
            {"merges", s.merges},   {"splits", s.splits},         {"ms", s.ms}};
}

} // namespace

nlohmann::json contours_to_json(const MeshReport& mesh, const Camera& camera, const Light& light,
                                const Drawing& drawing, const std::vector<ContourResult>& results,
                                const std::vector<MapRegion>* regions) {
    nlohmann::json doc;
    doc["mesh"] = {{"source", mesh.source},
                   {"vertices", mesh.vertices},
                   {"faces", mesh.faces},
                   {"split_vertices", mesh.split_vertices}};
    doc["camera"] = to_json(camera);
    doc["light"] = to_json(light);
    doc["image"] = {{"width", drawing.width}, {"height", drawing.height}};
    const bool parts = names_parts(drawing);
    if (parts) {
        nlohmann::json objects = nlohmann::json::array(), materials = nlohmann::json::array();
        for (const SceneObject& o : drawing.parts->objects) objects.push_back({{"name", o.name}, {"path", o.path}});
        for (const SceneMaterial& m : drawing.parts->materials)
            materials.push_back({{"name", m.name}, {"colour", {m.colour.r, m.colour.g, m.colour.b}}, {"opacity", m.colour.a}});
        doc["parts"] = {{"objects", std::move(objects)}, {"materials", std::move(materials)}};
    }
    ContourStats total;
    nlohmann::json contours = nlohmann::json::array();
    for (std::size_t i = 0; i < drawing.contours.size(); ++i) {
        const DrawnContour& c = drawing.contours[i];
        const ContourResult& r = results[i];
        nlohmann::json loops = nlohmann::json::array();
        for (const DrawnLoop& loop : c.loops) {
            nlohmann::json snaxels = nlohmann::json::array();
            for (std::size_t k = 0; k < loop.p.size(); ++k) {
                nlohmann::json s = {{"p", {loop.p[k].x, loop.p[k].y, loop.p[k].z}},
                                    {"q", {loop.q[k].x, loop.q[k].y}}};
                // Without visibility a QI is known only where a part is
                // left out (-1): a drawn snaxel's would claim it is seen.
                if (!loop.qi.empty() && (drawing.hidden_lines || loop.qi[k] < 0)) s["qi"] = loop.qi[k];
                snaxels.push_back(std::move(s));
            }
            nlohmann::json l = {{"closed", loop.closed}, {"snaxels", std::move(snaxels)}};
            if (parts) {
                nlohmann::json objects = nlohmann::json::array(), materials = nlohmann::json::array();
                for (const std::uint32_t o : loop.objects)
                    objects.push_back(o < drawing.parts->objects.size() ? drawing.parts->objects[o].path : "");
                for (const std::uint32_t m : loop.materials)
                    materials.push_back(m < drawing.parts->materials.size() ? drawing.parts->materials[m].name : "");
                l["objects"] = std::move(objects);
                l["materials"] = std::move(materials);
            }
            loops.push_back(std::move(l));
        }
        std::size_t positive = 0;
        for (const Region& region : r.regions) positive += region.sign > 0;
        nlohmann::json contour = {{"kind", c.spec.kind_name()},
                                  {"k", c.spec.k},
                                  {"loops", std::move(loops)},
                                  {"regions", {{"positive", positive}, {"negative", r.regions.size() - positive}}},
                                  {"stats", stats_json(r.stats)}};
        if (c.spec.kind == ContourKind::Suggestive)
            contour["test"] = c.spec.test == SuggestiveTest::Rtsc ? "rtsc" : "derivative";
        if (!c.spec.parts.objects.empty()) contour["object"] = c.spec.parts.objects;
        if (!c.spec.parts.materials.empty()) contour["material"] = c.spec.parts.materials;
        if (c.spec.parts.over_objects) contour["over"] = "objects";
        contours.push_back(std::move(contour));
        total.seeds += r.stats.seeds;
        total.iterations += r.stats.iterations;
        total.fanouts += r.stats.fanouts;
        total.merges += r.stats.merges;
        total.splits += r.stats.splits;
        total.ms += r.stats.ms;
    }
    doc["contours"] = std::move(contours);
    if (regions) {
        nlohmann::json list = nlohmann::json::array();
        for (const MapRegion& r : *regions) {
            nlohmann::json polygons = nlohmann::json::array();
            for (const auto& poly : r.polygons) {
                nlohmann::json points = nlohmann::json::array();
                for (const glm::dvec2& p : poly) points.push_back({p.x, p.y});
                polygons.push_back(std::move(points));
            }
            nlohmann::json region = {{"class", region_class_name(r.cls)},
                                     {"k", r.k},
                                     {"depth", r.depth},
                                     {"visible", true},
                                     {"area", r.area},
                                     {"polygons", std::move(polygons)}};
            if (parts && r.object >= 0 && r.material >= 0) {
                region["object"] = drawing.parts->objects[std::uint32_t(r.object)].path;
                region["material"] = drawing.parts->materials[std::uint32_t(r.material)].name;
            }
            list.push_back(std::move(region));
        }
        doc["regions"] = std::move(list);
    }
    doc["stats"] = stats_json(total);
    return doc;
}

} // namespace snaxels
