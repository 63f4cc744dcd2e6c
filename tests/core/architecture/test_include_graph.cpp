// The library's include structure, read from its sources: no circle between
// core folders, the library includes only its own headers by their installed
// names, and a public header needs nothing a user of the library lacks.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace {

struct Include {
    std::string file;   ///< path below core/
    std::string target; ///< as written between the quotes or brackets
    bool quoted;
};

std::vector<Include> core_includes() {
    const fs::path core = fs::path(SNAXELS_SOURCE_DIR) / "core";
    const std::regex line(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
    std::vector<Include> all;
    for (const auto& entry : fs::recursive_directory_iterator(core)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".h" && ext != ".cpp" && ext != ".in") continue;
        std::ifstream in(entry.path());
        for (std::string l; std::getline(in, l);) {
            std::smatch m;
            if (std::regex_search(l, m, line))
                all.push_back({fs::relative(entry.path(), core).generic_string(), m[2].str(), m[1].str() == "\""});
        }
    }
    return all;
}

/// "mesh/import.h" -> "mesh"; "error.h" -> "" (the library's root).
std::string folder_of(const std::string& path) {
    const auto slash = path.find('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

bool is_detail(const std::string& path) { return path.find("/detail/") != std::string::npos; }

} // namespace

TEST(IncludeGraph, ReadsTheLibrary) {
    // The scan itself works: the library has many files and includes.
    const auto includes = core_includes();
    EXPECT_GT(includes.size(), 300u);
    std::set<std::string> folders;
    for (const auto& inc : includes) folders.insert(folder_of(inc.file));
    EXPECT_GE(folders.size(), 10u);
}

TEST(IncludeGraph, CoreIncludesItsOwnHeadersByTheirInstalledNames) {
    for (const auto& inc : core_includes()) {
        if (!inc.quoted) continue;
        EXPECT_EQ(inc.target.rfind("snaxels/", 0), 0u)
            << inc.file << " includes \"" << inc.target << "\": the library's headers are \"snaxels/...\"";
        if (inc.target.rfind("snaxels/", 0) != 0) continue;
        const fs::path header = fs::path(SNAXELS_SOURCE_DIR) / "core" / inc.target.substr(8);
        if (inc.target != "snaxels/version.h") {
            EXPECT_TRUE(fs::exists(header)) << inc.file << " includes \"" << inc.target << "\", which is not in core/";
        }
    }
}

TEST(IncludeGraph, UmbrellaIsForEmbeddersOnly) {
    // <snaxels/snaxels.h> includes the public headers for a program that
    // embeds the library; no library file includes it, and every header it
    // names is public.
    bool found = false;
    for (const auto& inc : core_includes()) {
        EXPECT_NE(inc.target, "snaxels/snaxels.h") << inc.file << " includes the umbrella header";
        if (inc.file != "snaxels.h") continue;
        found = true;
        EXPECT_EQ(inc.target.find("/detail/"), std::string::npos) << "the umbrella includes " << inc.target;
    }
    EXPECT_TRUE(found) << "core/snaxels.h includes nothing";
}

TEST(IncludeGraph, UmbrellaIncludesEveryPublicHeader) {
    // What docs/library.md and docs/architecture.md promise an embedder:
    // every installed header, named by the umbrella itself (not left to
    // whichever header happens to include it).
    std::set<std::string> named;
    for (const auto& inc : core_includes())
        if (inc.file == "snaxels.h") named.insert(inc.target);
    const fs::path core = fs::path(SNAXELS_SOURCE_DIR) / "core";
    std::size_t headers = 0;
    for (const auto& entry : fs::recursive_directory_iterator(core)) {
        if (entry.path().extension() != ".h") continue;
        const std::string relative = fs::relative(entry.path(), core).generic_string();
        if (relative == "snaxels.h" || relative.find("detail/") != std::string::npos) continue;
        ++headers;
        EXPECT_TRUE(named.count("snaxels/" + relative)) << "core/snaxels.h leaves out snaxels/" << relative;
    }
    EXPECT_GT(headers, 40u);
}

TEST(IncludeGraph, NoCircleBetweenCoreFolders) {
    std::map<std::string, std::map<std::string, std::string>> edges; // from -> to -> an example
    for (const auto& inc : core_includes()) {
        if (!inc.quoted || inc.target.rfind("snaxels/", 0) != 0) continue;
        // The umbrella header for embedders sits above every folder; no
        // library file includes it (IncludeGraph.UmbrellaIsForEmbeddersOnly).
        if (inc.file == "snaxels.h") continue;
        const std::string from = folder_of(inc.file), to = folder_of(inc.target.substr(8));
        if (from != to) edges[from].emplace(to, inc.file + " includes " + inc.target);
    }
    // Depth-first search; a back edge closes a circle, reported with its path.
    std::map<std::string, int> state; // 0 new, 1 on the path, 2 done
    std::vector<std::string> path;
    std::string circle;
    std::function<void(const std::string&)> visit = [&](const std::string& f) {
        state[f] = 1;
        path.push_back(f);
        for (const auto& [to, example] : edges[f]) {
            if (!circle.empty()) break;
            if (state[to] == 1) {
                auto at = std::find(path.begin(), path.end(), to);
                for (auto it = at; it != path.end(); ++it) {
                    const std::string& next = (it + 1 == path.end()) ? to : *(it + 1);
                    circle += "  " + edges[*it][next] + "\n";
                }
            } else if (state[to] == 0) {
                visit(to);
            }
        }
        path.pop_back();
        state[f] = 2;
    };
    std::vector<std::string> folders;
    for (const auto& [f, _] : edges) folders.push_back(f);
    for (const auto& f : folders)
        if (state[f] == 0 && circle.empty()) visit(f);
    EXPECT_TRUE(circle.empty()) << "core folders include each other in a circle:\n" << circle;
}

TEST(IncludeGraph, PublicHeadersNeedOnlyPublicDependencies) {
    // What snaxels::core's users get on their include path: its own public
    // headers, the standard library, GLM, OpenMesh and nlohmann::json.
    const std::regex allowed_system(R"(^(glm/|OpenMesh/|nlohmann/)|^[a-z_]+$)");
    for (const auto& inc : core_includes()) {
        const bool public_header = inc.file.size() > 2 && inc.file.substr(inc.file.size() - 2) == ".h" &&
                                   !is_detail(inc.file);
        if (!public_header) continue;
        if (inc.quoted) {
            EXPECT_FALSE(is_detail(inc.target)) << "the public header " << inc.file << " includes " << inc.target;
        } else {
            EXPECT_TRUE(std::regex_search(inc.target, allowed_system))
                << "the public header " << inc.file << " includes <" << inc.target << ">";
        }
    }
}

TEST(Architecture, OneErrorRoot) {
    // Every exception the library defines derives from snaxels::Error (one
    // catch takes them all): none derives from a standard exception itself,
    // except Error.
    const std::regex standard_base(R"((class|struct)\s+(\w+)\s*(final\s*)?:\s*(public\s+)?std::(runtime_error|logic_error|exception|invalid_argument|out_of_range)\b)");
    std::vector<std::string> roots;
    std::size_t derived = 0;
    const std::regex derived_from_error(R"((class|struct)\s+\w+\s*(final\s*)?:\s*(public\s+)?(Error|InternalError|Cancelled)\b)");
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(SNAXELS_SOURCE_DIR) / "core")) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".h" && ext != ".cpp") continue;
        std::ifstream in(entry.path());
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), standard_base); it != std::sregex_iterator(); ++it)
            roots.push_back((*it)[2].str() + " in " + entry.path().filename().string());
        derived += std::size_t(std::distance(std::sregex_iterator(text.begin(), text.end(), derived_from_error), std::sregex_iterator()));
    }
    ASSERT_EQ(roots.size(), 1u) << "exception roots: " << [&] {
        std::string all;
        for (const auto& r : roots) all += r + "; ";
        return all;
    }();
    EXPECT_EQ(roots.front(), "Error in error.h");
    // InternalError, Cancelled, StyleError, ParabolicCancelled, AnimationCancelled at least.
    EXPECT_GE(derived, 5u);
}

TEST(Architecture, EveryThrowIsAnError) {
    // What the library throws is an Error (so the command line tells a
    // fault of the input, exit 1, from one of the program, exit 3): every
    // throw site in core/ names a class that derives from snaxels::Error,
    // directly or through another, read from the class definitions.
    const std::regex definition(R"((class|struct)\s+(\w+)\s*(final\s*)?:\s*(public\s+)?(std::)?(\w+)\b)");
    const std::regex throw_site(R"(\bthrow\s+([A-Za-z_][\w:]*)\s*[\({])");
    std::map<std::string, std::string> base_of;
    std::vector<std::pair<std::string, std::string>> thrown; // (class, where)
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(SNAXELS_SOURCE_DIR) / "core")) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".h" && ext != ".cpp") continue;
        std::ifstream in(entry.path());
        std::string line;
        for (int number = 1; std::getline(in, line); ++number) {
            const auto code_end = line.find("//"); // comments may name anything
            const std::string code = line.substr(0, code_end);
            for (auto it = std::sregex_iterator(code.begin(), code.end(), definition); it != std::sregex_iterator(); ++it)
                base_of[(*it)[2].str()] = ((*it)[5].matched ? "std::" : "") + (*it)[6].str();
            for (auto it = std::sregex_iterator(code.begin(), code.end(), throw_site); it != std::sregex_iterator(); ++it) {
                std::string name = (*it)[1].str();
                if (name.rfind("snaxels::", 0) == 0) name = name.substr(9);
                thrown.emplace_back(name, entry.path().filename().string() + ":" + std::to_string(number));
            }
        }
    }
    auto is_error = [&](std::string name) {
        for (int depth = 0; depth < 16; ++depth) {
            if (name == "Error") return true;
            const auto it = base_of.find(name);
            if (it == base_of.end()) return false;
            name = it->second;
        }
        return false;
    };
    ASSERT_GE(thrown.size(), 20u) << "the throw sites were not found";
    std::string strays;
    for (const auto& [name, where] : thrown)
        if (!is_error(name)) strays += name + " at " + where + "; ";
    EXPECT_TRUE(strays.empty()) << "throws outside snaxels::Error: " << strays;
}

TEST(Architecture, IndicesNeedFewCasts) {
    // Mesh elements are typed ids indexing typed containers (elements.h),
    // so core has little left to convert by hand: a stage that counts
    // casts again is likely to be indexing with plain integers.
    const std::regex cast(R"(std::size_t\()");
    std::size_t casts = 0;
    std::string where;
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(SNAXELS_SOURCE_DIR) / "core")) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".h" && ext != ".cpp") continue;
        std::ifstream in(entry.path());
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const auto n = std::size_t(std::distance(std::sregex_iterator(text.begin(), text.end(), cast), std::sregex_iterator()));
        if (n) where += entry.path().filename().string() + " " + std::to_string(n) + "; ";
        casts += n;
    }
    EXPECT_LT(casts, 50u) << where;
}
