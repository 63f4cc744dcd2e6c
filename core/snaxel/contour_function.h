#pragma once
/// The implicit contour functions of the paper's "NPR Contouring" section,
/// evaluated at a surface point with its (slerped) normal. f >= 0 is inside.

#include <string>

#include <glm/glm.hpp>

#include "core/scene/camera.h"

namespace snaxels {

enum class ContourKind { Visual, Shadow, Isophote, Gleam, Parabolic };

/// Which contour: visual N.V; shadow min(N.L, N.V); diffuse isophote
/// min(N.L - k, N.V); specular gleam min(V.R - k, N.V) with R = 2(N.L)N - L.
/// Parabolic curves have no contour function: they are the mesh's, found
/// from visual events over all views (core/parabolic), the same from any view.
struct ContourSpec {
    ContourKind kind = ContourKind::Visual;
    double k = 0.0;

    /// "visual", "shadow", "isophote", "gleam" or "parabolic".
    std::string kind_name() const;
    /// "visual", "shadow", "isophote:0.5", "gleam:0.9", "parabolic": what parse() reads.
    std::string label() const;
    /// Parses the CLI's --kind values; throws snaxels::Error when malformed.
    static ContourSpec parse(const std::string& text);
};

/// f for one spec, camera and light.
class ContourFunction {
  public:
    ContourFunction(const ContourSpec& spec, const Camera& camera, const Light& light)
        : spec_(spec), camera_(camera), light_(light) {}

    double operator()(const glm::dvec3& p, const glm::dvec3& n) const;

  private:
    double evaluate(const glm::dvec3& p, const glm::dvec3& n) const;

    ContourSpec spec_;
    Camera camera_;
    Light light_;
};

/// Spherical linear interpolation of unit normals, the limit na as they align.
glm::dvec3 slerp_normal(const glm::dvec3& na, const glm::dvec3& nb, double t);

/// slerp_normal along one edge, its arc's angle found once: root polishing
/// evaluates many points of the same edge (the same values, fewer acos and
/// sin calls).
class SlerpArc {
  public:
    SlerpArc(const glm::dvec3& na, const glm::dvec3& nb);
    glm::dvec3 operator()(double t) const;

  private:
    glm::dvec3 na_, nb_;
    double c_, theta_, s_;
};

} // namespace snaxels
