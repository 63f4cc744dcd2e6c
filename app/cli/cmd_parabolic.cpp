#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/scene_options.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/parabolic.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/util/atomic_file.h"

namespace snaxels::cli {

namespace {

nlohmann::json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

/// Mesh element ids as the numbers the JSON report gives them.
template <class Tag> nlohmann::json indices(const std::vector<ElementId<Tag>>& ids) {
    nlohmann::json out = nlohmann::json::array();
    for (const ElementId<Tag> id : ids) out.push_back(id.index());
    return out;
}

std::string obj_text(const ParabolicResult& r) {
    std::ostringstream out;
    out.precision(9);
    out << "# snaxels parabolic: " << r.points.size() << " marked points, " << r.curves.size() << " curves\n";
    std::size_t v = 0;
    for (const ParabolicCurve& c : r.curves) {
        for (const glm::dvec3& p : c.points) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        out << 'l';
        for (std::size_t k = 0; k < c.points.size(); ++k) out << ' ' << v + k + 1;
        if (c.closed) out << ' ' << v + 1;
        out << '\n';
        v += c.points.size();
    }
    out << "g marked_points\n";
    for (const ParabolicPoint& p : r.points) out << "v " << p.where.x << ' ' << p.where.y << ' ' << p.where.z << '\n';
    if (!r.points.empty()) {
        out << 'p';
        for (std::size_t k = 0; k < r.points.size(); ++k) out << ' ' << v + k + 1;
        out << '\n';
    }
    return out.str();
}

} // namespace

int run_parabolic(const std::vector<std::string>& argv) {
    Args args("parabolic",
              "parabolic MESH [--samples N] [--json OUT] [--obj OUT]",
              std::string("Finds the mesh's parabolic points and curves from visual events: orthographic\n"
                          "view directions spread evenly over the sphere and walked in small steps, the\n"
                          "visual contour tracked between them, every creation, annihilation, split and\n"
                          "merge marked on the surface, the marks chained into curves across the faces\n"
                          "(docs/parabolic.md).\n\n") +
                  kMeshArgumentHelp,
              {{"samples", "N", "view directions over the sphere (default 2000)"},
               {"smoothing", "S", "normals averaged over S times the mesh's bounding radius first (default 0.02; 0: none)"},
               {"json", "OUT", "the points and curves as JSON; - for standard output"},
               {"obj", "OUT", "the curves as OBJ polylines (l) and the points (p)"}},
              {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    ParabolicOptions options;
    if (const auto v = args.value("samples")) options.samples = parse_int("samples", *v, 24, 1000000);
    if (const auto v = args.value("smoothing"))
        options.smoothing = parse_closed_number("smoothing", *v, 0.0, 1.0, "a number from 0 to 1");
    const std::string mesh = args.positional()[0];
    const LoadedMesh loaded = load_mesh(mesh);
    const MeshTopology topology = engine_topology(loaded.mesh);
    Progress progress(0, ::isatty(2), "view steps");
    options.progress = [&](int done, int total) {
        progress.set_total(total);
        progress.update(done);
    };
    const ParabolicResult r = find_parabolic(topology, options);
    progress.finish();
    double length = 0.0;
    for (const ParabolicCurve& c : r.curves) length += c.length();
    if (const auto out = args.value("json")) {
        nlohmann::json points = nlohmann::json::array(), curves = nlohmann::json::array();
        for (const ParabolicPoint& p : r.points)
            points.push_back({{"kind", event_name(p.kind)}, {"where", vec(p.where)}, {"vertex", p.vertex.index()}, {"face", p.face.index()},
                              {"dir", vec(p.dir)}, {"from_dir", vec(p.from_dir)}, {"to_dir", vec(p.to_dir)},
                              {"confidence", p.confidence}});
        for (const ParabolicCurve& c : r.curves) {
            nlohmann::json pts = nlohmann::json::array();
            for (const glm::dvec3& p : c.points) pts.push_back(vec(p));
            curves.push_back({{"closed", c.closed}, {"length", c.length()}, {"points", pts}, {"edges", indices(c.edges)},
                               {"t", c.t}, {"faces", indices(c.faces)}});
        }
        const nlohmann::json doc = {{"mesh", mesh},           {"samples", r.samples}, {"walks", r.walks},
                                    {"faces", topology.n_faces()}, {"ms", r.ms}, {"smoothing_passes", r.smoothing_passes},
                                    {"events", r.events}, {"unplaced", r.unplaced},      {"points", points},
                                    {"curves", curves}};
        if (*out == "-") std::cout << doc.dump(1) << '\n';
        else write_file_atomically(*out, doc.dump(1) + "\n");
    }
    if (const auto out = args.value("obj")) write_file_atomically(*out, obj_text(r));
    if (args.value("json").value_or("") != "-")
        std::printf("%s: %d view directions in %d walks, normals smoothed in %d passes, %zu visual events (%zu unplaced), "
                    "%zu marked points, %zu curves (%.4g long), %.0f ms\n",
                    mesh.c_str(), r.samples, r.walks, r.smoothing_passes, r.events, r.unplaced, r.points.size(),
                    r.curves.size(), length, r.ms);
    return 0;
}

} // namespace snaxels::cli
