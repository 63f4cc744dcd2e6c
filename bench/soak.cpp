// snaxels-soak: a long random walk of camera, light and a skinned clip on the
// procedural nose, tracking four contour kinds frame after frame as an
// export does. Every frame the engine checks its invariants (check_fronts)
// and this program checks the trackers' identities; every 100th frame the
// tracked contours must equal a from-scratch computation; at the end the
// resident memory must be within 10% of what it was at frame 1,000.
//   snaxels-soak [--frames N] [--faces F] [--seed S]
// Exits 0 when everything held, 1 otherwise; prints the figures either way.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/mesh/topology.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/util/memory.h"

using namespace snaxels;

namespace {

double resident_mb() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    long pages = 0, resident = 0;
    if (f) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return double(resident) * double(::sysconf(_SC_PAGE_SIZE)) / (1024.0 * 1024.0);
}

// The clip: two joints of linear-blend skinning. The head nods about the
// x axis through the neck (weights rising with y) and turns about the y axis
// (weights rising toward the nose, +z), on incommensurate periods.
void pose(const std::vector<glm::dvec3>& rest, double seconds, std::vector<glm::dvec3>& out) {
    const double nod = 0.35 * std::sin(2.0 * M_PI * seconds / 3.0);
    const double turn = 0.5 * std::sin(2.0 * M_PI * seconds / 4.7);
    const double cn = std::cos(nod), sn = std::sin(nod), ct = std::cos(turn), st = std::sin(turn);
    auto smooth = [](double lo, double hi, double x) {
        const double u = std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
        return u * u * (3.0 - 2.0 * u);
    };
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const glm::dvec3 p = rest[i];
        const glm::dvec3 nodded(p.x, cn * p.y - sn * p.z, sn * p.y + cn * p.z);
        const double wn = smooth(-0.4, 0.4, p.y);
        const glm::dvec3 a = (1.0 - wn) * p + wn * nodded;
        const glm::dvec3 turned(ct * a.x + st * a.z, a.y, -st * a.x + ct * a.z);
        const double wt = smooth(-0.2, 0.6, p.z);
        out[i] = (1.0 - wt) * a + wt * turned;
    }
}

using Crossings = std::vector<std::tuple<EdgeId, VertexId, double>>;

Crossings crossings(const ContourResult& r) {
    Crossings out;
    for (const Snaxel& s : r.fronts.snaxels) out.emplace_back(s.edge, s.inside, s.t);
    std::sort(out.begin(), out.end());
    return out;
}

// Empty when the tracked and the fresh contour are the same zero set.
std::string compare(const ContourResult& tracked, const ContourResult& fresh) {
    const Crossings a = crossings(tracked), b = crossings(fresh);
    if (a.size() != b.size())
        return std::to_string(a.size()) + " tracked snaxels, " + std::to_string(b.size()) + " from scratch";
    if (tracked.fronts.loops.size() != fresh.fronts.loops.size())
        return std::to_string(tracked.fronts.loops.size()) + " tracked loops, " +
               std::to_string(fresh.fronts.loops.size()) + " from scratch";
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::get<0>(a[i]) != std::get<0>(b[i]) || std::get<1>(a[i]) != std::get<1>(b[i]))
            return "a snaxel on another edge";
        if (std::abs(std::get<2>(a[i]) - std::get<2>(b[i])) > 1e-9) return "a snaxel elsewhere on its edge";
    }
    return {};
}

// Empty when the frame's identities are sound: every snaxel has a non-zero
// id, no two share one, and no two loops share a sequence.
std::string check_identities(const TrackedFrame& f) {
    std::set<std::uint64_t> ids;
    for (const std::uint64_t id : f.snaxel_id) {
        if (id == 0) return "a snaxel without an id";
        if (!ids.insert(id).second) return "two snaxels with one id";
    }
    std::set<std::uint64_t> sequences(f.loop_sequence.begin(), f.loop_sequence.end());
    if (sequences.size() != f.loop_sequence.size()) return "two loops in one sequence";
    if (f.snaxel_id.size() != f.contour.fronts.snaxels.size()) return "ids not parallel to the snaxels";
    return {};
}

} // namespace

int main(int argc, char** argv) {
    snaxels::tune_allocator();
    int frames = 10000;
    std::size_t faces = 20000;
    unsigned seed = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--frames") frames = std::max(1, std::atoi(argv[i + 1]));
        else if (a == "--faces") faces = std::size_t(std::max(1000, std::atoi(argv[i + 1])));
        else if (a == "--seed") seed = unsigned(std::atoi(argv[i + 1]));
        else {
            std::fprintf(stderr, "usage: snaxels-soak [--frames N] [--faces F] [--seed S]\n");
            return 2;
        }
    }
    try {
        const LoadedMesh mesh = build_mesh(make_procedural("nose:" + std::to_string(faces)), "proc:nose");
        const MeshTopology rest_topology = engine_topology(mesh.mesh, 0);
        MeshTopology topology = rest_topology;
        const std::vector<glm::dvec3> rest(rest_topology.positions().begin(), rest_topology.positions().end());
        std::vector<glm::dvec3> posed(rest.size());
        EngineOptions options;
        options.check_invariants = true;
        const std::vector<ContourSpec> kinds{ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0},
                                             ContourSpec{ContourKind::Isophote, 0.5},
                                             ContourSpec{ContourKind::Gleam, 0.9}};
        std::vector<ContourTracker> trackers;
        trackers.reserve(kinds.size());
        for (const ContourSpec& k : kinds) trackers.emplace_back(rest_topology, k, options);

        std::mt19937 rng(seed);
        std::normal_distribution<double> step(0.0, 1.0);
        double yaw = 0.3, pitch = 0.2, light_yaw = -0.8, light_pitch = 0.6;
        const double fps = 30.0;
        double memory_at_1000 = 0.0, ms = 0.0;
        int compared = 0, failures = 0;
        std::size_t snaxels = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < frames; ++k) {
            // The walk: up to about a degree a frame, the pitch kept off the poles.
            yaw += 0.012 * step(rng);
            pitch = std::clamp(pitch + 0.008 * step(rng), -1.2, 1.2);
            light_yaw += 0.015 * step(rng);
            light_pitch = std::clamp(light_pitch + 0.01 * step(rng), -1.3, 1.3);
            pose(rest, k / fps, posed);
            topology = rest_topology.posed(std::make_shared<const MeshPose>(make_pose(*rest_topology.connectivity(), posed)));
            Camera camera;
            camera.projection = Camera::Projection::Perspective;
            camera.eye = 4.0 * glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
            camera.target = glm::dvec3(0.0);
            Light light;
            light.dir = glm::dvec3(std::cos(light_pitch) * std::sin(light_yaw), std::sin(light_pitch),
                                   std::cos(light_pitch) * std::cos(light_yaw));
            const auto t0 = std::chrono::steady_clock::now();
            for (std::size_t c = 0; c < trackers.size(); ++c) {
                const TrackedFrame& f = trackers[c].step(topology, camera, light);
                snaxels += f.contour.fronts.snaxels.size();
                if (const std::string why = check_identities(f); !why.empty()) {
                    std::fprintf(stderr, "frame %d, %s: %s\n", k, kinds[c].label().c_str(), why.c_str());
                    ++failures;
                }
            }
            ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (k % 100 == 99) {
                const SnaxelEngine engine(topology);
                for (std::size_t c = 0; c < trackers.size(); ++c) {
                    const ContourResult fresh = engine.compute(kinds[c], camera, light, options);
                    if (const std::string why = compare(trackers[c].current().contour, fresh); !why.empty()) {
                        std::fprintf(stderr, "frame %d, %s: tracked differs from scratch: %s\n", k,
                                     kinds[c].label().c_str(), why.c_str());
                        ++failures;
                    }
                    ++compared;
                }
            }
            if (k == 999) memory_at_1000 = resident_mb();
            if (k % 1000 == 999)
                std::fprintf(stderr, "frame %d: %.2f ms a frame for the four kinds, %.1f MB resident\n", k + 1,
                             ms / (k + 1), resident_mb());
        }
        const double memory_end = resident_mb();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const bool memory_ok = frames < 1000 || memory_end <= 1.1 * memory_at_1000;
        std::printf("soak: %d frames of proc:nose:%zu (%zu faces), 4 kinds, seed %u, in %.1f s\n", frames, faces,
                    topology.n_faces(), seed, seconds);
        std::printf("  tracking: %.2f ms a frame for the four kinds, %.0f snaxels a frame on average\n",
                    ms / frames, double(snaxels) / frames);
        std::printf("  invariants checked every frame; %d comparisons with a computation from scratch, %d failures\n",
                    compared, failures);
        if (frames >= 1000)
            std::printf("  resident memory: %.1f MB at frame 1,000, %.1f MB at the end (%+.1f%%)%s\n", memory_at_1000,
                        memory_end, 100.0 * (memory_end / memory_at_1000 - 1.0), memory_ok ? "" : ": OVER 10%");
        return failures == 0 && memory_ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "soak: %s\n", e.what());
        return 1;
    }
}
