#include "snaxels/mesh/import.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "snaxels/error.h"
#include "snaxels/mesh/detail/assimp_scene.h"
#include "snaxels/mesh/isolated_import.h"
#include "snaxels/mesh/procedural.h"

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

// One element of a PLY header: its count and the layout of one item.
struct PlyProperty {
    bool list = false;
    std::size_t size = 0;       ///< a scalar's size, or a list item's
    std::size_t count_size = 0; ///< a list's count type
};
struct PlyElement {
    std::string name;
    std::uintmax_t count = 0;
    std::vector<PlyProperty> properties;
    bool has_list() const {
        return std::any_of(properties.begin(), properties.end(), [](const PlyProperty& p) { return p.list; });
    }
    std::size_t fixed_size() const {
        std::size_t n = 0;
        for (const auto& p : properties) n += p.size;
        return n;
    }
};

std::size_t ply_type_size(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

// Reads a binary PLY body in large blocks, for walking its lists.
class BodyWalker {
  public:
    BodyWalker(std::ifstream& in, std::uintmax_t size) : in_(in), left_(size) {}
    /// Skips @p n bytes; false when the body ends first.
    bool skip(std::uintmax_t n) {
        const std::uintmax_t buffered = buffer_.size() - at_;
        if (n <= buffered) {
            at_ += std::size_t(n);
            return true;
        }
        n -= buffered;
        at_ = buffer_.size();
        if (n > left_) return false;
        in_.seekg(std::streamoff(n), std::ios::cur);
        left_ -= n;
        return true;
    }
    /// Reads an unsigned count of @p size bytes; false when the body ends.
    bool count(std::size_t size, bool big_endian, std::uint64_t& value) {
        if (buffer_.size() - at_ < size && !refill()) return false;
        if (buffer_.size() - at_ < size) return false;
        value = 0;
        for (std::size_t b = 0; b < size; ++b) {
            const auto byte = static_cast<unsigned char>(buffer_[at_ + (big_endian ? b : size - 1 - b)]);
            value = (value << 8) | byte;
        }
        at_ += size;
        return true;
    }

  private:
    bool refill() {
        buffer_.erase(0, at_);
        at_ = 0;
        const std::size_t want = std::size_t(std::min<std::uintmax_t>(left_, 1 << 20));
        if (want == 0) return false;
        const std::size_t had = buffer_.size();
        buffer_.resize(had + want);
        in_.read(buffer_.data() + had, std::streamsize(want));
        buffer_.resize(had + std::size_t(in_.gcount()));
        left_ -= std::uintmax_t(in_.gcount());
        return in_.gcount() > 0;
    }
    std::ifstream& in_;
    std::uintmax_t left_;
    std::string buffer_;
    std::size_t at_ = 0;
};

// A face (or any list) whose count runs past its line or past the end of the
// file makes Assimp allocate for the count (500,000,000 indices kept it busy
// for most of a minute) or read past the end; checking the body against its
// header says plainly what is wrong. Returns an empty string when the file
// is not PLY or holds what its header declares.
std::string lower_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// A line of a file quoted in a message: at most 80 characters, bytes that
// are not printable ASCII shown as '?' (a message is one line of text).
std::string shown(const std::string& line) {
    std::string out = line.substr(0, 80);
    for (char& c : out)
        if (c < 0x20 || c > 0x7e) c = '?';
    return line.size() > 80 ? out + "..." : out;
}

// Reads one line of a PLY header into @p line (without its CR LF or LF).
// The header is text: Assimp's reader also ends lines at NUL, a lone CR and
// form feed, and runs off the end of its buffer after one of them when no
// line feed follows (found by fuzz_mesh), so a control character other than
// a tab (or the CR of a CR LF) is a problem. Bytes past ASCII (UTF-8 in a
// comment) are text.
bool ply_header_line(std::istream& in, std::string& line, std::string& problem, std::uintmax_t& offset) {
    line.clear();
    for (int c; (c = in.get()) != std::char_traits<char>::eof(); ++offset) {
        if (c == '\n') {
            ++offset;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            return true;
        }
        if (!line.empty() && line.back() == '\r') {
            problem = "the PLY header has a carriage return without a line feed (at byte " +
                      std::to_string(offset - 1) + ")";
            return false;
        }
        if (c < 0x20 && c != '\t' && c != '\r') {
            char hex[16];
            std::snprintf(hex, sizeof hex, "0x%02x", unsigned(c));
            problem = std::string("the PLY header has a byte that is not text (") + hex + " at byte " +
                      std::to_string(offset) + ")";
            return false;
        }
        line.push_back(char(c));
    }
    return !line.empty();
}

/// Reads a PLY header's lines after its "ply" line from @p in (@p offset
/// counting the bytes read) into @p format and @p elements: what is wrong
/// with it, or "".
std::string read_ply_header(std::ifstream& in, std::uintmax_t& offset, std::string& format,
                            std::vector<PlyElement>& elements) {
    std::string line, problem;
    bool header_ended = false;
    while (!header_ended && ply_header_line(in, line, problem, offset)) {
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "format") {
            words >> format;
        } else if (word == "element") {
            PlyElement e;
            if (!(words >> e.name >> e.count)) return "the PLY header has a malformed element line: " + shown(line);
            elements.push_back(e);
        } else if (word == "property") {
            if (elements.empty()) return "the PLY header has a property before any element: " + shown(line);
            std::string type;
            words >> type;
            PlyProperty p;
            if (type == "list") {
                std::string count_type, item_type;
                words >> count_type >> item_type;
                p.list = true;
                p.count_size = ply_type_size(count_type);
                p.size = ply_type_size(item_type);
                if (p.count_size == 0 || p.size == 0) return "the PLY header has a list of an unknown type: " + shown(line);
            } else {
                p.size = ply_type_size(type);
                if (p.size == 0) return "the PLY header has a property of an unknown type: " + shown(line);
            }
            elements.back().properties.push_back(p);
        } else if (word == "end_header") {
            header_ended = true;
        } else if (!word.empty() && word != "comment" && word != "obj_info") {
            // Assimp reads on past a line it does not know and can corrupt
            // its memory (a double free, found by fuzz_mesh).
            return "the PLY header has a line that is not PLY: " + shown(line);
        }
    }
    if (!problem.empty()) return problem;
    if (!header_ended) return "the PLY header has no end_header line";
    for (std::size_t a = 0; a < elements.size(); ++a)
        for (std::size_t b = a + 1; b < elements.size(); ++b)
            if (elements[a].name == elements[b].name)
                return "the PLY header declares the element '" + elements[a].name + "' twice";
    return {};
}

std::string ply_item_name(const PlyElement& e, std::uintmax_t i) { return e.name + " " + std::to_string(i); }

/// What is wrong with an ASCII PLY body (after the header, in @p in) of
/// @p elements, or "".
std::string ascii_ply_problem(std::ifstream& in, const std::vector<PlyElement>& elements) {
    std::string line;
    // One item per line, each list as long as its count says.
    for (const PlyElement& e : elements) {
        for (std::uintmax_t i = 0; i < e.count;) {
            if (!std::getline(in, line)) {
                std::uintmax_t total = 0;
                for (const auto& el : elements) total += el.count;
                return "the ASCII PLY file is truncated (its header declares " + std::to_string(total) +
                       " elements, the file ends at " + ply_item_name(e, i) + ")";
            }
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (std::any_of(line.begin(), line.end(), [](char c) { return c >= 0 && c < 0x20 && c != '\t'; }))
                return "the ASCII PLY " + ply_item_name(e, i) + " has a control character in its line";
            if (line.find_first_not_of(" \t") == std::string::npos) continue;
            if (e.has_list()) {
                std::istringstream tokens(line);
                std::string token;
                for (const PlyProperty& p : e.properties) {
                    if (!(tokens >> token)) return "the ASCII PLY " + ply_item_name(e, i) + " is missing values: " + shown(line);
                    if (!p.list) continue;
                    char* end = nullptr;
                    const long long n = std::strtoll(token.c_str(), &end, 10);
                    if (*end != '\0' || n < 0)
                        return "the ASCII PLY " + ply_item_name(e, i) + " has a malformed list count '" + token + "'";
                    for (long long k = 0; k < n; ++k)
                        if (!(tokens >> token))
                            return "the ASCII PLY " + ply_item_name(e, i) + " declares a list of " + std::to_string(n) +
                                   " values but its line holds " + std::to_string(k);
                }
            }
            ++i;
        }
    }
    return {};
}

/// What is wrong with a binary PLY body (after the header, in @p in, of a
/// file of @p file_size bytes) of @p elements, or "".
std::string binary_ply_problem(std::ifstream& in, std::uintmax_t file_size, bool big_endian,
                               const std::vector<PlyElement>& elements) {
    const auto body = file_size - static_cast<std::uintmax_t>(in.tellg());
    const auto truncated = [&](const std::string& where) {
        return "the binary PLY file is truncated (its data ends inside " + where + "; the body has " +
               std::to_string(body) + " bytes)";
    };
    BodyWalker walk(in, body);
    for (const PlyElement& e : elements) {
        if (!e.has_list()) {
            const std::size_t size = e.fixed_size();
            if (size > 0 && e.count > body / size) return truncated("the " + e.name + " elements");
            if (!walk.skip(e.count * size)) return truncated("the " + e.name + " elements");
            continue;
        }
        for (std::uintmax_t i = 0; i < e.count; ++i) {
            for (const PlyProperty& p : e.properties) {
                if (!p.list) {
                    if (!walk.skip(p.size)) return truncated(ply_item_name(e, i));
                    continue;
                }
                std::uint64_t n = 0;
                if (!walk.count(p.count_size, big_endian, n)) return truncated(ply_item_name(e, i));
                if (n > body / p.size || !walk.skip(n * p.size))
                    return "the binary PLY " + ply_item_name(e, i) + " declares a list of " + std::to_string(n) +
                           " values, more than the file holds";
            }
        }
    }
    return {};
}

std::string ply_problem(std::ifstream& in, std::uintmax_t file_size, const std::string& path) {
    in.clear();
    in.seekg(0);
    // Assimp reads any .ply file as PLY, and a file that starts with "ply" or
    // "PLY" (after a line end) whatever its name.
    char head[4] = {};
    in.read(head, 4);
    const std::size_t skip = head[0] == '\n' ? 1 : head[0] == '\r' && head[1] == '\n' ? 2 : 0;
    const bool magic = std::tolower(head[skip]) == 'p' && std::tolower(head[skip + 1]) == 'l' &&
                       std::tolower(head[skip + 2]) == 'y';
    if (!magic && lower_extension(path) != ".ply") return {};
    in.clear();
    in.seekg(std::streamoff(skip));
    std::uintmax_t offset = skip;
    std::string line, problem;
    if (!ply_header_line(in, line, problem, offset))
        return problem.empty() ? "the PLY file has no header" : problem;
    std::transform(line.begin(), line.end(), line.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (line != "ply") return "the PLY file does not start with a 'ply' line";
    std::string format;
    std::vector<PlyElement> elements;
    if (std::string header = read_ply_header(in, offset, format, elements); !header.empty()) return header;
    if (format == "ascii") return ascii_ply_problem(in, elements);
    const bool big_endian = format == "binary_big_endian";
    if (!big_endian && format != "binary_little_endian") return "the PLY header has an unknown format '" + format + "'";
    return binary_ply_problem(in, file_size, big_endian, elements);
}

// OFF: the counts line must not promise more vertex and face lines than
// the file has (Assimp would allocate and loop for them).
bool is_off_magic(const std::string& word) {
    return word == "OFF" || word == "COFF" || word == "NOFF" || word == "CNOFF";
}

// The next line that is neither blank nor a comment.
bool next_data_line(std::istream& in, std::string& line) {
    while (std::getline(in, line)) {
        const auto at = line.find_first_not_of(" \t\r");
        if (at != std::string::npos && line[at] != '#') return true;
    }
    return false;
}

// OFF: an optional magic line ("OFF" and its variants, counts possibly on the same line), then the vertex, face
// and edge counts, then one line per vertex and per face. Assimp reads a .off file without its magic line too, and
// allocates for the declared counts before reading them, so the counts are checked against the file's lines first.
std::string off_problem(std::ifstream& in, const std::string& path) {
    in.clear();
    in.seekg(0);
    std::string line;
    if (!next_data_line(in, line)) return {};
    std::istringstream first(line);
    std::string magic;
    first >> magic;
    long long nv = -1, nf = -1;
    if (is_off_magic(magic)) {
        if (!(first >> nv >> nf)) {
            if (!next_data_line(in, line)) return "the OFF file has no vertex and face counts";
            std::istringstream counts(line);
            if (!(counts >> nv >> nf)) return "the OFF file's counts line is malformed: " + shown(line);
        }
    } else if (lower_extension(path) == ".off") {
        std::istringstream counts(line);
        if (!(counts >> nv >> nf))
            return "the OFF file starts with neither an OFF line nor its counts: " + shown(line);
    } else {
        return {};
    }
    if (nv < 0 || nf < 0) return "the OFF file has no valid vertex and face counts";
    constexpr long long kMostCount = 1LL << 40;  // far past any file; keeps nv + nf from overflowing
    if (nv > kMostCount || nf > kMostCount)
        return "the OFF file declares " + std::to_string(std::max(nv, nf)) + " elements, more than any file holds";
    long long lines = 0;
    while (lines < nv + nf && next_data_line(in, line)) ++lines;
    if (lines < nv + nf)
        return "the OFF file is truncated (it declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
               " faces, the file has " + std::to_string(lines) + " data lines)";
    return {};
}

// Binary STL: 80-byte header, a triangle count, 50 bytes per triangle.
std::string binary_stl_problem(std::ifstream& in, std::uintmax_t file_size, const std::string& path) {
    if (lower_extension(path) != ".stl" || file_size < 84) return {};
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
    for (const std::string& problem : {ply_problem(in, size, path), off_problem(in, path), binary_stl_problem(in, size, path)})
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

/// A file's axis system as the FBX format records it (Assimp passes the
/// file's GlobalSettings on as scene metadata: axis 0, 1, 2 for X, Y, Z and a
/// sign of +1 or -1 for up, front and the third, "coord" axis): the rotation
/// that makes its up +Y and its front +Z, the convention of glTF, OBJ and the
/// engine. Identity for a file that records none (Assimp turns Collada's up
/// axis to +Y itself) or is already +Y up.
aiMatrix4x4 upright_axes(const aiScene* scene) {
    const aiMetadata* meta = scene->mMetaData;
    std::int32_t up = 1, up_sign = 1, front = 2, front_sign = 1, coord = 0, coord_sign = 1;
    if (!meta || !meta->Get("UpAxis", up)) return {};
    meta->Get("UpAxisSign", up_sign);
    meta->Get("FrontAxis", front);
    meta->Get("FrontAxisSign", front_sign);
    meta->Get("CoordAxis", coord);
    meta->Get("CoordAxisSign", coord_sign);
    const std::array<std::int32_t, 3> axes{coord, up, front};
    if (axes[0] == axes[1] || axes[1] == axes[2] || axes[0] == axes[2] ||
        std::any_of(axes.begin(), axes.end(), [](std::int32_t a) { return a < 0 || a > 2; }))
        return {}; // not an axis system: leave the file as it is
    // Row k of the rotation picks the file's axis that becomes X, Y, Z.
    aiMatrix4x4 m;
    for (unsigned r = 0; r < 3; ++r)
        for (unsigned c = 0; c < 3; ++c) m[r][c] = 0.0f;
    m[0][unsigned(coord)] = coord_sign < 0 ? -1.0f : 1.0f;
    m[1][unsigned(up)] = up_sign < 0 ? -1.0f : 1.0f;
    m[2][unsigned(front)] = front_sign < 0 ? -1.0f : 1.0f;
    return m;
}

/// The JSON of a glTF 1.0 file (a .gltf, or the scene of a binary .glb of
/// version 1), or null for anything else.
nlohmann::json gltf1_json(const std::string& path) {
    nlohmann::json doc = detail::gltf_json(path);
    if (doc.is_null()) return nullptr;
    const nlohmann::json& version = doc["asset"].value("version", nlohmann::json());
    const bool one = (version.is_number() && version.get<double>() < 2.0) ||
                     (version.is_string() && version.get<std::string>().rfind("1", 0) == 0);
    return one ? doc : nullptr;
}

/// Assimp 5.2 composes a glTF 1.0 node's translation, rotation and scale as
/// R S T where the format means T R S (its glTF 2 reader has it right): a
/// node that is rotated or scaled has its translation turned with it (the
/// milk truck's wheels sink into the road). Such a node's matrix R S T is
/// put back to T R S: the same R S, translation (R S)^-1 times its own.
void mend_gltf1_node_order(const aiScene* scene, const std::string& path) {
    const nlohmann::json doc = gltf1_json(path);
    if (doc.is_null() || !doc.contains("nodes") || !doc["nodes"].is_object()) return;
    const nlohmann::json& nodes = doc["nodes"];
    std::function<void(aiNode*)> visit = [&](aiNode* node) {
        const auto it = nodes.find(node->mName.C_Str());
        if (it != nodes.end() && it->is_object() && !it->contains("matrix")) {
            aiMatrix4x4& m = node->mTransformation;
            aiMatrix3x3 linear(m);
            if (linear.Determinant() != 0.0f) {
                const aiVector3D t = linear.Inverse() * aiVector3D(m.a4, m.b4, m.c4);
                m.a4 = t.x, m.b4 = t.y, m.c4 = t.z;
            }
        }
        for (unsigned c = 0; c < node->mNumChildren; ++c) visit(node->mChildren[c]);
    };
    visit(scene->mRootNode);
}

} // namespace

namespace detail {

nlohmann::json gltf_json(const std::string& path) {
    const std::string ext = fs::path(path).extension().string();
    if (ext != ".gltf" && ext != ".glb" && ext != ".GLTF" && ext != ".GLB") return nullptr;
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.size() >= 12 && text.compare(0, 4, "glTF") == 0) {
        std::uint32_t version = 0;
        std::memcpy(&version, text.data() + 4, 4);
        if (version == 1 && text.size() >= 20) { // header, then the scene's length and format
            std::uint32_t length = 0;
            std::memcpy(&length, text.data() + 12, 4);
            if (length > text.size() - 20) return nullptr;
            text = text.substr(20, length);
        } else if (version == 2 && text.size() >= 20) { // header, then chunks; the first is the JSON
            std::uint32_t length = 0;
            std::memcpy(&length, text.data() + 12, 4);
            if (text.compare(16, 4, "JSON") != 0 || length > text.size() - 20) return nullptr;
            text = text.substr(20, length);
        } else {
            return nullptr;
        }
    }
    nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("asset") || !doc["asset"].is_object()) return nullptr;
    return doc;
}

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
    // Upright in the file's own axes: the root takes the turn, so the
    // meshes, their instances and an animation's every pose all follow it.
    // (The scene is the importer's, given out const; its root node is
    // changed once, before anything reads it.)
    mend_gltf1_node_order(scene, path);
    if (const aiMatrix4x4 axes = upright_axes(scene); !axes.IsIdentity())
        const_cast<aiNode*>(scene->mRootNode)->mTransformation = axes * scene->mRootNode->mTransformation;
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

namespace {

/// The names from the scene's top node down to @p node, joined by '/' (the
/// root's own name left out when it has a parent-less, mesh-less role).
std::string node_path(const aiNode* node) {
    std::vector<std::string> names;
    for (const aiNode* n = node; n; n = n->mParent)
        if (n->mParent || n == node) names.push_back(n->mName.length ? n->mName.C_Str() : "(unnamed)");
    std::string path;
    for (auto it = names.rbegin(); it != names.rend(); ++it) path += (path.empty() ? "" : "/") + *it;
    return path;
}

SceneMaterial scene_material(const aiMaterial* m, unsigned index) {
    SceneMaterial out;
    aiString name;
    out.name = m && m->Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length ? name.C_Str() : "material" + std::to_string(index);
    if (!m) return out;
    aiColor4D c;
    if (m->Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || m->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
        out.colour = glm::dvec4(c.r, c.g, c.b, out.colour.a);
    float opacity = 1.0f;
    if (m->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) out.colour.a = opacity;
    for (int k = 0; k < 4; ++k)
        if (!std::isfinite(out.colour[k])) out.colour[k] = k == 3 ? 1.0 : 0.8;
    out.colour = glm::clamp(out.colour, 0.0, 1.0);
    return out;
}

} // namespace

TriangleSoup detail::read_triangle_soup_here(const std::string& path) {
    Assimp::Importer importer;
    const aiScene* scene = detail::read_assimp_scene(importer, path);
    TriangleSoup soup;
    // The parts: each node that holds meshes, and each material a mesh uses,
    // in the order the instances come.
    std::map<const aiNode*, std::uint32_t> object_of;
    std::map<unsigned, std::uint32_t> material_of;
    // Normals are kept only when every mesh of the scene has them (a file
    // whose parts disagree is read as having none: smooth by default).
    bool normals = true;
    detail::for_each_mesh_instance(scene, [&](const aiNode*, const aiMesh* mesh, const aiMatrix4x4&) {
        normals = normals && mesh->mNormals != nullptr;
    });
    detail::for_each_mesh_instance(scene, [&](const aiNode* node, const aiMesh* mesh, const aiMatrix4x4& xf) {
        const auto base = static_cast<std::uint32_t>(soup.positions.size());
        glm::dmat3 linear{};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) linear[c][r] = double(xf[unsigned(r)][unsigned(c)]);
        // Normals turn by the inverse transpose (a scaled node keeps them
        // perpendicular to its faces; a mirrored one is turned outward with
        // its faces by build_mesh).
        const glm::dmat3 normal_turn = glm::transpose(glm::inverse(linear));
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D& p = mesh->mVertices[v];
            // Transform in double so welding sees exactly repeatable values.
            glm::dvec3 q{};
            for (int r = 0; r < 3; ++r)
                q[r] = double(xf[r][0]) * p.x + double(xf[r][1]) * p.y + double(xf[r][2]) * p.z +
                       double(xf[r][3]);
            soup.positions.push_back(q);
            if (!normals) continue;
            const aiVector3D& n = mesh->mNormals[v];
            const glm::dvec3 turned = normal_turn * glm::dvec3(n.x, n.y, n.z);
            const double len = glm::length(turned);
            // A zero or broken normal says nothing: it matches any other.
            soup.normals.push_back(len > 0.0 && std::isfinite(len) ? turned / len : glm::dvec3(0.0));
        }
        const auto object = object_of.try_emplace(node, std::uint32_t(soup.objects.size()));
        if (object.second) soup.objects.push_back({node->mName.length ? node->mName.C_Str() : "(unnamed)", node_path(node)});
        const unsigned m = mesh->mMaterialIndex;
        const auto material = material_of.try_emplace(m, std::uint32_t(soup.materials.size()));
        if (material.second) soup.materials.push_back(scene_material(m < scene->mNumMaterials ? scene->mMaterials[m] : nullptr, m));
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            soup.triangles.push_back(
                {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
            soup.triangle_object.push_back(object.first->second);
            soup.triangle_material.push_back(material.first->second);
        }
    });
    return soup;
}

TriangleSoup read_triangle_soup(const std::string& path) {
    const std::string helper = mesh_importer();
    return helper.empty() ? detail::read_triangle_soup_here(path) : detail::read_soup_isolated(helper, path);
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
    if (spec.rfind("proc:", 0) == 0) {
        const TriangleSoup soup = make_procedural(spec.substr(5));
        try {
            return build_mesh(soup, spec);
        } catch (const Error& e) {
            throw Error(spec + ": " + e.what());
        }
    }
    return import_mesh(spec);
}

} // namespace snaxels
