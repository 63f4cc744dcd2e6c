#include "snaxels/mesh/report.h"

#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

namespace snaxels {

nlohmann::json to_json(const MeshReport& r) {
    return {
        {"source", r.source},
        {"vertices", r.vertices},
        {"faces", r.faces},
        {"edges", r.edges},
        {"boundary_edges", r.boundary_edges},
        {"nonmanifold_edges", r.nonmanifold_edges},
        {"split_vertices", r.split_vertices},
        {"dropped_faces", r.dropped_faces},
        {"components", r.components},
        {"flipped_components", r.flipped_components},
        {"bbox",
         {{"min", {r.bbox_min.x, r.bbox_min.y, r.bbox_min.z}},
          {"max", {r.bbox_max.x, r.bbox_max.y, r.bbox_max.z}}}},
    };
}

std::string to_text(const MeshReport& r) {
    std::ostringstream out;
    char bbox[256];
    std::snprintf(bbox, sizeof bbox, "(%g, %g, %g) .. (%g, %g, %g)", r.bbox_min.x, r.bbox_min.y,
                  r.bbox_min.z, r.bbox_max.x, r.bbox_max.y, r.bbox_max.z);
    out << "source:            " << r.source << '\n'
        << "vertices:          " << r.vertices << '\n'
        << "faces:             " << r.faces << '\n'
        << "edges:             " << r.edges << '\n'
        << "boundary edges:    " << r.boundary_edges << '\n'
        << "non-manifold edges:" << ' ' << r.nonmanifold_edges << '\n'
        << "split vertices:    " << r.split_vertices << '\n'
        << "dropped faces:     " << r.dropped_faces << '\n'
        << "components:        " << r.components << '\n'
        << "turned outward:    " << r.flipped_components << '\n'
        << "bounding box:      " << bbox << '\n';
    return out.str();
}

} // namespace snaxels
