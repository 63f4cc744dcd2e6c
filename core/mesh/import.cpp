#include "core/mesh/import.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/glm.hpp>

#include "core/error.h"
#include "core/mesh/assimp_scene.h"
#include "core/mesh/procedural.h"

namespace snaxels {
namespace {

namespace fs = std::filesystem;

// Names the kind of a file whose first bytes mark it as something that is
// certainly not a mesh, so users get "a PNG image" instead of a parser error.
const char* non_mesh_kind(const std::array<unsigned char, 8>& head, std::size_t n) {
    auto starts = [&](std::initializer_list<unsigned char> magic) {
        if (magic.size() > n) return false;
        return std::equal(magic.begin(), magic.end(), head.begin());
    };
    if (starts({0x89, 'P', 'N', 'G'})) return "a PNG image";
    if (starts({0xFF, 0xD8, 0xFF})) return "a JPEG image";
    if (starts({'G', 'I', 'F', '8'})) return "a GIF image";
    if (starts({'%', 'P', 'D', 'F'})) return "a PDF document";
    if (starts({0x7F, 'E', 'L', 'F'})) return "an executable";
    if (starts({0x1F, 0x8B})) return "a gzip archive";
    return nullptr;
}

// Assimp reads past the end of a truncated binary PLY and reports whatever
// garbage follows; checking the body's size against its header says plainly
// what is wrong. Returns an empty string when the file is not binary PLY or
// is long enough.
std::string binary_ply_problem(std::ifstream& in, std::uintmax_t file_size) {
    in.clear();
    in.seekg(0);
    std::string line;
    if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return {};
    auto type_size = [](const std::string& t) -> std::size_t {
        if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
        if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
        if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" ||
            t == "float32")
            return 4;
        if (t == "double" || t == "float64") return 8;
        return 0;
    };
    bool binary = false;
    std::uintmax_t minimum = 0, count = 0, element_min = 0, elements = 0;
    std::string element;
    auto close_element = [&] { minimum += count * element_min; };
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "format") {
            std::string fmt;
            words >> fmt;
            binary = fmt.rfind("binary", 0) == 0;
        } else if (word == "element") {
            close_element();
            count = 0;
            if (!(words >> element >> count)) return "the PLY header has a malformed element line: " + line;
            element_min = 0;
            elements += count;
        } else if (word == "property") {
            std::string type;
            words >> type;
            if (type == "list") {
                std::string count_type, item_type;
                words >> count_type >> item_type;
                // A face list holds at least three indices.
                const std::size_t items = element == "face" ? 3 : 0;
                element_min += type_size(count_type) + items * type_size(item_type);
            } else {
                element_min += type_size(type);
            }
        } else if (word == "end_header") {
            close_element();
            if (!binary) {
                // One element per line: a body with fewer lines is truncated
                // (and Assimp would read past it).
                std::uintmax_t lines = 0;
                while (lines < elements && std::getline(in, line))
                    if (line.find_first_not_of(" \t\r") != std::string::npos) ++lines;
                if (lines < elements)
                    return "the ASCII PLY file is truncated (its header declares " + std::to_string(elements) +
                           " elements, the file has " + std::to_string(lines) + " data lines)";
                return {};
            }
            const auto body = file_size - static_cast<std::uintmax_t>(in.tellg());
            if (body < minimum)
                return "the binary PLY file is truncated (its header needs at least " +
                       std::to_string(minimum) + " bytes of data, the file has " +
                       std::to_string(body) + ")";
            return {};
        }
    }
    return "the PLY header has no end_header line";
}

// OFF: the counts line must not promise more vertex and face lines than
// the file has (Assimp would allocate and loop for them).
std::string off_problem(std::ifstream& in) {
    in.clear();
    in.seekg(0);
    std::string line, first;
    if (!std::getline(in, first)) return {};
    std::istringstream head(first);
    std::string magic;
    head >> magic;
    if (magic != "OFF" && magic != "COFF" && magic != "NOFF" && magic != "CNOFF") return {};
    long long nv = -1, nf = -1;
    if (!(head >> nv >> nf)) {
        while (std::getline(in, line)) {
            const auto at = line.find_first_not_of(" \t\r");
            if (at == std::string::npos || line[at] == '#') continue;
            std::istringstream counts(line);
            if (!(counts >> nv >> nf)) return "the OFF file's counts line is malformed: " + line;
            break;
        }
    }
    if (nv < 0 || nf < 0) return "the OFF file has no valid vertex and face counts";
    long long lines = 0;
    while (lines < nv + nf && std::getline(in, line)) {
        const auto at = line.find_first_not_of(" \t\r");
        if (at != std::string::npos && line[at] != '#') ++lines;
    }
    if (lines < nv + nf)
        return "the OFF file is truncated (it declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
               " faces, the file has " + std::to_string(lines) + " data lines)";
    return {};
}

// Binary STL: 80-byte header, a triangle count, 50 bytes per triangle.
std::string binary_stl_problem(std::ifstream& in, std::uintmax_t file_size, const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".stl" || file_size < 84) return {};
    in.clear();
    in.seekg(0);
    char head[84];
    in.read(head, 84);
    if (std::string(head, 5) == "solid") {
        // ASCII, unless the size matches the binary layout (some binary files start with "solid").
        std::uint32_t n = 0;
        std::memcpy(&n, head + 80, 4);
        if (84 + 50 * std::uintmax_t(n) != file_size) return {};
    }
    std::uint32_t n = 0;
    std::memcpy(&n, head + 80, 4);
    if (84 + 50 * std::uintmax_t(n) > file_size)
        return "the binary STL file is truncated (it declares " + std::to_string(n) + " triangles, room for " +
               std::to_string((file_size - 84) / 50) + ")";
    return {};
}

void check_readable(const std::string& path) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw Error(path + ": no such file");
    if (fs::is_directory(status)) throw Error(path + ": is a directory, not a mesh file");
    if (!fs::is_regular_file(status)) throw Error(path + ": is not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot be read (" + std::strerror(errno) + ")");
    std::array<unsigned char, 8> head{};
    in.read(reinterpret_cast<char*>(head.data()), head.size());
    const auto n = static_cast<std::size_t>(in.gcount());
    if (n == 0) throw Error(path + ": the file is empty");
    if (const char* kind = non_mesh_kind(head, n))
        throw Error(path + ": is " + kind + ", not a mesh file");
    const std::uintmax_t size = fs::file_size(path, ec);
    for (const std::string& problem : {binary_ply_problem(in, size), off_problem(in), binary_stl_problem(in, size, path)})
        if (!problem.empty()) throw Error(path + ": " + problem);
}

// Assimp's messages are written for developers; say the common ones plainly.
std::string plain_assimp_error(std::string why) {
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    if (why.empty()) return "cannot be read as a mesh";
    if (why.find("contains no faces") != std::string::npos ||
        why.find("no meshes") != std::string::npos)
        return "contains no faces";
    if (why.find("No suitable reader") != std::string::npos)
        return "is not in a mesh format Assimp can read";
    return "cannot be read as a mesh (" + why + ")";
}

} // namespace

namespace detail {

const aiScene* read_assimp_scene(Assimp::Importer& importer, const std::string& path) {
    check_readable(path);
    // Points and lines carry no surface; drop them rather than fail on them.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* scene = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
    if (!scene) throw Error(path + ": " + plain_assimp_error(importer.GetErrorString()));
    if (scene->mNumMeshes == 0 || !scene->mRootNode)
        throw Error(path + ": contains no mesh with faces");
    return scene;
}

void for_each_mesh_instance(const aiScene* scene,
                            const std::function<void(const aiNode*, const aiMesh*, const aiMatrix4x4&)>& fn) {
    std::function<void(const aiNode*, const aiMatrix4x4&)> visit = [&](const aiNode* node,
                                                                       const aiMatrix4x4& parent) {
        const aiMatrix4x4 xf = parent * node->mTransformation;
        for (unsigned m = 0; m < node->mNumMeshes; ++m) {
            if (node->mMeshes[m] >= scene->mNumMeshes) continue;
            const aiMesh* mesh = scene->mMeshes[node->mMeshes[m]];
            if (mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) fn(node, mesh, xf);
        }
        for (unsigned c = 0; c < node->mNumChildren; ++c) visit(node->mChildren[c], xf);
    };
    visit(scene->mRootNode, aiMatrix4x4());
}

} // namespace detail

TriangleSoup read_triangle_soup(const std::string& path) {
    Assimp::Importer importer;
    const aiScene* scene = detail::read_assimp_scene(importer, path);
    TriangleSoup soup;
    detail::for_each_mesh_instance(scene, [&](const aiNode*, const aiMesh* mesh, const aiMatrix4x4& xf) {
        const auto base = static_cast<std::uint32_t>(soup.positions.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D& p = mesh->mVertices[v];
            // Transform in double so welding sees exactly repeatable values.
            glm::dvec3 q{};
            for (int r = 0; r < 3; ++r)
                q[r] = double(xf[r][0]) * p.x + double(xf[r][1]) * p.y + double(xf[r][2]) * p.z +
                       double(xf[r][3]);
            soup.positions.push_back(q);
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            soup.triangles.push_back(
                {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    });
    return soup;
}

LoadedMesh import_mesh(const std::string& path) {
    TriangleSoup soup = read_triangle_soup(path);
    try {
        return build_mesh(soup, path);
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
}

LoadedMesh load_mesh(const std::string& spec) {
    if (spec.rfind("proc:", 0) == 0) return build_mesh(make_procedural(spec.substr(5)), spec);
    return import_mesh(spec);
}

} // namespace snaxels
