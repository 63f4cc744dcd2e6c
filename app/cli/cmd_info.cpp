#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/mesh/refine.h"

namespace snaxels::cli {

namespace {

/// What info reports beside the mesh's own report.
struct InfoFacts {
    std::vector<std::size_t> object_faces, material_faces; ///< the engine's faces (after repair)
    std::vector<FileCamera> cameras;
    std::vector<AnimationClipInfo> clips;
    int levels = 0;              ///< how far --refine auto refines it (docs/engine.md)
    std::size_t engine_faces = 0;
};

void print_json(const LoadedMesh& loaded, const InfoFacts& f) {
    nlohmann::json doc = to_json(loaded.report);
    doc["engine"] = {{"refine_levels", f.levels}, {"faces", f.engine_faces}};
    nlohmann::json list = nlohmann::json::array();
    for (const FileCamera& c : f.cameras) {
        nlohmann::json j = {{"name", c.name}, {"projection", c.orthographic ? "orthographic" : "perspective"}};
        if (c.orthographic) j["height"] = c.ortho_height;
        else j["fov_deg"] = c.fov_deg;
        j["aspect"] = c.aspect > 0.0 ? nlohmann::json(c.aspect) : nlohmann::json(nullptr);
        j["clip"] = c.animated() ? nlohmann::json(c.clip) : nlohmann::json(nullptr);
        if (c.animated()) j["seconds"] = c.clip_seconds;
        list.push_back(std::move(j));
    }
    doc["cameras"] = std::move(list);
    nlohmann::json clips = nlohmann::json::array();
    for (const AnimationClipInfo& c : f.clips) clips.push_back({{"name", c.name}, {"seconds", c.duration}});
    doc["clips"] = std::move(clips);
    nlohmann::json objects = nlohmann::json::array(), materials = nlohmann::json::array();
    for (std::size_t i = 0; i < loaded.objects.size(); ++i)
        objects.push_back({{"name", loaded.objects[i].name}, {"path", loaded.objects[i].path}, {"faces", f.object_faces[i]}});
    for (std::size_t i = 0; i < loaded.materials.size(); ++i) {
        const glm::dvec4& c = loaded.materials[i].colour;
        materials.push_back({{"name", loaded.materials[i].name},
                             {"colour", {c.r, c.g, c.b}},
                             {"opacity", c.a},
                             {"faces", f.material_faces[i]}});
    }
    doc["objects"] = std::move(objects);
    doc["materials"] = std::move(materials);
    std::cout << doc.dump(2) << '\n';
}

void print_text(const LoadedMesh& loaded, const InfoFacts& f) {
    std::cout << to_text(loaded.report);
    if (f.levels > 0)
        std::cout << "refined for contours: " << f.levels << (f.levels == 1 ? " level, " : " levels, ") << f.engine_faces
                  << " faces\n";
    for (std::size_t i = 0; i < loaded.objects.size(); ++i)
        std::cout << "object \"" << loaded.objects[i].path << "\": " << f.object_faces[i] << " faces\n";
    for (std::size_t i = 0; i < loaded.materials.size(); ++i) {
        const glm::dvec4& c = loaded.materials[i].colour;
        std::cout << "material \"" << loaded.materials[i].name << "\": " << f.material_faces[i] << " faces, colour "
                  << c.r << ' ' << c.g << ' ' << c.b;
        if (c.a < 1.0) std::cout << ", opacity " << c.a;
        std::cout << '\n';
    }
    for (const FileCamera& c : f.cameras) {
        std::cout << "camera \"" << c.name << "\": ";
        if (c.orthographic) std::cout << "orthographic, " << c.ortho_height << " units high";
        else std::cout << "perspective, " << c.fov_deg << " degrees vertical field of view";
        if (c.aspect > 0.0) std::cout << ", aspect " << c.aspect;
        if (c.animated()) std::cout << ", moved by clip \"" << c.clip << "\" (" << c.clip_seconds << " s)";
        std::cout << '\n';
    }
    for (std::size_t i = 0; i < f.clips.size(); ++i)
        std::cout << "clip " << i << " \"" << f.clips[i].name << "\": " << f.clips[i].duration << " s\n";
}

} // namespace

int run_info(const std::vector<std::string>& argv) {
    Args args("info", "info MESH [--json]",
              std::string("Reads MESH, welds and repairs it as the engine sees it, and prints a "
                          "report:\nvertices, faces, edges, boundary and non-manifold edges of the "
                          "input, vertices\nsplit and faces dropped by the repair, connected "
                          "components and bounding box,\nhow far the engine refines it (--refine auto), "
                          "the file's cameras\n(for --camera) and its animation clips (for --clip, by name or "
                          "number).\n\n") +
                  kMeshArgumentHelp,
              {{"json", "", "print one JSON object instead of text"}}, {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    const std::string& path = args.positional()[0];
    const LoadedMesh loaded = load_mesh(path);
    InfoFacts f;
    f.object_faces.assign(loaded.objects.size(), 0);
    f.material_faces.assign(loaded.materials.size(), 0);
    for (const std::uint32_t o : loaded.face_object) ++f.object_faces[o];
    for (const std::uint32_t m : loaded.face_material) ++f.material_faces[m];
    if (may_hold_cameras(path)) { // the formats that hold cameras hold clips; OBJ, PLY, STL and OFF hold neither
        f.cameras = file_cameras(path);
        f.clips = animation_clips(path);
    }
    f.levels = refine_levels(loaded.report.faces, kAutoRefine);
    f.engine_faces = loaded.report.faces * (std::size_t(1) << (2 * f.levels));
    if (args.flag("json")) print_json(loaded, f);
    else print_text(loaded, f);
    return 0;
}

} // namespace snaxels::cli
