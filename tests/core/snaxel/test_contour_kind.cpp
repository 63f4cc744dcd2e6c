// A contour kind is one entry of the table of kinds and its own function:
// a kind added here, and nowhere else, is read from the command line's
// --kind and a style's <contour kind>, found by the engine, followed by a
// tracker, and drawn with the entry's stroke. The kind: the facing-ratio
// line N.V = k (g = N.V - k, so f = min(g, N.V) = N.V - k for k >= 0),
// which on the unit sphere seen along -V is the circle of points p with
// p.V = k. The expected circle is written out here from that formula.

#include <gtest/gtest.h>

#include <cmath>

#include "snaxels/animation/still.h"
#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/contour_kind.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/style/style.h"

using namespace snaxels;

namespace {

double facing(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3&, double k) { return glm::dot(n, v) - k; }

/// The kind, added once for the whole test program.
ContourKind facing_kind() {
    static const ContourKind kind = [] {
        ContourKindInfo info;
        info.name = "facing";
        info.origin = ContourOrigin::View;
        info.value = ContourValue::Cosine;
        info.usage = "facing:K";
        info.stroke = "#0a7d6e";
        info.view_colour = "#40e0c0";
        info.g = facing;
        return register_contour_kind(info);
    }();
    return kind;
}

/// How far the snaxels of @p fronts on the unit sphere lie from the circle p.V = k.
double worst_off_circle(const MeshTopology& topo, const Fronts& fronts, const glm::dvec3& v, double k, std::size_t& n) {
    double worst = 0.0;
    n = 0;
    for (const FrontLoop& loop : fronts.loops)
        fronts.for_each_in_loop(loop, [&](std::int32_t s) {
            const Snaxel& sn = fronts.snaxels[std::size_t(s)];
            const glm::dvec3 p = glm::normalize((1.0 - sn.t) * topo.positions()[sn.inside] + sn.t * topo.positions()[sn.outside]);
            worst = std::max(worst, std::abs(glm::dot(p, v) - k));
            ++n;
        });
    return worst;
}

} // namespace

TEST(ContourKinds, AKindIsOneTableEntryAndOneFunction) {
    const ContourKind kind = facing_kind();
    EXPECT_GT(int(kind), int(ContourKind::Intersection));
    EXPECT_EQ(contour_kind_info(kind).name, std::string("facing"));
    EXPECT_THROW(register_contour_kind(contour_kind_info(kind)), Error); // a name is taken once

    // The command line.
    const ContourSpec spec = ContourSpec::parse("facing:0.5");
    EXPECT_EQ(spec.kind, kind);
    EXPECT_DOUBLE_EQ(spec.k, 0.5);
    EXPECT_EQ(spec.label(), "facing:0.5");
    EXPECT_EQ(spec.kind_name(), "facing");
    EXPECT_FALSE(spec.on_surface());
    EXPECT_THROW(ContourSpec::parse("facing"), Error); // a cosine it needs
    try {
        ContourSpec::parse("nothing");
        ADD_FAILURE() << "an unknown kind parsed";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("facing:K"), std::string::npos) << e.what();
    }

    // The engine, on the unit sphere seen from an orthographic camera and
    // from a perspective one.
    const LoadedMesh mesh = load_mesh("proc:sphere:20000");
    const MeshTopology topo = build_topology(mesh.mesh);
    const SnaxelEngine engine(topo);
    Camera ortho;
    ortho.view_dir = glm::normalize(glm::dvec3(0.3, -0.4, -1.0));
    const glm::dvec3 v = -ortho.view_dir;
    std::size_t n = 0;
    const ContourResult found = engine.compute(spec, ortho, Light{});
    EXPECT_LT(worst_off_circle(topo, found.fronts, v, 0.5, n), 0.01);
    EXPECT_GT(n, 100u);
    EXPECT_EQ(found.fronts.loops.size(), 1u);

    // A tracker follows it as the view turns, as from scratch.
    ContourTracker tracker(topo, spec);
    Camera turned = ortho;
    for (int step = 0; step < 5; ++step) {
        turned.view_dir = glm::normalize(turned.view_dir + glm::dvec3(0.05, 0.0, 0.0));
        const TrackedFrame& tracked = tracker.step(turned, Light{});
        EXPECT_LT(worst_off_circle(topo, tracked.contour.fronts, -turned.view_dir, 0.5, n), 0.01) << "step " << step;
        const ContourResult scratch = engine.compute(spec, turned, Light{});
        EXPECT_EQ(tracked.contour.fronts.snaxels.size(), scratch.fronts.snaxels.size()) << "step " << step;
    }

    // A style draws it with the entry's stroke.
    std::vector<StyleDiagnostic> warnings;
    const Style style = parse_style("<style version=\"1\"><contour kind=\"facing\" k=\"0.3\"/></style>", "test", &warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(style.contours.size(), 1u);
    EXPECT_EQ(style.contours[0].spec.kind, kind);
    EXPECT_DOUBLE_EQ(style.contours[0].spec.k, 0.3);
    EXPECT_EQ(style.contours[0].visible.colour, "#0a7d6e");
    StillJob job = make_still_job(style, ortho, std::nullopt);
    const StillOutput out = render_still(mesh, topo, nullptr, job);
    EXPECT_NE(out.svg.find("data-kind=\"facing\""), std::string::npos);
    EXPECT_NE(out.svg.find("#0a7d6e"), std::string::npos);
    // The value a cosine kind takes, and the attributes it does not.
    EXPECT_THROW(parse_style("<style><contour kind=\"facing\"/></style>", "test", nullptr), StyleError);
    EXPECT_THROW(parse_style("<style><contour kind=\"facing\" k=\"0.3\" angle=\"20\"/></style>", "test", nullptr), StyleError);
}

// Every built-in kind has what its origin needs, and its name finds it.
TEST(ContourKinds, TheTableIsComplete) {
    for (const ContourKindInfo* info : contour_kinds()) {
        EXPECT_EQ(find_contour_kind(info->name), info);
        EXPECT_EQ(&contour_kind_info(info->kind), info);
        switch (info->origin) {
        case ContourOrigin::View: EXPECT_NE(info->g, nullptr) << info->name; break;
        case ContourOrigin::Vertices: EXPECT_NE(info->vertices, nullptr) << info->name; break;
        case ContourOrigin::Edges: EXPECT_NE(info->edges, nullptr) << info->name; break;
        case ContourOrigin::Surface: break;
        }
        EXPECT_EQ(ContourSpec::parse(info->value == ContourValue::Cosine ? std::string(info->name) + ":0.5" : info->name).kind,
                  info->kind);
    }
}
