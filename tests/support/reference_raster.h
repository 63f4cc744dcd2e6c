#pragma once
// An independent reference for planar maps and shaded fills: a z-buffer
// rasterizer written for the tests from the mesh file alone. It reads OBJ
// and PLY itself, welds equal positions, computes area-weighted vertex
// normals, projects with its own camera formulas, keeps the nearest
// triangle per pixel centre and classes the pixel by N.L of the
// Phong-interpolated normal. It includes nothing from core/.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels::ref {

struct Mesh {
    std::vector<glm::dvec3> positions, normals;
    std::vector<std::array<int, 3>> faces;
};

namespace detail {

inline int weld(Mesh& m, std::map<std::array<double, 3>, int>& index, const glm::dvec3& p) {
    const auto [it, fresh] = index.emplace(std::array<double, 3>{p.x, p.y, p.z}, int(m.positions.size()));
    if (fresh) m.positions.push_back(p);
    return it->second;
}

inline void add_polygon(Mesh& m, const std::vector<int>& corners) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        const std::array<int, 3> f{corners[0], corners[i], corners[i + 1]};
        if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) m.faces.push_back(f);
    }
}

inline Mesh read_obj(std::istream& in) {
    Mesh m;
    std::vector<glm::dvec3> v;
    std::map<std::array<double, 3>, int> index;
    std::vector<int> welded;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            glm::dvec3 p;
            s >> p.x >> p.y >> p.z;
            v.push_back(p);
            welded.push_back(weld(m, index, p));
        } else if (tag == "f") {
            std::vector<int> corners;
            std::string word;
            while (s >> word) {
                const int i = std::stoi(word.substr(0, word.find('/')));
                const int at = i < 0 ? int(v.size()) + i : i - 1;
                if (at < 0 || at >= int(v.size())) throw std::runtime_error("OBJ face index out of range");
                corners.push_back(welded[std::size_t(at)]);
            }
            add_polygon(m, corners);
        }
    }
    return m;
}

inline Mesh read_ply(std::istream& in) {
    struct Property {
        std::string name, type, count_type; // count_type set: a list
    };
    struct Element {
        std::string name;
        std::size_t count = 0;
        std::vector<Property> props;
    };
    std::vector<Element> elements;
    std::string line, format;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string word;
        s >> word;
        if (word == "format") s >> format;
        else if (word == "element") {
            elements.emplace_back();
            s >> elements.back().name >> elements.back().count;
        } else if (word == "property") {
            Property p;
            s >> p.type;
            if (p.type == "list") s >> p.count_type >> p.type;
            s >> p.name;
            elements.back().props.push_back(p);
        } else if (word == "end_header") break;
    }
    const bool ascii = format == "ascii";
    if (!ascii && format != "binary_little_endian") throw std::runtime_error("PLY format " + format + " not read by the reference");
    auto size_of = [](const std::string& t) -> int {
        if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
        if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
        if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
        return 8;
    };
    auto read = [&](const std::string& t) -> double {
        if (ascii) {
            double x;
            in >> x;
            return x;
        }
        unsigned char b[8] = {};
        in.read(reinterpret_cast<char*>(b), size_of(t));
        if (t == "char" || t == "int8") return double(std::int8_t(b[0]));
        if (t == "uchar" || t == "uint8") return double(b[0]);
        if (t == "short" || t == "int16") { std::int16_t x; std::memcpy(&x, b, 2); return x; }
        if (t == "ushort" || t == "uint16") { std::uint16_t x; std::memcpy(&x, b, 2); return x; }
        if (t == "int" || t == "int32") { std::int32_t x; std::memcpy(&x, b, 4); return x; }
        if (t == "uint" || t == "uint32") { std::uint32_t x; std::memcpy(&x, b, 4); return x; }
        if (t == "float" || t == "float32") { float x; std::memcpy(&x, b, 4); return x; }
        double x;
        std::memcpy(&x, b, 8);
        return x;
    };
    Mesh m;
    std::vector<int> welded;
    std::map<std::array<double, 3>, int> index;
    for (const Element& e : elements)
        for (std::size_t i = 0; i < e.count; ++i) {
            glm::dvec3 p(0.0);
            std::vector<int> corners;
            for (const Property& prop : e.props) {
                if (!prop.count_type.empty()) {
                    const int n = int(read(prop.count_type));
                    std::vector<int> list;
                    for (int k = 0; k < n; ++k) list.push_back(int(read(prop.type)));
                    if (e.name == "face" && (prop.name == "vertex_indices" || prop.name == "vertex_index")) corners = list;
                    continue;
                }
                const double x = read(prop.type);
                if (prop.name == "x") p.x = x;
                if (prop.name == "y") p.y = x;
                if (prop.name == "z") p.z = x;
            }
            if (e.name == "vertex") welded.push_back(weld(m, index, p));
            if (e.name == "face") {
                for (int& c : corners) {
                    if (c < 0 || c >= int(welded.size())) throw std::runtime_error("PLY face index out of range");
                    c = welded[std::size_t(c)];
                }
                add_polygon(m, corners);
            }
        }
    return m;
}

} // namespace detail

/// Reads an OBJ or PLY file (by extension) and computes its normals.
inline Mesh read_mesh(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    const std::string ext = path.substr(path.find_last_of('.') + 1);
    Mesh m = ext == "ply" ? detail::read_ply(in) : detail::read_obj(in);
    // Closed parts turned inside out (negative enclosed volume) are turned
    // outward, so that normals point away from the solid.
    {
        std::vector<int> parent(m.positions.size());
        for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
        auto find = [&](int x) {
            while (parent[std::size_t(x)] != x) x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
            return x;
        };
        for (const auto& f : m.faces) parent[std::size_t(find(f[0]))] = find(f[1]), parent[std::size_t(find(f[1]))] = find(f[2]);
        std::map<std::pair<int, int>, int> edge_use; // directed edge count per undirected edge: closed if each twice
        std::map<int, double> volume;
        std::map<int, bool> closed;
        for (const auto& f : m.faces) {
            const glm::dvec3 &a = m.positions[std::size_t(f[0])], &b = m.positions[std::size_t(f[1])], &c = m.positions[std::size_t(f[2])];
            volume[find(f[0])] += glm::dot(a, glm::cross(b, c)) / 6.0;
            for (int k = 0; k < 3; ++k) ++edge_use[{std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])}];
        }
        for (const auto& f : m.faces) closed.emplace(find(f[0]), true);
        for (const auto& [e, n] : edge_use)
            if (n != 2) closed[find(e.first)] = false;
        for (auto& f : m.faces)
            if (closed[find(f[0])] && volume[find(f[0])] < 0.0) std::swap(f[1], f[2]);
    }
    m.normals.assign(m.positions.size(), glm::dvec3(0.0));
    for (const auto& f : m.faces) {
        const glm::dvec3 n = glm::cross(m.positions[std::size_t(f[1])] - m.positions[std::size_t(f[0])],
                                        m.positions[std::size_t(f[2])] - m.positions[std::size_t(f[0])]);
        for (const int v : f) m.normals[std::size_t(v)] += n; // |n| is twice the area: area weights
    }
    for (glm::dvec3& n : m.normals) {
        const double len = glm::length(n);
        n = len > 0.0 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
    }
    return m;
}

/// Writes triangles as an OBJ file (for procedural meshes, so that the
/// product and the reference read the same file).
inline void write_obj(const std::string& path, const std::vector<glm::dvec3>& positions,
                      const std::vector<std::array<std::uint32_t, 3>>& faces) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) throw std::runtime_error("cannot write " + path);
    for (const glm::dvec3& p : positions) std::fprintf(out, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    for (const auto& f : faces) std::fprintf(out, "f %u %u %u\n", f[0] + 1, f[1] + 1, f[2] + 1);
    std::fclose(out);
}

/// A view as numbers: orthographic along `dir`, or perspective from `eye`
/// at `target` with a vertical field of view; the image fits the sphere
/// (`centre`, `radius`) within `margin` pixels (orthographic) or maps the
/// field of view to its shorter side (perspective).
struct View {
    bool orthographic = true;
    glm::dvec3 dir{0, 0, 1}, eye{0, 0, 5}, target{0.0}, up{0, 1, 0};
    double fov_deg = 35.0;
    glm::dvec3 centre{0.0};
    double radius = 1.0;
    int width = 512, height = 512;
    double margin = 32.0;
};

/// Calls @p fn(x, y, wa, wb, wc) for every pixel whose centre lies in the
/// image triangle @p a, @p b, @p c (pixels, y down), with the centre's
/// barycentric weights; nothing for a triangle of no area.
template <class Fn>
void for_each_pixel_in(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, int width, int height, Fn&& fn) {
    const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (area == 0.0) return;
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            const double wa = ((b.x - px) * (c.y - py) - (c.x - px) * (b.y - py)) / area;
            const double wb = ((c.x - px) * (a.y - py) - (a.x - px) * (c.y - py)) / area;
            const double wc = 1.0 - wa - wb;
            if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
            fn(x, y, wa, wb, wc);
        }
}

/// Per pixel: 0 shadow (N.L < 0), 1 lit, 2 + i at or above bands[i]
/// (ascending), -1 where no triangle covers the pixel centre. @p to_light:
/// direction toward a directional light. With @p corner_normals (per face,
/// per corner) the normal is interpolated from those: a hard-edged mesh.
/// With @p nearest_face, each pixel's nearest face too (-1: none).
inline std::vector<int> class_image(const Mesh& m, const View& view, const glm::dvec3& to_light,
                                    const std::vector<double>& bands,
                                    const std::vector<std::array<glm::dvec3, 3>>* corner_normals = nullptr,
                                    std::vector<int>* nearest_face = nullptr) {
    const glm::dvec3 fwd = glm::normalize(view.orthographic ? view.dir : view.target - view.eye);
    glm::dvec3 up = glm::normalize(view.up);
    if (std::abs(glm::dot(fwd, up)) > 0.999) up = std::abs(fwd.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(fwd, up));
    const glm::dvec3 sup = glm::cross(right, fwd);
    const double half = 0.5 * std::min(view.width, view.height);
    const double scale = view.orthographic ? (half - view.margin) / view.radius
                                           : half / std::tan(0.5 * view.fov_deg * 3.14159265358979323846 / 180.0);
    struct Projected {
        double x, y, z; // pixels, depth along fwd
    };
    std::vector<Projected> pv(m.positions.size());
    for (std::size_t i = 0; i < pv.size(); ++i) {
        const glm::dvec3 d = m.positions[i] - (view.orthographic ? view.centre : view.eye);
        const double z = glm::dot(d, fwd);
        const double k = view.orthographic ? scale : scale / z;
        pv[i] = {0.5 * view.width + k * glm::dot(d, right), 0.5 * view.height - k * glm::dot(d, sup), z};
    }
    const std::size_t n = std::size_t(view.width) * std::size_t(view.height);
    std::vector<double> depth(n, std::numeric_limits<double>::infinity());
    std::vector<int> face(n, -1);
    std::vector<glm::dvec3> weight(n);
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const Projected& a = pv[std::size_t(m.faces[f][0])];
        const Projected& b = pv[std::size_t(m.faces[f][1])];
        const Projected& c = pv[std::size_t(m.faces[f][2])];
        if (!view.orthographic && (a.z <= 1e-9 || b.z <= 1e-9 || c.z <= 1e-9)) continue;
        for_each_pixel_in({a.x, a.y}, {b.x, b.y}, {c.x, c.y}, view.width, view.height, [&](int x, int y, double wa, double wb, double wc) {
                glm::dvec3 w(wa, wb, wc);
                double z;
                if (view.orthographic) {
                    z = wa * a.z + wb * b.z + wc * c.z;
                } else { // perspective-correct: 1/z is linear in the image
                    w = glm::dvec3(wa / a.z, wb / b.z, wc / c.z);
                    const double inv = w.x + w.y + w.z;
                    z = 1.0 / inv;
                    w /= inv;
                }
                const std::size_t at = std::size_t(y) * std::size_t(view.width) + std::size_t(x);
                if (z >= depth[at]) return;
                depth[at] = z, face[at] = int(f), weight[at] = w;
            });
    }
    if (nearest_face) *nearest_face = face; // per pixel: the nearest face, -1 for none
    const glm::dvec3 l = glm::normalize(to_light);
    std::vector<int> out(n, -1);
    for (std::size_t at = 0; at < n; ++at) {
        if (face[at] < 0) continue;
        const auto& f = m.faces[std::size_t(face[at])];
        // The face's own corner normals where given (hard edges), else the vertices'.
        const auto corner = [&](int k) {
            return corner_normals ? (*corner_normals)[std::size_t(face[at])][std::size_t(k)] : m.normals[std::size_t(f[std::size_t(k)])];
        };
        const glm::dvec3 nrm = glm::normalize(weight[at].x * corner(0) + weight[at].y * corner(1) + weight[at].z * corner(2));
        const double nl = glm::dot(nrm, l);
        int cls = nl < 0.0 ? 0 : 1;
        for (std::size_t i = 0; i < bands.size(); ++i)
            if (cls != 0 && nl >= bands[i]) cls = 2 + int(i);
        out[at] = cls;
    }
    return out;
}

} // namespace snaxels::ref
