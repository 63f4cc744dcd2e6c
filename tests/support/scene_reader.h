#pragma once
// Readers of scene files written for the tests alone, so that oracles of
// hard-surface drawings see the file as its format defines it and not as
// the product's importer (Assimp) reads it: glTF 1.0 (JSON with a binary
// buffer; node matrices or translation, rotation and scale; instanced
// meshes) and a subset of Collada 1.4 (<triangles> of one geometry per
// node with translate, rotate and scale, and the file's up axis). Each gives
// the triangles in world space, positions welded where equal, with the
// file's normal at every corner of every face. It includes nothing from core/.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

namespace snaxels::ref {

/// Triangles with the file's own normal at each corner.
struct SceneMesh {
    std::vector<glm::dvec3> positions;               ///< welded by exact position
    std::vector<std::array<int, 3>> faces;           ///< counter-clockwise seen from outside
    std::vector<std::array<glm::dvec3, 3>> normals;  ///< per face, per corner (unit)
    /// Per face: the name of its node (glTF: the node's name, else its id;
    /// Collada: the node's name) and of its material (glTF 1.0: its id;
    /// Collada: the material's name, else its id).
    std::vector<std::string> face_object, face_material;
};

namespace scene_detail {

inline void add_triangle(SceneMesh& m, std::map<std::array<double, 3>, int>& index, const glm::dmat4& xf,
                         const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
                         const std::string& object = "", const std::string& material = "") {
    const glm::dmat3 normal_xf = glm::transpose(glm::inverse(glm::dmat3(xf)));
    std::array<int, 3> f{};
    std::array<glm::dvec3, 3> fn{};
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 w = glm::dvec3(xf * glm::dvec4(p[std::size_t(k)], 1.0));
        const auto [it, fresh] = index.emplace(std::array<double, 3>{w.x + 0.0, w.y + 0.0, w.z + 0.0}, int(m.positions.size()));
        if (fresh) m.positions.push_back(w);
        f[std::size_t(k)] = it->second;
        const glm::dvec3 turned = normal_xf * n[std::size_t(k)];
        fn[std::size_t(k)] = glm::length(turned) > 0.0 ? glm::normalize(turned) : glm::dvec3(0.0);
    }
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) return;
    m.faces.push_back(f);
    m.normals.push_back(fn);
    m.face_object.push_back(object);
    m.face_material.push_back(material);
}

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace scene_detail

namespace scene_detail {

/// A glTF entry by its key: an id (glTF 1.0 dictionaries) or an index (2.0 arrays).
inline const nlohmann::json& item(const nlohmann::json& table, const nlohmann::json& key) {
    return key.is_string() ? table.at(key.get<std::string>()) : table.at(key.get<std::size_t>());
}

/// The values of glTF accessor @p a of file @p g, whose buffers' bytes
/// @p buffer gives by the buffer view's key.
template <class Buffer> std::vector<double> accessor_values(const nlohmann::json& g, const nlohmann::json& a, Buffer&& buffer) {
    const nlohmann::json& view = item(g.at("bufferViews"), a.at("bufferView"));
    const std::string& data = buffer(view.at("buffer"));
    const std::size_t start = view.value("byteOffset", std::size_t(0)) + a.value("byteOffset", std::size_t(0));
    const std::string type = a.at("type");
    const int width = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
    const int component = a.at("componentType");
    const std::size_t size = component == 5126 || component == 5125 ? 4 : component == 5123 || component == 5122 ? 2 : 1;
    std::size_t stride = a.value("byteStride", view.value("byteStride", std::size_t(0))); // 1.0: the accessor's; 2.0: the view's
    if (stride == 0) stride = size * std::size_t(width);
    std::vector<double> out;
    const std::size_t count = a.at("count");
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < width; ++c) {
            const char* at = data.data() + start + i * stride + std::size_t(c) * size;
            if (start + i * stride + std::size_t(c + 1) * size > data.size()) throw std::runtime_error("accessor past its buffer");
            double v = 0.0;
            if (component == 5126) { float f; std::memcpy(&f, at, 4); v = f; }
            else if (component == 5125) { std::uint32_t u; std::memcpy(&u, at, 4); v = u; }
            else if (component == 5123) { std::uint16_t u; std::memcpy(&u, at, 2); v = u; }
            else if (component == 5122) { std::int16_t u; std::memcpy(&u, at, 2); v = u; }
            else v = static_cast<unsigned char>(*at);
            out.push_back(v);
        }
    return out;
}

/// A translation, a rotation (x, y, z, w) and a scale as one matrix.
inline glm::dmat4 trs(const std::vector<double>& t, const std::vector<double>& q, const std::vector<double>& s) {
    const glm::dmat4 rotation = glm::mat4_cast(glm::dquat(q[3], q[0], q[1], q[2]));
    glm::dmat4 translation(1.0), scale(1.0);
    translation[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
    scale[0][0] = s[0], scale[1][1] = s[1], scale[2][2] = s[2];
    return translation * rotation * scale;
}

/// A glTF node's own transform: its matrix (column-major), else its TRS.
inline glm::dmat4 node_matrix(const nlohmann::json& node) {
    if (node.contains("matrix")) {
        glm::dmat4 local(1.0);
        const auto v = node.at("matrix").get<std::vector<double>>();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) local[c][r] = v[std::size_t(4 * c + r)]; // column-major, as glm
        return local;
    }
    return trs(node.value("translation", std::vector<double>{0, 0, 0}), node.value("rotation", std::vector<double>{0, 0, 0, 1}),
               node.value("scale", std::vector<double>{1, 1, 1}));
}

/// A glTF file's scene (1.0: "scene" names it; 2.0: its index, default 0),
/// every node's triangle-list primitives in world space. @p meshes_of
/// gives a node's mesh keys, @p material_name a primitive's material.
template <class MeshesOf, class MaterialName>
SceneMesh read_gltf(const std::string& path, MeshesOf&& meshes_of, MaterialName&& material_name) {
    using nlohmann::json;
    const json g = json::parse(slurp(path));
    const std::string dir = path.substr(0, path.find_last_of('/') + 1);
    std::map<std::string, std::string> buffers;
    auto buffer = [&](const json& key) -> const std::string& {
        const std::string id = key.dump();
        auto it = buffers.find(id);
        if (it == buffers.end()) it = buffers.emplace(id, slurp(dir + item(g.at("buffers"), key).at("uri").get<std::string>())).first;
        return it->second;
    };
    auto accessor = [&](const json& key) { return accessor_values(g, item(g.at("accessors"), key), buffer); };
    SceneMesh m;
    std::map<std::array<double, 3>, int> index;
    std::function<void(const json&, const glm::dmat4&)> visit = [&](const json& id, const glm::dmat4& parent) {
        const json& node = item(g.at("nodes"), id);
        const glm::dmat4 world = parent * node_matrix(node);
        const std::string object = node.value("name", id.is_string() ? id.get<std::string>() : id.dump());
        for (const json& mesh_id : meshes_of(node))
            for (const json& prim : item(g.at("meshes"), mesh_id).at("primitives")) {
                if (prim.value("mode", 4) != 4) continue;
                const std::string material = material_name(g, prim);
                const auto pos = accessor(prim.at("attributes").at("POSITION"));
                const auto nrm = accessor(prim.at("attributes").at("NORMAL"));
                const auto idx = accessor(prim.at("indices"));
                for (std::size_t i = 0; i + 2 < idx.size(); i += 3) {
                    std::array<glm::dvec3, 3> p, n;
                    for (std::size_t k = 0; k < 3; ++k) {
                        const auto v = std::size_t(idx[i + k]);
                        p[k] = {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]};
                        n[k] = {nrm[3 * v], nrm[3 * v + 1], nrm[3 * v + 2]};
                    }
                    add_triangle(m, index, world, p, n, object, material);
                }
            }
        for (const json& child : node.value("children", json::array())) visit(child, world);
    };
    const json& scene = item(g.at("scenes"), g.value("scene", json(0)));
    for (const json& id : scene.at("nodes")) visit(id, glm::dmat4(1.0));
    return m;
}

} // namespace scene_detail

/// A glTF 1.0 file (dictionaries of accessors, buffer views, buffers, meshes
/// and nodes by id; the scene named by "scene"); triangle lists only.
inline SceneMesh read_gltf1(const std::string& path) {
    return scene_detail::read_gltf(
        path, [](const nlohmann::json& node) { return node.value("meshes", nlohmann::json::array()); },
        // The file's identifier (Assimp names glTF 1.0 materials by it).
        [](const nlohmann::json&, const nlohmann::json& prim) { return prim.value("material", std::string()); });
}

/// A glTF 2.0 file (arrays; a node's one mesh; materials by their names);
/// triangle lists only.
inline SceneMesh read_gltf2(const std::string& path) {
    return scene_detail::read_gltf(
        path,
        [](const nlohmann::json& node) { return node.contains("mesh") ? nlohmann::json::array({node.at("mesh")}) : nlohmann::json::array(); },
        [](const nlohmann::json& g, const nlohmann::json& prim) {
            if (!prim.contains("material")) return std::string();
            const nlohmann::json& material = g.at("materials").at(prim.at("material").get<std::size_t>());
            return material.value("name", prim.at("material").dump());
        });
}

/// A glTF 2.0 camera as its file poses it at one time.
struct SceneCamera {
    glm::dvec3 eye, forward, up; ///< world space; unit forward and up
    double yfov = 0.0;           ///< radians
    double znear = 0.0;
    double aspect = 0.0; ///< width over height (0: not given)
};

/// The camera of root node @p name of glTF 2.0 file @p path at @p seconds:
/// its translation and rotation keys (LINEAR: interpolated, rotations by
/// slerp; STEP: held), else its own TRS. A glTF camera looks down its -Z
/// with +Y up.
inline SceneCamera read_gltf2_camera(const std::string& path, const std::string& name, double seconds) {
    using nlohmann::json;
    const json g = json::parse(scene_detail::slurp(path));
    const std::string dir = path.substr(0, path.find_last_of('/') + 1);
    std::map<std::size_t, std::string> buffers;
    auto buffer = [&](const json& key) -> const std::string& {
        const std::size_t b = key.get<std::size_t>();
        if (!buffers.count(b)) buffers[b] = scene_detail::slurp(dir + g.at("buffers").at(b).at("uri").get<std::string>());
        return buffers[b];
    };
    std::size_t node_index = g.at("nodes").size();
    for (std::size_t i = 0; i < g.at("nodes").size(); ++i)
        if (g.at("nodes")[i].value("name", "") == name && g.at("nodes")[i].contains("camera")) node_index = i;
    if (node_index == g.at("nodes").size()) throw std::runtime_error("no camera node " + name);
    const json& node = g.at("nodes")[node_index];
    std::vector<double> t = node.value("translation", std::vector<double>{0, 0, 0});
    std::vector<double> q = node.value("rotation", std::vector<double>{0, 0, 0, 1});
    for (const json& anim : g.value("animations", json::array()))
        for (const json& channel : anim.at("channels")) {
            if (channel.at("target").value("node", std::size_t(-1)) != node_index) continue;
            const std::string target = channel.at("target").at("path");
            if (target != "translation" && target != "rotation") continue;
            const json& sampler = anim.at("samplers").at(channel.at("sampler").get<std::size_t>());
            const auto times = scene_detail::accessor_values(g, g.at("accessors").at(sampler.at("input").get<std::size_t>()), buffer);
            const auto values = scene_detail::accessor_values(g, g.at("accessors").at(sampler.at("output").get<std::size_t>()), buffer);
            const std::size_t width = target == "rotation" ? 4 : 3;
            std::size_t k = 0;
            while (k + 1 < times.size() && times[k + 1] <= seconds) ++k;
            double w = 0.0;
            if (k + 1 < times.size() && seconds > times[k] && sampler.value("interpolation", "LINEAR") == "LINEAR")
                w = (seconds - times[k]) / (times[k + 1] - times[k]);
            std::vector<double> a(values.begin() + std::ptrdiff_t(k * width), values.begin() + std::ptrdiff_t((k + 1) * width));
            if (w > 0.0) {
                std::vector<double> b(values.begin() + std::ptrdiff_t((k + 1) * width), values.begin() + std::ptrdiff_t((k + 2) * width));
                if (width == 4) {
                    const glm::dquat s = glm::slerp(glm::dquat(a[3], a[0], a[1], a[2]), glm::dquat(b[3], b[0], b[1], b[2]), w);
                    a = {s.x, s.y, s.z, s.w};
                } else {
                    for (std::size_t c = 0; c < 3; ++c) a[c] += w * (b[c] - a[c]);
                }
            }
            (width == 4 ? q : t) = a;
        }
    const glm::dmat4 m = scene_detail::trs(t, q, {1, 1, 1});
    const json& perspective = g.at("cameras").at(node.at("camera").get<std::size_t>()).at("perspective");
    SceneCamera cam;
    cam.eye = glm::dvec3(m[3]);
    cam.forward = glm::normalize(-glm::dvec3(m[2]));
    cam.up = glm::normalize(glm::dvec3(m[1]));
    cam.yfov = perspective.at("yfov");
    cam.znear = perspective.value("znear", 0.0);
    cam.aspect = perspective.value("aspectRatio", 0.0);
    return cam;
}

/// A Collada 1.4 file: every node's <instance_geometry> with <triangles>
/// (VERTEX and NORMAL inputs), the node's translate, rotate (degrees) and
/// scale in order, the asset's unit of length in metres, and its up axis
/// turned to +Y (Z up: (x, y, z) becomes (x, z, -y)).
inline SceneMesh read_collada(const std::string& path) {
    pugi::xml_document doc;
    if (!doc.load_file(path.c_str())) throw std::runtime_error("cannot parse " + path);
    const pugi::xml_node root = doc.child("COLLADA");
    // Numbers as exporters write them, some (3ds Max's in some locales)
    // with a decimal comma: the format separates numbers by white space.
    auto numbers = [](const char* text) {
        std::vector<double> v;
        std::string dotted(text);
        std::replace(dotted.begin(), dotted.end(), ',', '.');
        std::istringstream s(dotted);
        double x;
        while (s >> x) v.push_back(x);
        return v;
    };
    auto strip = [](std::string id) { return id.empty() || id[0] != '#' ? id : id.substr(1); };
    auto by_id = [&](const pugi::xml_node& scope, const std::string& id) {
        return scope.find_node([&](const pugi::xml_node& n) { return id == n.attribute("id").value(); });
    };
    glm::dmat4 up(1.0);
    if (std::string(root.child("asset").child_value("up_axis")) == "Z_UP") {
        up = glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, -1, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 0, 1));
    }
    // Lengths in metres, as the format's <unit meter="..."> says.
    if (const pugi::xml_attribute unit = root.child("asset").child("unit").attribute("meter"))
        if (const auto metres = numbers(unit.value()); metres.size() == 1) up = up * glm::dmat4(glm::dmat3(metres[0]));
    SceneMesh m;
    std::map<std::array<double, 3>, int> index;
    std::function<void(const pugi::xml_node&, const glm::dmat4&)> visit = [&](const pugi::xml_node& n, const glm::dmat4& parent) {
        glm::dmat4 local = parent;
        for (const pugi::xml_node t : n.children()) {
            const std::string name = t.name();
            const auto v = numbers(t.child_value());
            glm::dmat4 step(1.0);
            if (name == "translate" && v.size() == 3) step[3] = glm::dvec4(v[0], v[1], v[2], 1.0);
            else if (name == "scale" && v.size() == 3) step[0][0] = v[0], step[1][1] = v[1], step[2][2] = v[2];
            else if (name == "rotate" && v.size() == 4) {
                const double a = v[3] * 3.14159265358979323846 / 180.0;
                if (a != 0.0) step = glm::dmat4(glm::mat4_cast(glm::angleAxis(a, glm::normalize(glm::dvec3(v[0], v[1], v[2])))));
            } else if (name == "matrix" && v.size() == 16) {
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c) step[c][r] = v[std::size_t(4 * r + c)]; // row-major in the file
            } else continue;
            local = local * step;
        }
        const std::string object = n.attribute("name").value();
        for (const pugi::xml_node inst : n.children("instance_geometry")) {
            const pugi::xml_node geometry = by_id(root.child("library_geometries"), strip(inst.attribute("url").value()));
            const pugi::xml_node mesh = geometry.child("mesh");
            for (const pugi::xml_node tris : mesh.children()) {
                const std::string element = tris.name();
                if (element != "triangles" && element != "polygons" && element != "polylist") continue;
                // The triangles' material symbol, bound by the instance to a material.
                std::string material = tris.attribute("material").value();
                const pugi::xml_node bound = inst.find_node([&](const pugi::xml_node& b) {
                    return std::string(b.name()) == "instance_material" && material == b.attribute("symbol").value();
                });
                if (bound) {
                    const pugi::xml_node mat = by_id(root.child("library_materials"), strip(bound.attribute("target").value()));
                    material = mat && mat.attribute("name") ? mat.attribute("name").value() : strip(bound.attribute("target").value());
                }
                int stride = 0, vertex_offset = 0, normal_offset = -1;
                std::string vertex_source, normal_source;
                for (const pugi::xml_node in : tris.children("input")) {
                    const int offset = in.attribute("offset").as_int();
                    stride = std::max(stride, offset + 1);
                    const std::string semantic = in.attribute("semantic").value();
                    if (semantic == "VERTEX") vertex_offset = offset, vertex_source = strip(in.attribute("source").value());
                    if (semantic == "NORMAL") normal_offset = offset, normal_source = strip(in.attribute("source").value());
                }
                const pugi::xml_node vertices = by_id(mesh, vertex_source);
                std::string position_source;
                for (const pugi::xml_node in : vertices.children("input"))
                    if (std::string(in.attribute("semantic").value()) == "POSITION") position_source = strip(in.attribute("source").value());
                const auto pos = numbers(by_id(mesh, position_source).child("float_array").child_value());
                const auto nrm = normal_offset >= 0 ? numbers(by_id(mesh, normal_source).child("float_array").child_value())
                                                    : std::vector<double>{};
                const std::size_t corner = std::size_t(stride);
                // The polygons as corner counts and index lists: <triangles>
                // one <p> of triangles, <polylist> one <p> with a <vcount>,
                // <polygons> a <p> per polygon. Each polygon is fanned.
                std::vector<std::pair<std::vector<double>, std::vector<double>>> lists;
                if (element == "polygons") {
                    for (const pugi::xml_node p : tris.children("p")) {
                        const auto indices = numbers(p.child_value());
                        lists.push_back({{double(indices.size() / corner)}, indices});
                    }
                } else {
                    const auto indices = numbers(tris.child_value("p"));
                    lists.push_back({element == "polylist" ? numbers(tris.child_value("vcount"))
                                                           : std::vector<double>(indices.size() / (3 * corner), 3.0),
                                     indices});
                }
                for (const auto& list : lists) {
                    const std::vector<double>& counts = list.first;
                    const std::vector<double>& p = list.second; // (a lambda below reads it: no structured binding)
                    std::size_t first = 0;
                    for (const double count : counts) {
                        const auto corners = std::size_t(count);
                        if ((first + corners) * corner > p.size()) break;
                        auto corner_at = [&](std::size_t c, glm::dvec3& q, glm::dvec3& nn) {
                            const std::size_t at = (first + c) * corner;
                            const auto v = std::size_t(p[at + std::size_t(vertex_offset)]);
                            q = {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]};
                            nn = glm::dvec3(0.0);
                            if (normal_offset >= 0) {
                                const auto w = std::size_t(p[at + std::size_t(normal_offset)]);
                                nn = {nrm[3 * w], nrm[3 * w + 1], nrm[3 * w + 2]};
                            }
                        };
                        for (std::size_t c = 1; c + 1 < corners; ++c) {
                            std::array<glm::dvec3, 3> q, nn;
                            corner_at(0, q[0], nn[0]);
                            corner_at(c, q[1], nn[1]);
                            corner_at(c + 1, q[2], nn[2]);
                            scene_detail::add_triangle(m, index, local, q, nn, object, material);
                        }
                        first += corners;
                    }
                }
            }
        }
        for (const pugi::xml_node child : n.children("node")) visit(child, local);
    };
    for (const pugi::xml_node scene : root.child("library_visual_scenes").children("visual_scene"))
        for (const pugi::xml_node n : scene.children("node")) visit(n, up);
    return m;
}

/// A Wavefront OBJ file with its parts: `o` names the object of the faces
/// after it, `usemtl` their material; `v`, `vn` and triangles `f v//vn` or
/// `f v/vt/vn` (a face without normals gets zero corner normals; polygons
/// are fanned). Indices count from 1, negative ones back from the end.
inline SceneMesh read_obj_parts(const std::string& path) {
    std::istringstream in(scene_detail::slurp(path));
    std::vector<glm::dvec3> v, vn;
    SceneMesh m;
    std::map<std::array<double, 3>, int> index;
    std::string object, material, line;
    auto at = [](long i, std::size_t n) { return i > 0 ? std::size_t(i - 1) : std::size_t(long(n) + i); };
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "v" || key == "vn") {
            glm::dvec3 p;
            words >> p.x >> p.y >> p.z;
            (key == "v" ? v : vn).push_back(p);
        } else if (key == "o") {
            std::getline(words >> std::ws, object);
        } else if (key == "usemtl") {
            std::getline(words >> std::ws, material);
        } else if (key == "f") {
            std::vector<std::pair<glm::dvec3, glm::dvec3>> corners;
            for (std::string c; words >> c;) {
                const auto slash = c.find('/'), last = c.rfind('/');
                const glm::dvec3 p = v.at(at(std::stol(c.substr(0, slash)), v.size()));
                const glm::dvec3 n = slash != std::string::npos && last + 1 < c.size()
                                         ? vn.at(at(std::stol(c.substr(last + 1)), vn.size()))
                                         : glm::dvec3(0.0);
                corners.push_back({p, n});
            }
            for (std::size_t k = 1; k + 1 < corners.size(); ++k)
                scene_detail::add_triangle(m, index, glm::dmat4(1.0), {corners[0].first, corners[k].first, corners[k + 1].first},
                                           {corners[0].second, corners[k].second, corners[k + 1].second}, object, material);
        }
    }
    return m;
}

/// Corner normals shaded with an auto-smooth angle: at each corner, the
/// area-weighted normal of the faces around its vertex reached through
/// edges whose faces meet at no more than @p degrees.
inline std::vector<std::array<glm::dvec3, 3>> auto_smooth_normals(const std::vector<glm::dvec3>& positions,
                                                                  const std::vector<std::array<int, 3>>& faces,
                                                                  double degrees) {
    std::vector<glm::dvec3> area(faces.size()); // twice the area along the unit normal
    for (std::size_t f = 0; f < faces.size(); ++f)
        area[f] = glm::cross(positions[std::size_t(faces[f][1])] - positions[std::size_t(faces[f][0])],
                             positions[std::size_t(faces[f][2])] - positions[std::size_t(faces[f][0])]);
    std::map<std::pair<int, int>, std::vector<std::size_t>> edge_faces;
    std::vector<std::vector<std::size_t>> vertex_faces(positions.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = faces[f][std::size_t(k)], b = faces[f][std::size_t((k + 1) % 3)];
            edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
            vertex_faces[std::size_t(a)].push_back(f);
        }
    const double limit = std::cos(degrees * 3.14159265358979323846 / 180.0);
    auto smooth = [&](std::size_t f, std::size_t g) {
        return glm::dot(glm::normalize(area[f]), glm::normalize(area[g])) >= limit;
    };
    std::vector<std::array<glm::dvec3, 3>> out(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int v = faces[f][std::size_t(k)];
            // Flood from f over the faces at v, crossing smooth edges at v only.
            std::vector<std::size_t> reached{f};
            for (std::size_t i = 0; i < reached.size(); ++i) {
                const auto& r = faces[reached[i]];
                for (int j = 0; j < 3; ++j) {
                    const int w = r[std::size_t(j)];
                    if (w == v) continue;
                    for (const std::size_t g : edge_faces[{std::min(v, w), std::max(v, w)}])
                        if (std::find(reached.begin(), reached.end(), g) == reached.end() && smooth(reached[i], g))
                            reached.push_back(g);
                }
            }
            glm::dvec3 sum(0.0);
            for (const std::size_t g : reached) sum += area[g];
            out[f][std::size_t(k)] = glm::normalize(sum);
        }
    return out;
}

} // namespace snaxels::ref
