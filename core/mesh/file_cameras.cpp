#include "snaxels/mesh/file_cameras.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <pugixml.hpp>

#include "snaxels/error.h"
#include "snaxels/mesh/detail/assimp_scene.h"
#include "snaxels/mesh/isolated_import.h"

namespace snaxels {
namespace {

/// What a glTF file says of the camera on node @p node_name (its own
/// numbers: Assimp 5.2 keeps a glTF camera's vertical field of view only
/// multiplied by its aspect, and drops an orthographic camera's height).
bool gltf_framing(const nlohmann::json& doc, const std::string& node_name, FileCamera& cam) {
    if (doc.is_null() || !doc.contains("nodes") || !doc.contains("cameras") || !doc["cameras"].is_array())
        return false;
    const nlohmann::json& nodes = doc["nodes"];
    const nlohmann::json& cameras = doc["cameras"];
    auto framing = [&](const nlohmann::json& c) {
        if (!c.is_object()) return false;
        if (c.value("type", "") == "orthographic" && c.contains("orthographic")) {
            const nlohmann::json& o = c["orthographic"];
            const double xmag = std::abs(o.value("xmag", 0.0)), ymag = std::abs(o.value("ymag", 0.0));
            if (!(ymag > 0.0) || !std::isfinite(ymag)) return false;
            cam.orthographic = true;
            cam.ortho_height = 2.0 * ymag;
            cam.aspect = xmag > 0.0 && std::isfinite(xmag) ? xmag / ymag : 0.0;
            return true;
        }
        if (!c.contains("perspective") || !c["perspective"].is_object()) return false;
        const nlohmann::json& p = c["perspective"];
        const double yfov = p.value("yfov", 0.0);
        if (!(yfov > 0.0 && yfov < M_PI)) return false;
        cam.fov_deg = yfov * 180.0 / M_PI;
        const double aspect = p.value("aspectRatio", 0.0);
        cam.aspect = aspect > 0.0 && std::isfinite(aspect) ? aspect : 0.0;
        return true;
    };
    auto camera_of = [&](const nlohmann::json& node) -> const nlohmann::json* {
        if (!node.is_object() || !node.contains("camera")) return nullptr;
        const nlohmann::json& ref = node["camera"];
        if (ref.is_number_unsigned() && ref.get<std::size_t>() < cameras.size()) return &cameras[ref.get<std::size_t>()];
        return nullptr;
    };
    if (nodes.is_array()) {
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const nlohmann::json& node = nodes[i];
            // Assimp names an unnamed glTF 2 node by its index.
            const std::string name = node.is_object() && node.contains("name") && node["name"].is_string()
                                         ? node["name"].get<std::string>()
                                         : std::to_string(i);
            if (name != node_name) continue;
            if (const nlohmann::json* c = camera_of(node)) return framing(*c);
        }
    }
    return false;
}

/// What a Collada file says of an orthographic camera on node @p node_name
/// (Assimp 5.2 reads its half width as a field of view in degrees).
bool collada_ortho(const pugi::xml_document& dae, const std::string& node_name, FileCamera& cam) {
    const pugi::xml_node root = dae.child("COLLADA");
    if (!root) return false;
    std::string url;
    for (const pugi::xpath_node& n : root.select_nodes("//node[instance_camera]")) {
        const pugi::xml_node node = n.node();
        if (node_name == node.attribute("name").value() || node_name == node.attribute("id").value()) {
            url = node.child("instance_camera").attribute("url").value();
            break;
        }
    }
    if (url.size() < 2 || url[0] != '#') return false;
    for (const pugi::xml_node c : root.child("library_cameras").children("camera")) {
        if (url.compare(1, std::string::npos, c.attribute("id").value()) != 0) continue;
        const pugi::xml_node o = c.child("optics").child("technique_common").child("orthographic");
        if (!o) return false;
        const double xmag = o.child("xmag").text().as_double(0.0), ymag = o.child("ymag").text().as_double(0.0);
        const double aspect = o.child("aspect_ratio").text().as_double(0.0);
        cam.aspect = aspect > 0.0 ? aspect : xmag > 0.0 && ymag > 0.0 ? xmag / ymag : 0.0;
        const double height = ymag > 0.0 ? 2.0 * ymag : xmag > 0.0 && cam.aspect > 0.0 ? 2.0 * xmag / cam.aspect : 0.0;
        if (!(height > 0.0) || !std::isfinite(height)) return false;
        cam.orthographic = true;
        cam.ortho_height = height;
        return true;
    }
    return false;
}

/// What Assimp says of the camera (FBX, Collada and the rest): its field
/// of view is the whole horizontal angle (as the FBX and Collada readers
/// fill it), made vertical by the aspect.
void assimp_framing(const aiCamera& c, FileCamera& cam) {
    cam.aspect = c.mAspect > 0.0f && std::isfinite(c.mAspect) ? double(c.mAspect) : 0.0;
    if (c.mOrthographicWidth > 0.0f) {
        cam.orthographic = true;
        cam.ortho_height = 2.0 * double(c.mOrthographicWidth) / (cam.aspect > 0.0 ? cam.aspect : 1.0);
        return;
    }
    double h = double(c.mHorizontalFOV);
    if (!(h > 0.0 && h < M_PI)) h = 0.25 * M_PI * 2.0; // Assimp's default, taken as the whole angle
    cam.fov_deg = (cam.aspect > 0.0 ? 2.0 * std::atan(std::tan(0.5 * h) / cam.aspect) : h) * 180.0 / M_PI;
}

std::string clip_name(const aiScene* scene, unsigned a) {
    const std::string n = scene->mAnimations[a]->mName.C_Str();
    return n.empty() ? "clip" + std::to_string(a) : n;
}

/// Whether @p anim has keys for @p node or a node above it.
bool moves(const aiAnimation* anim, const aiNode* node) {
    for (const aiNode* n = node; n; n = n->mParent)
        for (unsigned c = 0; c < anim->mNumChannels; ++c)
            if (anim->mChannels[c]->mNodeName == n->mName) return true;
    return false;
}

const aiScene* read_scene(Assimp::Importer& importer, const std::string& path) {
    // With an isolated importer the helper reads the file first: one that
    // crashes the reader or overruns its limits is refused there.
    if (const std::string helper = mesh_importer(); !helper.empty()) detail::read_clips_isolated(helper, path);
    return detail::read_assimp_scene(importer, path);
}

std::string listed(const std::vector<std::string>& names) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    return list;
}

glm::dvec3 turned(const aiMatrix4x4& m, const aiVector3D& v, double w) {
    glm::dvec3 q{};
    for (unsigned r = 0; r < 3; ++r) q[r] = double(m[r][0]) * v.x + double(m[r][1]) * v.y + double(m[r][2]) * v.z + double(m[r][3]) * w;
    return q;
}

/// The camera in its node's space: where it stands, where it looks and its
/// up. A glTF camera is its node's origin looking down -Z with +Y up
/// (Assimp 5.2 also copies the node's translation into the camera's
/// position, which would count it twice).
struct LocalCamera {
    aiVector3D position, look, up;
};

LocalCamera local_camera(const aiCamera& c, bool gltf) {
    if (gltf) return {aiVector3D(0.0f, 0.0f, 0.0f), aiVector3D(0.0f, 0.0f, -1.0f), aiVector3D(0.0f, 1.0f, 0.0f)};
    return {c.mPosition, c.mLookAt, c.mUp};
}

/// Camera @p c of @p scene at @p ticks into @p anim (null: at rest).
Camera pose_camera(const aiScene* scene, const aiCamera& c, const LocalCamera& local, const FileCamera& info,
                   const aiAnimation* anim, double ticks) {
    const auto global = detail::node_transforms_at(scene, anim, ticks);
    const auto it = global.find(c.mName.C_Str());
    const aiMatrix4x4 g = it != global.end() ? it->second : aiMatrix4x4();
    Camera cam;
    cam.own_frame = true;
    cam.eye = turned(g, local.position, 1.0);
    glm::dvec3 forward = turned(g, local.look, 0.0), up = turned(g, local.up, 0.0);
    // The clip start as the file gives it, in the mesh's units: an FBX in
    // centimetres gives centimetres, though its camera's node scales by 100.
    cam.near_clip = info.orthographic ? 0.0 : info.clip_start;
    forward = glm::length(forward) > 0.0 ? glm::normalize(forward) : glm::dvec3(0.0, 0.0, -1.0);
    up -= glm::dot(up, forward) * forward;
    cam.up = glm::length(up) > 1e-12 ? glm::normalize(up) : glm::dvec3(0.0, 1.0, 0.0);
    if (info.orthographic) {
        cam.projection = Camera::Projection::Orthographic;
        cam.view_dir = forward;
        cam.ortho_height = info.ortho_height;
    } else {
        cam.projection = Camera::Projection::Perspective;
        cam.target = cam.eye + forward;
        cam.fov_deg = info.fov_deg;
    }
    return cam;
}

/// The cameras of @p scene read from @p path, whose glTF JSON (null for
/// another format) is @p gltf.
std::vector<FileCamera> cameras_of(const aiScene* scene, const std::string& path, const nlohmann::json& gltf) {
    pugi::xml_document dae;
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const bool collada = ext == ".dae" && scene->mNumCameras > 0 && dae.load_file(path.c_str());
    std::vector<FileCamera> out;
    for (unsigned i = 0; i < scene->mNumCameras; ++i) {
        const aiCamera& c = *scene->mCameras[i];
        FileCamera cam;
        cam.name = c.mName.C_Str();
        if (!gltf_framing(gltf, cam.name, cam) && !(collada && collada_ortho(dae, cam.name, cam))) assimp_framing(c, cam);
        if (!cam.orthographic && std::isfinite(c.mClipPlaneNear) && c.mClipPlaneNear > 0.0f)
            cam.clip_start = double(c.mClipPlaneNear);
        const aiAnimation* anim = nullptr;
        if (const aiNode* node = scene->mRootNode->FindNode(c.mName))
            for (unsigned a = 0; a < scene->mNumAnimations && !anim; ++a)
                if (moves(scene->mAnimations[a], node)) {
                    anim = scene->mAnimations[a];
                    cam.clip = clip_name(scene, a);
                    cam.clip_seconds = std::max(anim->mDuration, 0.0) / detail::ticks_per_second(anim);
                }
        cam.first = pose_camera(scene, c, local_camera(c, !gltf.is_null()), cam, anim, 0.0);
        out.push_back(std::move(cam));
    }
    return out;
}

} // namespace

bool may_hold_cameras(const std::string& path) {
    if (path.rfind("proc:", 0) == 0) return false;
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".off";
}

std::vector<FileCamera> file_cameras(const std::string& path) {
    Assimp::Importer importer;
    const aiScene* scene = read_scene(importer, path);
    return cameras_of(scene, path, detail::gltf_json(path));
}

struct CameraTrack::Impl {
    Assimp::Importer importer;
    const aiScene* scene = nullptr;
    const aiCamera* camera = nullptr;
    LocalCamera local;
    const aiAnimation* anim = nullptr;
    FileCamera info;
};

CameraTrack::CameraTrack(const std::string& path, const std::string& name, const std::string& clip)
    : impl_(std::make_unique<Impl>()) {
    impl_->scene = read_scene(impl_->importer, path);
    const aiScene* scene = impl_->scene;
    const nlohmann::json gltf = detail::gltf_json(path); // read once: framing and the camera's local frame
    const std::vector<FileCamera> cameras = cameras_of(scene, path, gltf);
    std::vector<std::string> names;
    for (const FileCamera& c : cameras) names.push_back(c.name);
    std::size_t chosen = cameras.size();
    for (std::size_t i = 0; i < cameras.size() && chosen == cameras.size(); ++i)
        if (cameras[i].name == name || std::to_string(i) == name) chosen = i;
    if (chosen == cameras.size())
        throw Error(path + (cameras.empty() ? ": has no cameras" : ": no camera '" + name + "' (it has: " + listed(names) + ")"));
    impl_->camera = scene->mCameras[chosen];
    impl_->info = cameras[chosen];
    impl_->local = local_camera(*impl_->camera, !gltf.is_null());
    // The clip that moves it: the one asked for (a camera it does not move
    // stands still), or the camera's own.
    std::vector<std::string> clips;
    for (unsigned a = 0; a < scene->mNumAnimations; ++a) clips.push_back(clip_name(scene, a));
    std::size_t index = clips.size();
    for (std::size_t a = 0; a < clips.size() && index == clips.size(); ++a)
        if (clip.empty() ? clips[a] == impl_->info.clip : clips[a] == clip || std::to_string(a) == clip) index = a;
    if (!clip.empty() && index == clips.size())
        throw Error(path + (clips.empty() ? ": has no animation clips" : ": no animation clip '" + clip + "' (it has: " + listed(clips) + ")"));
    const aiNode* node = scene->mRootNode->FindNode(impl_->camera->mName);
    if (index < clips.size() && node && moves(scene->mAnimations[index], node)) impl_->anim = scene->mAnimations[index];
    impl_->info.clip = impl_->anim ? clips[index] : "";
    impl_->info.clip_seconds = impl_->anim ? std::max(impl_->anim->mDuration, 0.0) / detail::ticks_per_second(impl_->anim) : 0.0;
}

CameraTrack::~CameraTrack() = default;
CameraTrack::CameraTrack(CameraTrack&&) noexcept = default;

const FileCamera& CameraTrack::info() const { return impl_->info; }

Camera CameraTrack::at(double seconds) const {
    const aiAnimation* anim = impl_->anim;
    double ticks = 0.0;
    if (anim) ticks = std::clamp(seconds * detail::ticks_per_second(anim), 0.0, std::max(anim->mDuration, 0.0));
    return pose_camera(impl_->scene, *impl_->camera, impl_->local, impl_->info, anim, ticks);
}

int canvas_height_for(const FileCamera& camera, int width, int height) {
    if (!(camera.aspect > 0.0)) return height;
    return std::clamp(int(std::lround(width / camera.aspect)), 16, 20000);
}

} // namespace snaxels
