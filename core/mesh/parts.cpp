#include "snaxels/mesh/parts.h"

#include <algorithm>
#include <array>
#include <cctype>

#include "snaxels/error.h"

#include "snaxels/mesh/build.h"

namespace snaxels {

namespace {

char lower(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }

bool excluding(const std::string& pattern) { return !pattern.empty() && pattern[0] == '!'; }

/// Whether @p patterns pass a thing known by @p names (any of them may match).
template <class Names> bool passes(const std::vector<std::string>& patterns, const Names& names) {
    bool any_including = false, included = false;
    for (const std::string& p : patterns) {
        const bool ex = excluding(p);
        const std::string glob = ex ? p.substr(1) : p;
        bool hit = false;
        for (const std::string& name : names) hit = hit || glob_match(glob, name);
        if (ex && hit) return false;
        if (!ex) any_including = true, included = included || hit;
    }
    return !any_including || included;
}

std::string joined(const std::vector<std::string>& list) {
    std::string out;
    for (std::size_t i = 0; i < list.size(); ++i) out += (i ? "," : "") + list[i];
    return out;
}

} // namespace

std::shared_ptr<const FaceParts> loaded_parts(const LoadedMesh& mesh) {
    if (mesh.face_object.size() != mesh.mesh.n_faces() || mesh.face_material.size() != mesh.mesh.n_faces()) return nullptr;
    auto parts = std::make_shared<FaceParts>();
    parts->objects = mesh.objects;
    parts->materials = mesh.materials;
    parts->object.values().reserve(mesh.face_object.size());
    parts->material.values().reserve(mesh.face_material.size());
    for (const std::uint32_t o : mesh.face_object) parts->object.push_back(o);
    for (const std::uint32_t m : mesh.face_material) parts->material.push_back(m);
    return parts;
}

std::string PartSelector::text() const {
    std::string out;
    if (!objects.empty()) out += "object=" + joined(objects);
    if (!materials.empty()) out += std::string(out.empty() ? "" : " ") + "material=" + joined(materials);
    if (over_objects) out += std::string(out.empty() ? "" : " ") + "over=objects";
    return out;
}

bool glob_match(const std::string& pattern, const std::string& text) {
    // Iterative matching with one backtrack point (the last `*`).
    std::size_t p = 0, t = 0, star = std::string::npos, resume = 0;
    while (t < text.size()) {
        if (p < pattern.size() && (pattern[p] == '?' || lower(pattern[p]) == lower(text[t]))) {
            ++p, ++t;
        } else if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = t;
        } else if (star != std::string::npos) {
            p = star + 1;
            t = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

std::vector<std::string> split_patterns(const std::string& value) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= value.size()) {
        std::size_t end = value.find(',', start);
        if (end == std::string::npos) end = value.size();
        std::size_t a = start, b = end;
        while (a < b && std::isspace(static_cast<unsigned char>(value[a]))) ++a;
        while (b > a && std::isspace(static_cast<unsigned char>(value[b - 1]))) --b;
        if (b > a) out.push_back(value.substr(a, b - a));
        start = end + 1;
    }
    return out;
}

PartMatcher::PartMatcher(const PartSelector& selector, const FaceParts* parts) : parts_(parts) {
    if (!parts || selector.empty() || parts->object.empty()) return;
    all_ = false;
    objects_.reserve(parts->objects.size());
    for (const SceneObject& o : parts->objects)
        objects_.push_back(passes(selector.objects, std::vector<std::string>{o.name, o.path}));
    materials_.reserve(parts->materials.size());
    for (const SceneMaterial& m : parts->materials)
        materials_.push_back(passes(selector.materials, std::vector<std::string>{m.name}));
    // Faces may name a part past the lists (a file's default): not selected
    // unless every list is empty, as a face of no named part.
    if (objects_.empty()) objects_.push_back(selector.objects.empty());
    if (materials_.empty()) materials_.push_back(selector.materials.empty());
}

std::optional<LoadedMesh> without_objects(const LoadedMesh& loaded, const std::vector<std::string>& patterns) {
    const Mesh& mesh = loaded.mesh;
    if (patterns.empty() || loaded.face_object.size() != mesh.n_faces()) return std::nullopt;
    PartSelector selector;
    selector.objects = patterns;
    std::vector<std::uint8_t> hidden_object(loaded.objects.size(), 0);
    for (std::size_t o = 0; o < loaded.objects.size(); ++o)
        hidden_object[o] = passes(selector.objects, std::vector<std::string>{loaded.objects[o].name, loaded.objects[o].path});
    std::vector<std::uint8_t> keep_face(mesh.n_faces(), 1);
    std::size_t kept = 0;
    for (std::size_t f = 0; f < keep_face.size(); ++f) {
        const std::uint32_t o = loaded.face_object[f];
        keep_face[f] = !(o < hidden_object.size() && hidden_object[o]);
        kept += keep_face[f];
    }
    if (kept == mesh.n_faces()) return std::nullopt;
    if (kept == 0) throw Error("every object of the scene is hidden: nothing is left to draw");
    std::vector<std::int64_t> new_vertex(mesh.n_vertices(), -1);
    for (const auto fh : mesh.faces())
        if (keep_face[slot(fh)])
            for (const auto vh : mesh.fv_range(fh)) new_vertex[slot(vh)] = 0;
    LoadedMesh out;
    out.report = loaded.report;
    out.objects = loaded.objects;
    out.materials = loaded.materials;
    Mesh& m = out.mesh;
    std::vector<Mesh::VertexHandle> handle(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) {
        if (new_vertex[slot(vh)] < 0) continue;
        handle[slot(vh)] = m.add_vertex(mesh.point(vh));
        m.set_normal(handle[slot(vh)], mesh.normal(vh));
        if (!loaded.vertex_source.empty()) out.vertex_source.push_back(loaded.vertex_source[slot(vh)]);
    }
    for (const auto fh : mesh.faces()) {
        const std::size_t f = slot(fh);
        if (!keep_face[f]) continue;
        std::array<Mesh::VertexHandle, 3> c;
        auto corner = c.begin();
        for (const auto vh : mesh.fv_range(fh)) *corner++ = handle[slot(vh)];
        // The faces were a manifold mesh's: a subset of them adds as they are.
        const auto added = m.add_face(c[0], c[1], c[2]);
        if (!added.is_valid()) throw InternalError("without_objects: a kept face was refused");
        out.face_object.push_back(loaded.face_object[f]);
        out.face_material.push_back(loaded.face_material[f]);
        if (!loaded.corner_normals.empty()) {
            // The corners' normals in the new face's own order of its vertices.
            std::array<glm::dvec3, 3> normals{};
            std::size_t k = 0;
            for (const auto vh : m.fv_range(added)) {
                for (std::size_t at = 0; at < 3; ++at)
                    if (c[at] == vh) normals[k] = loaded.corner_normals[f][at];
                ++k;
            }
            out.corner_normals.push_back(normals);
        }
    }
    return out;
}

std::vector<std::string> unmatched_patterns(const PartSelector& selector, const FaceParts& parts) {
    std::vector<std::string> out;
    auto check = [&](const std::vector<std::string>& patterns, const char* what, auto&& names_of, std::size_t n) {
        std::string have;
        for (std::size_t i = 0; i < n; ++i) have += (i ? ", " : "") + names_of(i).front();
        for (const std::string& p : patterns) {
            const std::string glob = excluding(p) ? p.substr(1) : p;
            bool hit = false;
            for (std::size_t i = 0; i < n && !hit; ++i)
                for (const std::string& name : names_of(i)) hit = hit || glob_match(glob, name);
            if (!hit)
                out.push_back(std::string(what) + " \"" + glob + "\" matches none of the scene's " + what + "s (" +
                              (have.empty() ? "none" : have) + ")");
        }
    };
    check(selector.objects, "object",
          [&](std::size_t i) { return std::vector<std::string>{parts.objects[i].name, parts.objects[i].path}; },
          parts.objects.size());
    check(selector.materials, "material", [&](std::size_t i) { return std::vector<std::string>{parts.materials[i].name}; },
          parts.materials.size());
    return out;
}

} // namespace snaxels
