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

/// A glTF 1.0 file (dictionaries of accessors, buffer views, buffers, meshes
/// and nodes by id; the scene named by "scene"); triangle lists only.
inline SceneMesh read_gltf1(const std::string& path) {
    using nlohmann::json;
    const json g = json::parse(scene_detail::slurp(path));
    const std::string dir = path.substr(0, path.find_last_of('/') + 1);
    std::map<std::string, std::string> buffers;
    for (const auto& [id, b] : g.at("buffers").items()) buffers[id] = scene_detail::slurp(dir + b.at("uri").get<std::string>());
    auto accessor = [&](const std::string& id) {
        const json& a = g.at("accessors").at(id);
        const json& view = g.at("bufferViews").at(a.at("bufferView").get<std::string>());
        const std::string& data = buffers.at(view.at("buffer").get<std::string>());
        const std::size_t start = view.value("byteOffset", std::size_t(0)) + a.value("byteOffset", std::size_t(0));
        const std::string type = a.at("type");
        const int width = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
        const int component = a.at("componentType");
        const std::size_t size = component == 5126 || component == 5125 ? 4 : component == 5123 || component == 5122 ? 2 : 1;
        std::size_t stride = a.value("byteStride", std::size_t(0));
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
    };
    SceneMesh m;
    std::map<std::array<double, 3>, int> index;
    std::function<void(const std::string&, const glm::dmat4&)> visit = [&](const std::string& id, const glm::dmat4& parent) {
        const json& node = g.at("nodes").at(id);
        glm::dmat4 local(1.0);
        if (node.contains("matrix")) {
            const auto v = node.at("matrix").get<std::vector<double>>();
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) local[c][r] = v[std::size_t(4 * c + r)]; // column-major, as glm
        } else {
            const auto t = node.value("translation", std::vector<double>{0, 0, 0});
            const auto q = node.value("rotation", std::vector<double>{0, 0, 0, 1}); // x, y, z, w
            const auto s = node.value("scale", std::vector<double>{1, 1, 1});
            const glm::dmat4 rotation = glm::mat4_cast(glm::dquat(q[3], q[0], q[1], q[2]));
            glm::dmat4 translation(1.0), scale(1.0);
            translation[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
            scale[0][0] = s[0], scale[1][1] = s[1], scale[2][2] = s[2];
            local = translation * rotation * scale;
        }
        const glm::dmat4 world = parent * local;
        const std::string object = node.value("name", id);
        for (const auto& mesh_id : node.value("meshes", std::vector<std::string>{}))
            for (const json& prim : g.at("meshes").at(mesh_id).at("primitives")) {
                if (prim.value("mode", 4) != 4) continue;
                const std::string material_id = prim.value("material", std::string());
                const std::string material = material_id; // the file's identifier (Assimp names glTF 1.0 materials by it)
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
                    scene_detail::add_triangle(m, index, world, p, n, object, material);
                }
            }
        for (const auto& child : node.value("children", std::vector<std::string>{})) visit(child, world);
    };
    const json& scene = g.at("scenes").at(g.at("scene").get<std::string>());
    for (const auto& id : scene.at("nodes")) visit(id.get<std::string>(), glm::dmat4(1.0));
    return m;
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
