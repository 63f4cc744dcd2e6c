// Writes the project-compatibility folder's projects for this version of
// the project format (tests/assets/projects/compat/README.md), with the
// writer the application saves with (write_project): run it once when the
// format changes, into compat/vN, then record what each renders
// (scripts/record-compat.sh does both).
//
//   record_compat_projects OUT_DIR STYLES_DIR

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "snaxels/project/project.h"

using namespace snaxels;

namespace {

/// The text of the preset @p name in @p dir.
std::string preset(const std::filesystem::path& dir, const char* name) {
    const std::filesystem::path path = dir / name;
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return text.str();
}

/// A project of @p mesh seen from the orbit (yaw, pitch, distance), in @p style.
Project seen(const std::string& mesh, double yaw, double pitch, double distance, std::string style) {
    Project p;
    p.mesh = mesh;
    p.view.yaw = yaw;
    p.view.pitch = pitch;
    p.view.distance = distance;
    p.style = std::move(style);
    return p;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: record_compat_projects OUT_DIR STYLES_DIR\n");
        return 2;
    }
    const std::string out = argv[1];
    const std::filesystem::path styles = argv[2];
    try {
        // A turntable of a character in the faded pencil sketch, a light given.
        Project a = seen("../../../spot.obj", 0.6, 0.25, 3.2, preset(styles, "pencil-sketch.xml"));
        a.view.fov_deg = 35.0;
        Light la;
        la.dir = {-0.5, 1.0, 0.8};
        a.light = la;
        a.animation.kind = AnimationSpec::Kind::Turntable;
        a.animation.degrees_per_frame = 3.0;
        a.animation.frames = 24;
        a.animation.fps = 24.0;
        a.frame = 5;
        write_project(out + "/spot-pencil-turntable.snaxels", a);

        // A still of a Z-up scan in two tones under a point light.
        Project b = seen("../../../horse.ply", 2.2, 0.15, 0.33, preset(styles, "toon.xml"));
        b.view.up = {0.0, 0.0, 1.0};
        Light lb;
        lb.point = true;
        lb.pos = {0.1, -0.25, 0.2};
        b.light = lb;
        write_project(out + "/horse-toon-zup.snaxels", b);

        // A file's own clip at a frame of it, in shading lines.
        Project c = seen("../../../anim/morph-ball.gltf", -0.4, 0.3, 6.0, preset(styles, "shading-lines.xml"));
        c.animation.kind = AnimationSpec::Kind::Clip;
        c.animation.clip = "0";
        c.animation.frames = 30;
        c.animation.fps = 24.0;
        c.frame = 12;
        write_project(out + "/morph-ball-clip.snaxels", c);

        // A procedural mesh, the default style and light, a light orbit.
        Project d = seen("proc:nose:20000", 0.3, 0.1, 5.2, "");
        d.animation.kind = AnimationSpec::Kind::LightOrbit;
        d.animation.degrees_per_frame = 10.0;
        d.animation.frames = 12;
        d.frame = 4;
        write_project(out + "/nose-default-light-orbit.snaxels", d);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "record_compat_projects: %s\n", e.what());
        return 1;
    }
    return 0;
}
