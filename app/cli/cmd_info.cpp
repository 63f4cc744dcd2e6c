#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/refine.h"

namespace snaxels::cli {

int run_info(const std::vector<std::string>& argv) {
    Args args("info", "info MESH [--json]",
              std::string("Reads MESH, welds and repairs it as the engine sees it, and prints a "
                          "report:\nvertices, faces, edges, boundary and non-manifold edges of the "
                          "input, vertices\nsplit and faces dropped by the repair, connected "
                          "components and bounding box,\nhow far the engine refines it (--refine auto), and "
                          "the file's cameras\n(for --camera).\n\n") +
                  kMeshArgumentHelp,
              {{"json", "", "print one JSON object instead of text"}}, {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    const LoadedMesh loaded = load_mesh(args.positional()[0]);
    // Faces per object and per material (the engine's faces: after repair).
    std::vector<std::size_t> object_faces(loaded.objects.size()), material_faces(loaded.materials.size());
    for (const std::uint32_t o : loaded.face_object) ++object_faces[o];
    for (const std::uint32_t m : loaded.face_material) ++material_faces[m];
    const std::vector<FileCamera> cameras =
        may_hold_cameras(args.positional()[0]) ? file_cameras(args.positional()[0]) : std::vector<FileCamera>{};
    // What the engine works on by default (--refine auto): docs/engine.md.
    const int levels = refine_levels(loaded.report.faces, kAutoRefine);
    const std::size_t engine_faces = loaded.report.faces * (std::size_t(1) << (2 * levels));
    if (args.flag("json")) {
        nlohmann::json doc = to_json(loaded.report);
        doc["engine"] = {{"refine_levels", levels}, {"faces", engine_faces}};
        nlohmann::json list = nlohmann::json::array();
        for (const FileCamera& c : cameras) {
            nlohmann::json j = {{"name", c.name}, {"projection", c.orthographic ? "orthographic" : "perspective"}};
            if (c.orthographic) j["height"] = c.ortho_height;
            else j["fov_deg"] = c.fov_deg;
            j["aspect"] = c.aspect > 0.0 ? nlohmann::json(c.aspect) : nlohmann::json(nullptr);
            j["clip"] = c.animated() ? nlohmann::json(c.clip) : nlohmann::json(nullptr);
            if (c.animated()) j["seconds"] = c.clip_seconds;
            list.push_back(std::move(j));
        }
        doc["cameras"] = std::move(list);
        nlohmann::json objects = nlohmann::json::array(), materials = nlohmann::json::array();
        for (std::size_t i = 0; i < loaded.objects.size(); ++i)
            objects.push_back({{"name", loaded.objects[i].name}, {"path", loaded.objects[i].path}, {"faces", object_faces[i]}});
        for (std::size_t i = 0; i < loaded.materials.size(); ++i) {
            const glm::dvec4& c = loaded.materials[i].colour;
            materials.push_back({{"name", loaded.materials[i].name},
                                 {"colour", {c.r, c.g, c.b}},
                                 {"opacity", c.a},
                                 {"faces", material_faces[i]}});
        }
        doc["objects"] = std::move(objects);
        doc["materials"] = std::move(materials);
        std::cout << doc.dump(2) << '\n';
    } else {
        std::cout << to_text(loaded.report);
        if (levels > 0)
            std::cout << "refined for contours: " << levels << (levels == 1 ? " level, " : " levels, ") << engine_faces
                      << " faces\n";
        for (std::size_t i = 0; i < loaded.objects.size(); ++i)
            std::cout << "object \"" << loaded.objects[i].path << "\": " << object_faces[i] << " faces\n";
        for (std::size_t i = 0; i < loaded.materials.size(); ++i) {
            const glm::dvec4& c = loaded.materials[i].colour;
            std::cout << "material \"" << loaded.materials[i].name << "\": " << material_faces[i] << " faces, colour "
                      << c.r << ' ' << c.g << ' ' << c.b;
            if (c.a < 1.0) std::cout << ", opacity " << c.a;
            std::cout << '\n';
        }
        for (const FileCamera& c : cameras) {
            std::cout << "camera \"" << c.name << "\": ";
            if (c.orthographic) std::cout << "orthographic, " << c.ortho_height << " units high";
            else std::cout << "perspective, " << c.fov_deg << " degrees vertical field of view";
            if (c.aspect > 0.0) std::cout << ", aspect " << c.aspect;
            if (c.animated()) std::cout << ", moved by clip \"" << c.clip << "\" (" << c.clip_seconds << " s)";
            std::cout << '\n';
        }
    }
    return 0;
}

} // namespace snaxels::cli
