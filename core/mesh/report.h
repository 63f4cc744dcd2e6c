#pragma once
/// What import and repair found out about a mesh.

#include <cstddef>
#include <string>

#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

namespace snaxels {

struct MeshReport {
    std::string source;              ///< file path or procedural description
    std::size_t vertices = 0;        ///< welded, referenced input vertices (the mesh has
                                     ///< vertices + split_vertices after repair)
    std::size_t faces = 0;           ///< of the repaired mesh
    std::size_t edges = 0;           ///< distinct undirected edges of the input, before repair
    std::size_t boundary_edges = 0;  ///< input edges with exactly one face
    std::size_t nonmanifold_edges = 0; ///< input edges with three or more faces
    std::size_t split_vertices = 0;  ///< vertex copies made so that every face could be added
    std::size_t dropped_faces = 0;   ///< degenerate (zero-area) faces removed
    std::size_t components = 0;      ///< connected components of the repaired mesh
    std::size_t flipped_components = 0; ///< closed components turned outward (they faced inward)
    glm::dvec3 bbox_min{0.0};
    glm::dvec3 bbox_max{0.0};

    /// The middle of the bounding box: what turntables and light orbits turn about.
    glm::dvec3 centre() const { return 0.5 * (bbox_min + bbox_max); }
};

/// The report as one JSON object (keys as documented in docs/cli.md).
nlohmann::json to_json(const MeshReport& report);

/// The report as aligned, human-readable lines.
std::string to_text(const MeshReport& report);

} // namespace snaxels
