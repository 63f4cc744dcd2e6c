// Writes the project-compatibility folder's projects for this version of
// the project format (tests/assets/projects/compat/README.md), with the
// writer the application saves with (write_project): run it once when the
// format changes, into compat/vN, then record what each renders
// (scripts/record-compat.sh does both).
//
//   record_compat_projects OUT_DIR STYLES_DIR

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "snaxels/project/project.h"

using namespace snaxels;

namespace {

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error("cannot read " + path);
    return text.str();
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: record_compat_projects OUT_DIR STYLES_DIR\n");
        return 2;
    }
    const std::string out = argv[1], styles = argv[2];
    try {
        // A turntable of a character in the faded pencil sketch, a light given.
        Project a;
        a.mesh = "../../../spot.obj";
        a.view.yaw = 0.6;
        a.view.pitch = 0.25;
        a.view.distance = 3.2;
        a.view.fov_deg = 35.0;
        Light la;
        la.dir = {-0.5, 1.0, 0.8};
        a.light = la;
        a.animation.kind = AnimationSpec::Kind::Turntable;
        a.animation.degrees_per_frame = 3.0;
        a.animation.frames = 24;
        a.animation.fps = 24.0;
        a.frame = 5;
        a.style = read(styles + "/pencil-sketch.xml");
        write_project(out + "/spot-pencil-turntable.snaxels", a);

        // A still of a Z-up scan in two tones under a point light.
        Project b;
        b.mesh = "../../../horse.ply";
        b.view.yaw = 2.2;
        b.view.pitch = 0.15;
        b.view.distance = 0.33;
        b.view.up = {0.0, 0.0, 1.0};
        Light lb;
        lb.point = true;
        lb.pos = {0.1, -0.25, 0.2};
        b.light = lb;
        b.style = read(styles + "/toon.xml");
        write_project(out + "/horse-toon-zup.snaxels", b);

        // A file's own clip at a frame of it, in shading lines.
        Project c;
        c.mesh = "../../../anim/morph-ball.gltf";
        c.view.yaw = -0.4;
        c.view.pitch = 0.3;
        c.view.distance = 6.0;
        c.animation.kind = AnimationSpec::Kind::Clip;
        c.animation.clip = "0";
        c.animation.frames = 30;
        c.animation.fps = 24.0;
        c.frame = 12;
        c.style = read(styles + "/shading-lines.xml");
        write_project(out + "/morph-ball-clip.snaxels", c);

        // A procedural mesh, the default style and light, a light orbit.
        Project d;
        d.mesh = "proc:nose:20000";
        d.view.yaw = 0.3;
        d.view.pitch = 0.1;
        d.view.distance = 5.2;
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
