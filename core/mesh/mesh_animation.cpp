#include "snaxels/mesh/mesh_animation.h"

#include <cmath>
#include <functional>
#include <map>

#include "snaxels/error.h"
#include "snaxels/mesh/detail/assimp_scene.h"
#include "snaxels/mesh/isolated_import.h"

namespace snaxels {
namespace {

template <class Key> std::size_t key_before(const Key* keys, unsigned n, double t) {
    std::size_t i = 0;
    while (i + 1 < n && keys[i + 1].mTime <= t) ++i;
    return i;
}

aiVector3D lerp_keys(const aiVectorKey* keys, unsigned n, double t) {
    const std::size_t i = key_before(keys, n, t);
    if (i + 1 >= n || t <= keys[i].mTime) return keys[i].mValue;
    const double u = (t - keys[i].mTime) / (keys[i + 1].mTime - keys[i].mTime);
    return keys[i].mValue + (keys[i + 1].mValue - keys[i].mValue) * float(u);
}

aiQuaternion slerp_keys(const aiQuatKey* keys, unsigned n, double t) {
    const std::size_t i = key_before(keys, n, t);
    if (i + 1 >= n || t <= keys[i].mTime) return keys[i].mValue;
    const double u = (t - keys[i].mTime) / (keys[i + 1].mTime - keys[i].mTime);
    aiQuaternion q;
    aiQuaternion::Interpolate(q, keys[i].mValue, keys[i + 1].mValue, float(u));
    return q.Normalize();
}

glm::dvec3 transform(const aiMatrix4x4& m, const aiVector3D& p) {
    glm::dvec3 q{};
    for (int r = 0; r < 3; ++r)
        q[r] = double(m[r][0]) * p.x + double(m[r][1]) * p.y + double(m[r][2]) * p.z + double(m[r][3]);
    return q;
}

} // namespace

std::map<std::string, aiMatrix4x4> detail::node_transforms_at(const aiScene* scene, const aiAnimation* anim,
                                                               double t) {
    std::map<std::string, const aiNodeAnim*> channel;
    if (anim)
        for (unsigned c = 0; c < anim->mNumChannels; ++c) channel[anim->mChannels[c]->mNodeName.C_Str()] = anim->mChannels[c];
    std::map<std::string, aiMatrix4x4> global;
    std::function<void(const aiNode*, const aiMatrix4x4&)> walk = [&](const aiNode* node, const aiMatrix4x4& parent) {
        aiMatrix4x4 local = node->mTransformation;
        if (const auto it = channel.find(node->mName.C_Str()); it != channel.end()) {
            const aiNodeAnim* ch = it->second;
            aiVector3D scale(1, 1, 1), pos;
            aiQuaternion rot;
            node->mTransformation.Decompose(scale, rot, pos);
            if (ch->mNumScalingKeys) scale = lerp_keys(ch->mScalingKeys, ch->mNumScalingKeys, t);
            if (ch->mNumRotationKeys) rot = slerp_keys(ch->mRotationKeys, ch->mNumRotationKeys, t);
            if (ch->mNumPositionKeys) pos = lerp_keys(ch->mPositionKeys, ch->mNumPositionKeys, t);
            local = aiMatrix4x4(scale, rot, pos);
        }
        const aiMatrix4x4 g = parent * local;
        global[node->mName.C_Str()] = g;
        for (unsigned c = 0; c < node->mNumChildren; ++c) walk(node->mChildren[c], g);
    };
    walk(scene->mRootNode, aiMatrix4x4());
    return global;
}

double detail::ticks_per_second(const aiAnimation* anim) {
    return anim->mTicksPerSecond > 0 ? anim->mTicksPerSecond : 25.0;
}

struct MeshAnimation::Impl {
    Assimp::Importer importer;
    const aiScene* scene = nullptr;
    const aiAnimation* anim = nullptr;
    std::vector<std::string> names;
    std::string clip;
};

int clip_frame_count(double seconds, double fps) {
    return std::max(1, int(std::lround(seconds * fps)) + 1);
}

std::vector<AnimationClipInfo> animation_clips(const std::string& path) {
    const std::string helper = mesh_importer();
    return helper.empty() ? detail::animation_clips_here(path) : detail::read_clips_isolated(helper, path);
}

std::vector<AnimationClipInfo> detail::animation_clips_here(const std::string& path) {
    Assimp::Importer importer;
    const aiScene* scene = detail::read_assimp_scene(importer, path);
    std::vector<AnimationClipInfo> clips;
    for (unsigned a = 0; a < scene->mNumAnimations; ++a) {
        const aiAnimation* anim = scene->mAnimations[a];
        std::string n = anim->mName.C_Str();
        clips.push_back({n.empty() ? "clip" + std::to_string(a) : n,
                         std::max(anim->mDuration, 0.0) / detail::ticks_per_second(anim)});
    }
    return clips;
}

MeshAnimation::MeshAnimation(const std::string& path, const std::string& clip)
    : impl_(std::make_unique<Impl>()) {
    // Posing needs Assimp's scene in this process. With an isolated importer
    // the helper reads the file first, so one that crashes the reader or
    // overruns its limits is refused there, before it is read here.
    if (const std::string helper = mesh_importer(); !helper.empty()) detail::read_clips_isolated(helper, path);
    impl_->scene = detail::read_assimp_scene(impl_->importer, path);
    const aiScene* scene = impl_->scene;
    for (unsigned a = 0; a < scene->mNumAnimations; ++a) {
        std::string n = scene->mAnimations[a]->mName.C_Str();
        impl_->names.push_back(n.empty() ? "clip" + std::to_string(a) : n);
    }
    if (impl_->names.empty()) throw Error(path + ": has no animation clips");
    std::size_t chosen = impl_->names.size();
    if (clip.empty()) chosen = 0;
    for (std::size_t i = 0; i < impl_->names.size() && chosen == impl_->names.size(); ++i)
        if (impl_->names[i] == clip || std::to_string(i) == clip) chosen = i;
    if (chosen == impl_->names.size()) {
        std::string list;
        for (const auto& n : impl_->names) list += (list.empty() ? "" : ", ") + n;
        throw Error(path + ": no animation clip '" + clip + "' (it has: " + list + ")");
    }
    impl_->anim = scene->mAnimations[chosen];
    impl_->clip = impl_->names[chosen];
}

MeshAnimation::~MeshAnimation() = default;

const std::vector<std::string>& MeshAnimation::clip_names() const { return impl_->names; }
const std::string& MeshAnimation::clip() const { return impl_->clip; }

double MeshAnimation::duration() const {
    return std::max(impl_->anim->mDuration, 0.0) / detail::ticks_per_second(impl_->anim);
}

void MeshAnimation::pose(double seconds, std::vector<glm::dvec3>& positions) const {
    const aiAnimation* anim = impl_->anim;
    const aiScene* scene = impl_->scene;
    double t = seconds * detail::ticks_per_second(anim);
    if (anim->mDuration > 0) t = std::fmod(std::max(t, 0.0), anim->mDuration + 1e-9);

    std::map<std::string, const aiMeshMorphAnim*> morph;
    for (unsigned c = 0; c < anim->mNumMorphMeshChannels; ++c)
        morph[anim->mMorphMeshChannels[c]->mName.C_Str()] = anim->mMorphMeshChannels[c];

    // Every node's global transform at t.
    const std::map<std::string, aiMatrix4x4> global = detail::node_transforms_at(scene, anim, t);

    positions.clear();
    std::vector<aiVector3D> local;
    detail::for_each_mesh_instance(scene, [&](const aiNode* node, const aiMesh* mesh, const aiMatrix4x4&) {
        local.assign(mesh->mVertices, mesh->mVertices + mesh->mNumVertices);
        // Morph targets: base + sum of weight * (target - base).
        if (const auto it = morph.find(node->mName.C_Str()); it != morph.end() && mesh->mNumAnimMeshes) {
            const aiMeshMorphAnim* m = it->second;
            if (m->mNumKeys) {
                const std::size_t i = key_before(m->mKeys, m->mNumKeys, t);
                const std::size_t j = std::min<std::size_t>(i + 1, m->mNumKeys - 1);
                const double u = (j == i || t <= m->mKeys[i].mTime)
                                     ? 0.0
                                     : (t - m->mKeys[i].mTime) / (m->mKeys[j].mTime - m->mKeys[i].mTime);
                std::map<unsigned, double> weight;
                for (unsigned k = 0; k < m->mKeys[i].mNumValuesAndWeights; ++k)
                    weight[m->mKeys[i].mValues[k]] += (1.0 - u) * m->mKeys[i].mWeights[k];
                for (unsigned k = 0; k < m->mKeys[j].mNumValuesAndWeights; ++k)
                    weight[m->mKeys[j].mValues[k]] += u * m->mKeys[j].mWeights[k];
                for (const auto& [target, w] : weight) {
                    if (target >= mesh->mNumAnimMeshes || w == 0.0) continue;
                    const aiAnimMesh* am = mesh->mAnimMeshes[target];
                    if (!am->mVertices || am->mNumVertices != mesh->mNumVertices) continue;
                    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
                        local[v] += (am->mVertices[v] - mesh->mVertices[v]) * float(w);
                }
            }
        }
        const aiMatrix4x4& node_xf = global.at(node->mName.C_Str());
        if (!mesh->mNumBones) {
            for (const auto& p : local) positions.push_back(transform(node_xf, p));
            return;
        }
        // Skinning: sum of weight * (bone's global * offset) * vertex.
        std::vector<glm::dvec3> skinned(mesh->mNumVertices, glm::dvec3(0.0));
        std::vector<double> total(mesh->mNumVertices, 0.0);
        for (unsigned b = 0; b < mesh->mNumBones; ++b) {
            const aiBone* bone = mesh->mBones[b];
            const auto g = global.find(bone->mName.C_Str());
            if (g == global.end()) continue;
            const aiMatrix4x4 m = g->second * bone->mOffsetMatrix;
            for (unsigned w = 0; w < bone->mNumWeights; ++w) {
                const aiVertexWeight& vw = bone->mWeights[w];
                if (vw.mVertexId >= mesh->mNumVertices) continue;
                skinned[vw.mVertexId] += double(vw.mWeight) * transform(m, local[vw.mVertexId]);
                total[vw.mVertexId] += vw.mWeight;
            }
        }
        for (unsigned v = 0; v < mesh->mNumVertices; ++v)
            positions.push_back(total[v] > 1e-9 ? skinned[v] / total[v] : transform(node_xf, local[v]));
    });
}

} // namespace snaxels
