// Checks drawings through a glTF 2.0 file's own camera standing inside its
// scene (tests/cli/near_plane_test.sh): at each frame given, the visible
// visual contour of the static frame the export wrote, and of the animated
// SVG as a player seeks it to the frame's time, against the oracle of
// tests/support/perspective_oracle.h (the file's triangles and camera read
// by the tests' own reader, a z-buffer cut at the camera's near plane).
//   near_plane_check SCENE.gltf CAMERA FPS FRAMES_DIR ANIMATED.svg MIN FRAME...
// FRAMES_DIR holds frame_NNNNN.svg; MIN is the least coverage and
// precision (0.95). Prints one line per frame; exits 1 if any falls short.
// With NEAR_PLANE_PICTURES set to a folder, each static frame's comparison
// is drawn there as frame_NNNNN.ppm.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "tests/support/perspective_oracle.h"
#include "tests/support/svg_player.h"

using namespace snaxels;
using namespace snaxels::test;

namespace {

/// The canvas size of an SVG (its width and height in pixels).
std::pair<int, int> canvas_of(const pugi::xml_document& doc) {
    const pugi::xml_node svg = doc.child("svg");
    return {std::atoi(svg.attribute("width").value()), std::atoi(svg.attribute("height").value())};
}

/// The strokes of <g id="visible"> at normalized time @p t (a static SVG: its paths).
std::vector<std::vector<glm::dvec2>> visible_strokes(const pugi::xml_document& doc, double t) {
    const pugi::xml_node visible = doc.child("svg").find_child_by_attribute("g", "id", "visible");
    std::vector<std::vector<svg::Pt>> subs;
    if (visible) svg::strokes_at(visible, t, subs);
    std::vector<std::vector<glm::dvec2>> out;
    for (const auto& sub : subs) {
        std::vector<glm::dvec2>& line = out.emplace_back();
        for (const svg::Pt& p : sub) line.push_back({p.x, p.y});
    }
    return out;
}

int frames_of(const pugi::xml_document& animated, double fps) {
    // The duration of every <animate>: frames over the rate.
    const pugi::xml_node a = animated.find_node([](pugi::xml_node n) { return std::string(n.name()) == "animate"; });
    return a ? int(std::lround(std::atof(a.attribute("dur").value()) * fps)) : 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 8) {
        std::fprintf(stderr, "usage: near_plane_check SCENE.gltf CAMERA FPS FRAMES_DIR ANIMATED.svg MIN FRAME...\n");
        return 2;
    }
    const std::string scene = argv[1], camera = argv[2], frames_dir = argv[4];
    const double fps = std::atof(argv[3]), min = std::atof(argv[6]);
    const ref::SceneMesh mesh = ref::read_gltf2(scene);
    pugi::xml_document animated;
    if (!animated.load_file(argv[5])) {
        std::fprintf(stderr, "cannot read %s\n", argv[5]);
        return 2;
    }
    const int frames = frames_of(animated, fps);
    bool ok = true;
    for (int i = 7; i < argc; ++i) {
        const int k = std::atoi(argv[i]);
        char name[64];
        std::snprintf(name, sizeof name, "/frame_%05d.svg", k);
        pugi::xml_document still;
        if (!still.load_file((frames_dir + name).c_str())) {
            std::fprintf(stderr, "cannot read %s%s\n", frames_dir.c_str(), name);
            return 2;
        }
        const auto [width, height] = canvas_of(still);
        const ref::SceneCamera cam = ref::read_gltf2_camera(scene, camera, k / fps);
        const perspective::View view(cam, width, height, cam.znear);
        std::vector<std::uint8_t> picture;
        const char* debug = std::getenv("NEAR_PLANE_PICTURES"); // a folder for frame_NNNNN.ppm: what was compared
        const perspective::Score a = perspective::score(mesh, view, visible_strokes(still, 0.0), debug ? &picture : nullptr);
        if (debug) {
            if (FILE* f = std::fopen((std::string(debug) + std::string(name).replace(std::string(name).size() - 3, 3, "ppm")).c_str(), "wb")) {
                std::fprintf(f, "P6 %d %d 255\n", width, height);
                std::fwrite(picture.data(), 1, picture.size(), f);
                std::fclose(f);
            }
        }
        const perspective::Score b = perspective::score(mesh, view, visible_strokes(animated, double(k) / frames));
        const bool pass = a.coverage() >= min && a.precision() >= min && b.coverage() >= min && b.precision() >= min;
        ok = ok && pass;
        std::printf("frame %3d: eye (%.2f, %.2f, %.2f); static %5.1f%% covered, %5.1f%% on the outline; animated at %.4f s %5.1f%%, "
                    "%5.1f%% (%zu silhouette samples)%s\n",
                    k, cam.eye.x, cam.eye.y, cam.eye.z, 100.0 * a.coverage(), 100.0 * a.precision(), k / fps,
                    100.0 * b.coverage(), 100.0 * b.precision(), a.silhouette, pass ? "" : "  FAILS");
    }
    return ok ? 0 : 1;
}
