#include "snaxels/project/project.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "snaxels/error.h"
#include "snaxels/util/atomic_file.h"

namespace snaxels {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kFormat = "snaxels-project";
// 2: view.up (the model's up axis); version 1 files are +Y up.
constexpr int kVersion = 2;

struct Kinds {
    AnimationSpec::Kind kind;
    const char* name;
};
constexpr Kinds kKinds[] = {{AnimationSpec::Kind::Still, "still"},
                            {AnimationSpec::Kind::Turntable, "turntable"},
                            {AnimationSpec::Kind::LightOrbit, "light-orbit"},
                            {AnimationSpec::Kind::Clip, "clip"},
                            {AnimationSpec::Kind::Sequence, "sequence"},
                            {AnimationSpec::Kind::Camera, "camera"}};

json vec(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

/// Reads fields of one JSON object, naming the file and the field in errors.
class Reader {
  public:
    Reader(const std::string& file, const json& object, std::string where)
        : file_(file), object_(object), where_(std::move(where)) {
        if (!object_.is_object()) fail(where_.empty() ? "is not a JSON object" : "is not an object");
    }
    bool has(const char* key) const { return object_.contains(key) && !object_.at(key).is_null(); }
    const json& at(const char* key) const {
        if (!has(key)) fail_field(key, "is missing");
        return object_.at(key);
    }
    double number(const char* key) const {
        const json& v = at(key);
        if (!v.is_number() || !std::isfinite(v.get<double>())) fail_field(key, "must be a finite number");
        return v.get<double>();
    }
    double number(const char* key, double lo, double hi) const {
        const double v = number(key);
        if (!(v >= lo && v <= hi)) {
            std::ostringstream msg;
            msg << "must lie between " << lo << " and " << hi;
            fail_field(key, msg.str());
        }
        return v;
    }
    int integer(const char* key, int lo, int hi) const {
        const json& v = at(key);
        if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
            fail_field(key, "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
        return int(v.get<long long>());
    }
    std::string string(const char* key) const {
        const json& v = at(key);
        if (!v.is_string()) fail_field(key, "must be a string");
        return v.get<std::string>();
    }
    glm::dvec3 vec3(const char* key) const {
        const json& v = at(key);
        if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
            fail_field(key, "must be an array of three numbers");
        const glm::dvec3 r(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
        if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z)) fail_field(key, "must be finite");
        return r;
    }
    Reader object(const char* key) const { return Reader(file_, at(key), path(key)); }
    [[noreturn]] void fail_field(const char* key, const std::string& what) const {
        throw Error(file_ + ": \"" + path(key) + "\" " + what);
    }
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(file_ + ": " + (where_.empty() ? "" : "\"" + where_ + "\" ") + what);
    }

  private:
    std::string path(const char* key) const { return where_.empty() ? key : where_ + "." + key; }
    const std::string& file_;
    const json& object_;
    std::string where_;
};

} // namespace

std::string project_text(const Project& p) {
    json anim{{"source", ""}, {"frames", p.animation.frames}, {"start", p.animation.start}, {"fps", p.animation.fps}};
    for (const Kinds& k : kKinds)
        if (k.kind == p.animation.kind) anim["source"] = k.name;
    if (p.animation.kind == AnimationSpec::Kind::Turntable || p.animation.kind == AnimationSpec::Kind::LightOrbit)
        anim["degrees_per_frame"] = p.animation.degrees_per_frame;
    if (p.animation.kind == AnimationSpec::Kind::Clip || p.animation.kind == AnimationSpec::Kind::Camera)
        anim["clip"] = p.animation.clip;
    if (!p.animation.camera.empty()) anim["camera"] = p.animation.camera;
    if (p.animation.kind == AnimationSpec::Kind::Sequence) {
        anim["pattern"] = p.animation.pattern;
        anim["first_file"] = p.animation.first_file;
    }
    json light = nullptr;
    if (p.light) light = p.light->point ? json{{"pos", vec(p.light->pos)}} : json{{"dir", vec(p.light->dir)}};
    json view{{"yaw", p.view.yaw},
              {"pitch", p.view.pitch},
              {"distance", p.view.distance},
              {"pan", vec(p.view.pan)},
              {"up", vec(p.view.up)},
              {"fov_deg", p.view.fov_deg}};
    // Written only when set, so a perspective project's text is as before.
    if (p.view.orthographic) view["projection"] = "orthographic";
    const json doc{{"format", kFormat},
                   {"version", kVersion},
                   {"mesh", p.mesh},
                   {"view", view},
                   {"light", light},
                   {"animation", anim},
                   {"frame", p.frame},
                   {"style", p.style}};
    return doc.dump(2) + "\n";
}

void write_project(const std::string& path, const Project& project) {
    write_file_atomically(path, project_text(project));
}

Project read_project(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw Error(path + ": is a directory, not a project file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open (" + std::string(std::strerror(errno)) + ")");
    std::stringstream buffer;
    buffer << in.rdbuf();
    json doc;
    try {
        doc = json::parse(buffer.str());
    } catch (const json::parse_error& e) {
        // nlohmann's message carries the line and column.
        std::string what = e.what();
        if (const auto colon = what.find("parse error"); colon != std::string::npos) what = what.substr(colon);
        throw Error(path + ": not a snaxels project (" + what + ")");
    } catch (const json::exception& e) {
        // A number past double's range (1e400), say: found by fuzz_project.
        std::string what = e.what();
        if (const auto bracket = what.find("] "); bracket != std::string::npos) what = what.substr(bracket + 2);
        throw Error(path + ": not a snaxels project (" + what + ")");
    }
    const Reader top(path, doc, "");
    if (!top.has("format") || !doc.at("format").is_string() || doc.at("format").get<std::string>() != kFormat)
        top.fail("is not a snaxels project (no \"format\": \"snaxels-project\")");
    const int version = top.integer("version", 1, 1 << 20);
    if (version > kVersion)
        top.fail("was written by a newer snaxels (project version " + std::to_string(version) +
                 "; this one reads up to " + std::to_string(kVersion) + ")");

    Project p;
    p.mesh = top.string("mesh");
    if (p.mesh.empty()) top.fail_field("mesh", "is empty");
    const Reader view = top.object("view");
    p.view.yaw = view.number("yaw");
    p.view.pitch = view.number("pitch", -M_PI_2, M_PI_2);
    p.view.distance = view.number("distance");
    if (!(p.view.distance > 0.0)) view.fail_field("distance", "must be positive");
    p.view.pan = view.vec3("pan");
    if (view.has("up")) {
        p.view.up = view.vec3("up");
        // Kept as written (the orbit normalizes it), so a project reads back exactly.
        if (!(glm::length(p.view.up) > 1e-9)) view.fail_field("up", "must be a direction, not zero");
    }
    if (view.has("fov_deg")) p.view.fov_deg = view.number("fov_deg", 1.0, 179.0);
    if (view.has("projection")) {
        const std::string projection = view.string("projection");
        if (projection != "orthographic" && projection != "perspective")
            view.fail_field("projection", "must be orthographic or perspective (not \"" + projection + "\")");
        p.view.orthographic = projection == "orthographic";
    }
    if (top.has("light")) {
        const Reader light = top.object("light");
        Light l;
        if (light.has("pos")) {
            l.point = true;
            l.pos = light.vec3("pos");
        } else {
            l.dir = light.vec3("dir");
            if (glm::length(l.dir) < 1e-12) light.fail_field("dir", "must not be the zero vector");
        }
        p.light = l;
    }
    const Reader anim = top.object("animation");
    const std::string source = anim.string("source");
    bool known = false;
    for (const Kinds& k : kKinds)
        if (source == k.name) p.animation.kind = k.kind, known = true;
    if (!known)
        anim.fail_field("source", "must be one of still, turntable, light-orbit, clip, sequence, camera (not \"" + source + "\")");
    p.animation.frames = anim.integer("frames", 0, 100000);
    p.animation.fps = anim.number("fps", 1e-3, 1000.0);
    if (anim.has("start")) p.animation.start = anim.integer("start", 0, 1000000);
    if (anim.has("degrees_per_frame")) p.animation.degrees_per_frame = anim.number("degrees_per_frame", -360.0, 360.0);
    if (anim.has("clip")) p.animation.clip = anim.string("clip");
    if (anim.has("camera")) p.animation.camera = anim.string("camera");
    if (p.animation.kind == AnimationSpec::Kind::Camera && p.animation.camera.empty())
        anim.fail_field("camera", "must name one of the file's cameras for a camera animation");
    if (p.animation.kind == AnimationSpec::Kind::Sequence) {
        p.animation.pattern = anim.string("pattern");
        if (anim.has("first_file")) p.animation.first_file = anim.integer("first_file", -1, 1 << 30);
    }
    if (p.animation.kind != AnimationSpec::Kind::Clip && p.animation.kind != AnimationSpec::Kind::Camera &&
        p.animation.frames < 1)
        anim.fail_field("frames", "must be at least 1");
    p.frame = top.has("frame") ? top.integer("frame", 0, 100000) : 0;
    p.style = top.has("style") ? top.string("style") : std::string();
    return p;
}

std::string project_mesh_reference(const std::string& project_path, const std::string& mesh_path) {
    if (mesh_path.rfind("proc:", 0) == 0) return mesh_path;
    std::error_code ec;
    const fs::path folder = fs::absolute(fs::path(project_path), ec).parent_path();
    const fs::path mesh = fs::absolute(fs::path(mesh_path), ec).lexically_normal();
    const fs::path relative = mesh.lexically_relative(folder);
    if (relative.empty()) return mesh.generic_string(); // another root: keep it absolute
    return relative.generic_string();
}

std::string resolve_project_mesh(const std::string& project_path, const std::string& reference) {
    if (reference.rfind("proc:", 0) == 0) return reference;
    const fs::path ref(reference);
    if (ref.is_absolute()) return ref.lexically_normal().string();
    std::error_code ec;
    const fs::path folder = fs::absolute(fs::path(project_path), ec).parent_path();
    return (folder / ref).lexically_normal().string();
}

} // namespace snaxels
