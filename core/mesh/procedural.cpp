#include "snaxels/mesh/procedural.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/glm.hpp>

#include "snaxels/error.h"

namespace snaxels {
namespace {

constexpr std::size_t kMinFaces = 48;
constexpr std::size_t kMaxFaces = 50'000'000;

// Grid of (n+1)^2 points on each cube face, pushed out to radius(dir). Points
// on shared cube edges are computed by the same expression from every face,
// so they are bit-identical and welding joins the faces into a closed mesh.
TriangleSoup make_cube_sphere(std::size_t target_faces,
                              const std::function<double(const glm::dvec3&)>& radius) {
    const auto n = static_cast<std::uint32_t>(
        std::max(2.0, std::round(std::sqrt(double(target_faces) / 12.0))));
    TriangleSoup soup;
    soup.positions.reserve(6u * (n + 1) * (n + 1));
    soup.triangles.reserve(12u * n * n);
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            const auto base = static_cast<std::uint32_t>(soup.positions.size());
            for (std::uint32_t i = 0; i <= n; ++i)
                for (std::uint32_t j = 0; j <= n; ++j) {
                    const double u = -1.0 + 2.0 * i / n, v = -1.0 + 2.0 * j / n;
                    glm::dvec3 p{};
                    p[axis] = sign;
                    p[(axis + 1) % 3] = u;
                    p[(axis + 2) % 3] = v;
                    const glm::dvec3 d = glm::normalize(p);
                    soup.positions.push_back(d * radius(d));
                }
            for (std::uint32_t i = 0; i < n; ++i)
                for (std::uint32_t j = 0; j < n; ++j) {
                    const std::uint32_t a = base + i * (n + 1) + j, b = a + (n + 1), c = b + 1,
                                        d = a + 1;
                    // Keep outward orientation on both signs of the axis.
                    if (sign > 0) {
                        soup.triangles.push_back({a, b, c});
                        soup.triangles.push_back({a, c, d});
                    } else {
                        soup.triangles.push_back({a, c, b});
                        soup.triangles.push_back({a, d, c});
                    }
                }
        }
    return soup;
}

double bump(const glm::dvec3& dir, const glm::dvec3& centre, double width) {
    const double s = 1.0 - glm::dot(dir, glm::normalize(centre)); // 0 at the centre
    return std::exp(-s / (width * width));
}

} // namespace

TriangleSoup make_torus(std::size_t target_faces) {
    constexpr double R = 1.0, r = 0.4;
    // Cells roughly square: the long way round is R/r times the short way.
    const double cells = double(target_faces) / 2.0;
    const auto nv = static_cast<std::uint32_t>(std::max(3.0, std::round(std::sqrt(cells * r / R))));
    const auto nu = static_cast<std::uint32_t>(std::max(3.0, std::round(cells / nv)));
    TriangleSoup soup;
    soup.positions.reserve(std::size_t(nu) * nv);
    soup.triangles.reserve(std::size_t(nu) * nv * 2);
    for (std::uint32_t i = 0; i < nu; ++i) {
        const double phi = 2.0 * std::numbers::pi * i / nu;
        for (std::uint32_t j = 0; j < nv; ++j) {
            const double theta = 2.0 * std::numbers::pi * j / nv;
            const double ring = R + r * std::cos(theta);
            soup.positions.push_back({ring * std::cos(phi), ring * std::sin(phi), r * std::sin(theta)});
        }
    }
    for (std::uint32_t i = 0; i < nu; ++i)
        for (std::uint32_t j = 0; j < nv; ++j) {
            const std::uint32_t i1 = (i + 1) % nu, j1 = (j + 1) % nv;
            const std::uint32_t a = i * nv + j, b = i1 * nv + j, c = i1 * nv + j1, d = i * nv + j1;
            soup.triangles.push_back({a, b, c});
            soup.triangles.push_back({a, c, d});
        }
    return soup;
}

TriangleSoup make_sphere(std::size_t target_faces) {
    return make_cube_sphere(target_faces, [](const glm::dvec3&) { return 1.0; });
}

TriangleSoup make_bumpy_sphere(std::size_t target_faces) {
    return make_cube_sphere(target_faces, [](const glm::dvec3& d) {
        return 1.0 + 0.12 * std::sin(6.0 * d.x) * std::sin(6.0 * d.y) * std::sin(6.0 * d.z);
    });
}

namespace {

/// The nose's radius in direction @p d.
double nose_radius(const glm::dvec3& d) {
    return 1.0 + 0.85 * bump(d, {0.0, -0.05, 1.0}, 0.2)    // the nose
           + 0.25 * bump(d, {0.0, 0.25, 1.0}, 0.14)         // its bridge
           + 0.2 * bump(d, {0.2, -0.32, 0.93}, 0.1)         // nostrils
           + 0.2 * bump(d, {-0.2, -0.32, 0.93}, 0.1)
           - 0.16 * bump(d, {0.38, 0.3, 0.87}, 0.13)        // eye sockets
           - 0.16 * bump(d, {-0.38, 0.3, 0.87}, 0.13)
           + 0.14 * bump(d, {0.4, 0.5, 0.77}, 0.12)         // brows
           + 0.14 * bump(d, {-0.4, 0.5, 0.77}, 0.12)
           - 0.1 * bump(d, {0.0, -0.6, 0.8}, 0.12)          // mouth
           + 0.12 * bump(d, {0.0, -0.85, 0.53}, 0.2);       // chin
}

} // namespace

TriangleSoup make_nose(std::size_t target_faces) { return make_cube_sphere(target_faces, nose_radius); }

TriangleSoup make_scan(std::size_t target_faces) {
    // The nose's cube-sphere grid: n cells along a cube face's side, each
    // about a quarter turn / n long on the unit sphere.
    const double cells = std::max(2.0, std::round(std::sqrt(double(target_faces) / 12.0)));
    const double edge = 0.5 * std::numbers::pi / cells;
    return make_cube_sphere(target_faces, [edge](const glm::dvec3& d) {
        // Noise of the grid's scale: a value per point, from a hash of its
        // direction (the same on every cube face that holds the point, so
        // the seams still weld), a twentieth of an edge either way...
        std::uint64_t h = 0x9e3779b97f4a7c15ull;
        for (int k = 0; k < 3; ++k) {
            h ^= std::uint64_t(std::llround(d[k] * 1e9)) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
            h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
            h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
            h ^= h >> 31;
        }
        const double grain = (double(h >> 11) * 0x1.0p-53 * 2.0 - 1.0) * 0.05 * edge;
        // ... and ripples a few edges long and a tenth of one high, as a
        // scanner's registration leaves. (The amounts give a 360-frame
        // turntable of the 100K-face scan about the paths and events of a
        // real 100K-face scanned bust.)
        const double ripple = 0.1 * edge * std::sin(90.0 * d.x + 1.0) * std::sin(83.0 * d.y + 2.0) * std::sin(77.0 * d.z);
        return nose_radius(d) + grain + ripple;
    });
}

std::vector<std::string> procedural_names() { return {"torus", "sphere", "bumpy", "nose", "scan"}; }

TriangleSoup make_procedural(const std::string& description) {
    const auto colon = description.find(':');
    const std::string name = description.substr(0, colon);
    std::size_t faces = 20000;
    if (colon != std::string::npos) {
        const std::string count = description.substr(colon + 1);
        const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), faces);
        if (ec != std::errc() || end != count.data() + count.size() || faces < kMinFaces ||
            faces > kMaxFaces)
            throw Error("proc:" + description + ": the face count must be a whole number from " +
                        std::to_string(kMinFaces) + " to " + std::to_string(kMaxFaces));
    }
    if (name == "torus") return make_torus(faces);
    if (name == "sphere") return make_sphere(faces);
    if (name == "bumpy") return make_bumpy_sphere(faces);
    if (name == "nose") return make_nose(faces);
    if (name == "scan") return make_scan(faces);
    throw Error("proc:" + description + ": unknown procedural mesh '" + name +
                "' (known: torus, sphere, bumpy, nose, scan)");
}

} // namespace snaxels
