#pragma once
// The numbers of a product view, light and contour kind for the engine
// oracle (tests/support/marching_triangles.h), which takes plain numbers.

#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "tests/support/marching_triangles.h"

namespace snaxels::test {

inline OracleSetup oracle_setup(const ContourSpec& spec, const Camera& cam, const Light& light) {
    OracleSetup s;
    s.kind = spec.kind == ContourKind::Visual     ? OracleSetup::Visual
             : spec.kind == ContourKind::Shadow   ? OracleSetup::Shadow
             : spec.kind == ContourKind::Isophote ? OracleSetup::Isophote
                                                  : OracleSetup::Gleam;
    s.k = spec.k;
    s.orthographic = cam.projection == Camera::Projection::Orthographic;
    s.view_dir = cam.view_dir, s.eye = cam.eye;
    s.point_light = light.point;
    s.light_dir = light.dir, s.light_pos = light.pos;
    return s;
}

} // namespace snaxels::test
