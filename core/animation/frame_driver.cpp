#include "snaxels/animation/frame_driver.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/error.h"
#include "snaxels/mesh/import.h"

namespace snaxels {

FrameDriver::FrameDriver(const AnimationSpec& spec, const LoadedMesh& mesh, const MeshTopology& topology,
                         const Camera& camera, const Light& light, const glm::dvec3& centre,
                         const std::string& mesh_path)
    : spec_(spec), vertex_source_(mesh.vertex_source), rest_(topology), camera_(camera), light_(light),
      centre_(centre) {
    if (spec_.kind == AnimationSpec::Kind::Clip) clip_ = std::make_unique<MeshAnimation>(mesh_path, spec_.clip);
    if (spec_.kind == AnimationSpec::Kind::Camera && spec_.camera.empty())
        throw Error(mesh_path + ": a camera animation needs one of the file's cameras");
    if (!spec_.camera.empty()) {
        const bool shared_clip = spec_.kind == AnimationSpec::Kind::Clip || spec_.kind == AnimationSpec::Kind::Camera;
        track_ = std::make_unique<CameraTrack>(mesh_path, spec_.camera, shared_clip ? spec_.clip : "");
        camera_ = file_camera_at(*track_, spec_.start / spec_.fps, centre_);
    }
    if (spec_.kind == AnimationSpec::Kind::Sequence) {
        if (spec_.first_file < 0) {
            // Numbering starts at 0 or 1, whichever file exists.
            std::error_code ec;
            spec_.first_file = 0;
            const std::string zero = sequence_path(0);
            if (!std::filesystem::exists(zero, ec)) {
                spec_.first_file = 1;
                if (!std::filesystem::exists(sequence_path(0), ec))
                    throw Error(spec_.pattern + ": no file of the sequence (neither " + zero + " nor " +
                                sequence_path(0) + " exists)");
            }
        }
        soup_size_ = read_triangle_soup(sequence_path(0)).positions.size();
    }
}

FrameDriver::~FrameDriver() = default;

std::optional<SequenceFiles> find_sequence(const std::string& file) {
    const std::filesystem::path path(file);
    // The last run of digits in the name (its extension has none that count).
    const std::string stem = path.stem().string();
    auto end = stem.find_last_of("0123456789");
    if (end == std::string::npos) return std::nullopt;
    auto begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    ++end;
    const std::size_t width = end - begin;
    if (width > 9) return std::nullopt;
    const int number = std::stoi(stem.substr(begin, width));
    const std::string prefix = stem.substr(0, begin), suffix = stem.substr(end) + path.extension().string();
    // Numbers written without leading zeros (frame_7, frame_10) use %d.
    const bool padded = width > 1 && stem[begin] == '0';
    const std::string marker = padded ? std::string(width, '#') : std::string("%d");
    std::error_code ec;
    SequenceFiles s;
    s.pattern = (path.parent_path() / (prefix + marker + suffix)).string();
    AnimationSpec numbered; // file k of the series is frame k counted from 0
    numbered.pattern = s.pattern;
    numbered.first_file = 0;
    auto file_of = [&](int k) { return sequence_file(numbered, k); };
    s.first_file = number;
    while (s.first_file > 0 && std::filesystem::is_regular_file(file_of(s.first_file - 1), ec)) --s.first_file;
    int last = number;
    while (std::filesystem::is_regular_file(file_of(last + 1), ec)) ++last;
    s.count = last - s.first_file + 1;
    return s;
}

bool FrameDriver::mesh_moves() const {
    return spec_.kind == AnimationSpec::Kind::Clip || spec_.kind == AnimationSpec::Kind::Sequence;
}

std::string FrameDriver::sequence_path(int k) const { return sequence_file(spec_, k); }

std::string sequence_file(const AnimationSpec& spec, int k) {
    int first_number = spec.first_file;
    if (first_number < 0) {
        // Numbering starts at 0 or 1, whichever file exists.
        AnimationSpec zero = spec;
        zero.first_file = 0;
        std::error_code ec;
        first_number = std::filesystem::exists(sequence_file(zero, 0), ec) ? 0 : 1;
    }
    const int number = first_number + k;
    std::string path = spec.pattern;
    if (const auto pct = path.find('%'); pct != std::string::npos) {
        char buf[4096];
        std::snprintf(buf, sizeof buf, path.c_str(), number);
        return buf;
    }
    const auto first = path.find('#');
    if (first == std::string::npos) return path;
    auto last = first;
    while (last < path.size() && path[last] == '#') ++last;
    std::string digits = std::to_string(number);
    if (digits.size() < last - first) digits.insert(0, last - first - digits.size(), '0');
    return path.substr(0, first) + digits + path.substr(last);
}

Light light_at_frame(const AnimationSpec& spec, const Light& light, double source_frame, const glm::dvec3& axis,
                     const glm::dvec3& centre) {
    const double angle = glm::radians(spec.degrees_per_frame * source_frame);
    Light out = light;
    if (spec.kind == AnimationSpec::Kind::Turntable && !light.point) {
        out.dir = glm::rotate(light.dir, angle, axis); // lit from the same side
    } else if (spec.kind == AnimationSpec::Kind::LightOrbit) {
        if (light.point) out.pos = centre + glm::rotate(light.pos - centre, angle, axis);
        else out.dir = glm::rotate(light.dir, angle, axis);
    }
    return out;
}

Camera file_camera_at(const CameraTrack& track, double seconds, const glm::dvec3& centre) {
    Camera c = track.at(seconds);
    // Aimed at the orbited point's depth, so a turntable turns it about a
    // point before it, not about its own eye.
    if (!c.orthographic()) c.target = c.eye + c.forward() * std::max(glm::dot(centre - c.eye, c.forward()), 1e-9);
    return c;
}

glm::dvec3 turntable_axis(const Camera& camera, const CameraTrack* track) {
    // A file's camera turns about the model's up (its own up is the
    // picture's, tilted with it); the view's camera's up is the model's.
    return track ? glm::dvec3(0.0, 1.0, 0.0) : glm::normalize(camera.up);
}

Camera camera_at_frame(const AnimationSpec& spec, const Camera& camera, const CameraTrack* track, int source_frame,
                       const glm::dvec3& centre) {
    Camera out = track ? file_camera_at(*track, source_frame / spec.fps, centre) : camera;
    if (spec.kind != AnimationSpec::Kind::Turntable) return out;
    // The camera orbits the target about the up axis, as on a turntable.
    const Camera base = out;
    const double angle = glm::radians(spec.degrees_per_frame * source_frame);
    const glm::dvec3 axis = turntable_axis(camera, track);
    if (out.orthographic()) {
        out.view_dir = glm::rotate(base.view_dir, angle, axis);
        out.eye = centre + glm::rotate(base.eye - centre, angle, axis); // a file's framing camera
    } else {
        out.eye = base.target + glm::rotate(base.eye - base.target, angle, axis);
    }
    if (track) out.up = glm::rotate(base.up, angle, axis);
    return out;
}

int animation_frame_count(const AnimationSpec& spec, const std::string& mesh_path) {
    int frames = spec.frames;
    if (frames <= 0 && spec.kind == AnimationSpec::Kind::Clip) {
        const MeshAnimation clip(mesh_path, spec.clip);
        frames = clip_frame_count(clip.duration(), spec.fps) - spec.start;
    } else if (frames <= 0 && spec.kind == AnimationSpec::Kind::Camera) {
        const CameraTrack track(mesh_path, spec.camera, spec.clip);
        frames = clip_frame_count(track.info().clip_seconds, spec.fps) - spec.start;
    }
    return std::max(frames, 1);
}

FramePose FrameDriver::pose(int k) {
    FramePose out{camera_, light_, rest_};
    k += spec_.start;
    out.camera = camera_at_frame(spec_, camera_, track_.get(), k, centre_);
    const glm::dvec3 axis = turntable_axis(camera_, track_.get());
    switch (spec_.kind) {
    case AnimationSpec::Kind::Turntable:
        out.light = light_at_frame(spec_, light_, double(k), axis, centre_);
        break;
    case AnimationSpec::Kind::LightOrbit: out.light = light_at_frame(spec_, light_, double(k), axis, centre_); break;
    case AnimationSpec::Kind::Clip:
    case AnimationSpec::Kind::Sequence: out.mesh = mesh_pose(k); break;
    case AnimationSpec::Kind::Still:
    case AnimationSpec::Kind::Camera: break;
    }
    return out;
}

MeshTopology FrameDriver::mesh_pose(int k) {
    std::vector<glm::dvec3> positions(rest_.n_base_vertices());
    if (spec_.kind == AnimationSpec::Kind::Clip) {
        clip_->pose(double(k) / spec_.fps, soup_);
        for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = soup_[vertex_source_[v]];
    } else {
        const std::string path = sequence_path(k);
        const TriangleSoup soup = read_triangle_soup(path);
        if (soup.positions.size() != soup_size_)
            throw Error(path + ": has " + std::to_string(soup.positions.size()) +
                        " vertices where the sequence's first file has " + std::to_string(soup_size_) +
                        " (every file must share one connectivity)");
        for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = soup.positions[vertex_source_[v]];
        for (const auto& p : positions)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw Error(path + ": a vertex has a non-finite coordinate");
    }
    return rest_.posed(std::make_shared<const MeshPose>(make_pose(*rest_.connectivity(), std::move(positions))));
}

} // namespace snaxels
