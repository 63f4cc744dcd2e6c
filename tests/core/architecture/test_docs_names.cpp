// docs/architecture.md names files, folders, types and functions in
// `code`: each must exist, so the map of the code stays true as the code
// moves. A path must exist (from the repository's root, or as the end of
// a path under it: `detail/smil.h`, `curvature.h`), a type must be
// defined (class, struct, enum or alias), a function or constant must
// appear as one. Words of the style language and the command line
// (`border`, `render`) are not checked.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Tree {
    std::vector<std::string> files; ///< paths relative to the root, '/'-separated
    std::string sources;            ///< every source of core/, ui/ and app/, concatenated
};

const Tree& tree() {
    static const Tree t = [] {
        Tree out;
        const fs::path root(SNAXELS_SOURCE_DIR);
        for (const char* top : {"core", "ui", "app", "tests", "bench", "fuzz", "examples", "packaging", "scripts"}) {
            if (!fs::exists(root / top)) continue;
            for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
                if (!entry.is_regular_file()) continue;
                const std::string relative = fs::relative(entry.path(), root).generic_string();
                out.files.push_back(relative);
                const std::string top_name = top;
                const std::string ext = entry.path().extension().string();
                if ((top_name == "core" || top_name == "ui" || top_name == "app") && (ext == ".h" || ext == ".cpp"))
                    out.sources += read(entry.path()) + "\n";
            }
        }
        return out;
    }();
    return t;
}

bool path_exists(std::string name) {
    const fs::path root(SNAXELS_SOURCE_DIR);
    while (!name.empty() && name.back() == '/') name.pop_back();
    if (fs::exists(root / name)) return true;
    // The end of a path (a section's file named from its folder), or a
    // folder inside one (a section's `detail/`).
    for (const std::string& f : tree().files) {
        if (f.size() > name.size() && f.compare(f.size() - name.size(), name.size(), name) == 0 &&
            f[f.size() - name.size() - 1] == '/')
            return true;
        if (f.find("/" + name + "/") != std::string::npos) return true;
    }
    return false;
}

bool defined_type(const std::string& name) {
    return std::regex_search(tree().sources,
                             std::regex("\\b(class|struct|enum class|enum|using)\\s+" + name + "\\b"));
}

bool appears_as(const std::string& pattern) { return std::regex_search(tree().sources, std::regex(pattern)); }

/// Why @p token (a name in `code` in the document) names nothing, or "".
std::string problem(const std::string& token) {
    static const std::regex type_name(R"(^(snaxels::)?([A-Z][A-Za-z0-9]*)(<T>)?$)");
    static const std::regex member(R"(^([A-Z][A-Za-z0-9]*)::([a-z_][a-z0-9_]*)$)");
    static const std::regex constant(R"(^k[A-Z][A-Za-z0-9]*$)");
    static const std::regex call(R"(([a-z_][a-z0-9_]*)\(\)$)");
    static const std::regex identifier(R"(^[a-z][a-z0-9]*(_[a-z0-9]+)+$)");
    std::smatch m;
    if (token.find(' ') != std::string::npos || token.find('*') != std::string::npos ||
        token.find("...") != std::string::npos || token.empty() || token[0] == '.')
        return ""; // a command, a glob, an elision, an extension
    if (token.find('/') != std::string::npos || std::regex_search(token, std::regex(R"(\.(h|cpp)$)")))
        return path_exists(token) ? "" : "no such file or folder";
    if (std::regex_match(token, m, constant))
        return appears_as("\\b" + token + "\\s*=") ? "" : "no such constant";
    if (std::regex_match(token, m, member))
        return defined_type(m[1]) && appears_as("\\b" + m[2].str() + "\\s*\\(") ? "" : "no such member function";
    if (std::regex_match(token, m, type_name)) return defined_type(m[2]) ? "" : "no such type";
    if (std::regex_search(token, m, call)) return appears_as("\\b" + m[1].str() + "\\s*\\(") ? "" : "no such function";
    if (std::regex_match(token, identifier)) return appears_as("\\b" + token + "\\b") ? "" : "no such name";
    return ""; // a word of the style language or the command line
}

} // namespace

TEST(Docs, ArchitectureNamesOnlyWhatExists) {
    const std::string text = read(fs::path(SNAXELS_SOURCE_DIR) / "docs" / "architecture.md");
    ASSERT_FALSE(text.empty());
    std::size_t checked = 0;
    const std::regex code("`([^`\\n]+)`");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), code); it != std::sregex_iterator(); ++it) {
        const std::string token = (*it)[1];
        const std::string why = problem(token);
        EXPECT_TRUE(why.empty()) << "docs/architecture.md names `" << token << "`: " << why;
        ++checked;
    }
    EXPECT_GT(checked, 100u);
}

TEST(Docs, TheCheckFindsWhatIsMissing) {
    EXPECT_EQ(problem("core/snaxel/curvature.h"), "");
    EXPECT_EQ(problem("detail/smil.h"), "");
    EXPECT_EQ(problem("curvature.h"), "");
    EXPECT_NE(problem("core/snaxel/topology.h"), ""); // the topology is the mesh folder's
    EXPECT_NE(problem("rvature.h"), "");
    EXPECT_EQ(problem("detail/"), "");
    EXPECT_NE(problem("nowhere/"), "");
    EXPECT_EQ(problem("MeshTopology"), "");
    EXPECT_NE(problem("MeshTopologyOfOld"), "");
    EXPECT_EQ(problem("RayScene::refit"), "");
    EXPECT_NE(problem("RayScene::rebuild_everything"), "");
    EXPECT_EQ(problem("kNotDrawn"), "");
    EXPECT_NE(problem("kNeverDefined"), "");
    EXPECT_EQ(problem("make_pose()"), "");
    EXPECT_NE(problem("make_nothing()"), "");
    EXPECT_EQ(problem("border"), ""); // a word of the style language: not checked
}
