// No function in the library is longer than a reader can hold: every
// function body in core/, ui/ and app/, free or member, defined in a class or out of one,
// spans at most 100 lines from the line its declaration starts on to its
// closing brace (lambdas count toward the function they are written in).
//
// The scan reads the sources itself: comments, string and character
// literals are blanked, then every brace is matched. A brace opens a
// function body when it sits at namespace or class scope and the text
// before it (since the last ';', '{' or '}') has a parameter list and does
// not begin a class, struct, union, enum or namespace.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace {

constexpr int kMaxLines = 100;

struct FunctionSpan {
    std::string signature; ///< the declaration's first line, trimmed
    int first_line = 0;    ///< 1-based
    int lines = 0;
};

/// @p text with comments, string and character literals (raw strings too)
/// replaced by spaces; line breaks are kept, so lines still count.
std::string blank_literals(const std::string& text) {
    std::string out = text;
    std::size_t i = 0;
    auto blank = [&](std::size_t from, std::size_t to) {
        for (std::size_t k = from; k < to && k < out.size(); ++k)
            if (out[k] != '\n') out[k] = ' ';
    };
    while (i < text.size()) {
        if (text.compare(i, 2, "//") == 0) {
            const std::size_t end = text.find('\n', i);
            blank(i, end == std::string::npos ? text.size() : end);
            i = end == std::string::npos ? text.size() : end;
        } else if (text.compare(i, 2, "/*") == 0) {
            const std::size_t end = text.find("*/", i + 2);
            const std::size_t stop = end == std::string::npos ? text.size() : end + 2;
            blank(i, stop);
            i = stop;
        } else if (text[i] == 'R' && i + 1 < text.size() && text[i + 1] == '"' &&
                   (i == 0 || !(std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_'))) {
            const std::size_t open = text.find('(', i + 2);
            if (open == std::string::npos) break;
            const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
            const std::size_t end = text.find(close, open);
            const std::size_t stop = end == std::string::npos ? text.size() : end + close.size();
            blank(i, stop);
            i = stop;
        } else if (text[i] == '"' || (text[i] == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(text[i - 1])) &&
                                                            i + 1 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1]))))) {
            // (a quote between two hex digits is a digit separator: 1'000)
            const char quote = text[i];
            std::size_t k = i + 1;
            while (k < text.size() && text[k] != quote && text[k] != '\n') k += text[k] == '\\' ? 2 : 1;
            blank(i, k + 1);
            i = k + 1;
        } else {
            ++i;
        }
    }
    return out;
}

/// Every function body of @p source, as defined above.
std::vector<FunctionSpan> function_spans(const std::string& source) {
    const std::string text = blank_literals(source);
    enum class Scope { Namespace, Class, Function, Other };
    struct Open {
        Scope scope;
        bool outer; ///< opened at namespace or class scope
        int line;
        std::string signature;
    };
    std::vector<Open> stack;
    std::vector<FunctionSpan> spans;
    const std::regex type_head(R"(^(template\s*<[^{]*>\s*)?(class|struct|union|enum|namespace)\b)");
    const std::regex params(R"(\)\s*(const|noexcept|override|final|mutable|&|&&|->[^;{}]*|\s)*$)");
    // A constructor's member initializers, the last one in braces or parentheses: ) : x_(a), y_{b}
    const std::regex initializers(R"(\)\s*:\s*[\s\S]*[)}]\s*$)");
    const std::regex access(R"(^(public|private|protected)\s*:)");
    std::size_t since = 0; // where the text before the next brace starts
    int line = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') ++line;
        if (c != '{' && c != '}' && c != ';') continue;
        if (c == '{') {
            // The declaration starts past blank space, preprocessor lines and
            // access specifiers.
            std::size_t start = since;
            for (bool moved = true; moved && start < i;) {
                moved = false;
                while (start < i && std::isspace(static_cast<unsigned char>(text[start]))) ++start, moved = true;
                if (start < i && text[start] == '#') {
                    while (start < i && text[start] != '\n') ++start;
                    moved = true;
                }
                std::smatch m;
                const std::string rest = text.substr(start, std::min<std::size_t>(i - start, 16));
                if (std::regex_search(rest, m, access)) start += std::size_t(m.length(0)), moved = true;
            }
            const std::string head = text.substr(start, i - start);
            const bool outer = stack.empty() || stack.back().scope == Scope::Namespace || stack.back().scope == Scope::Class;
            Scope scope = Scope::Other;
            std::smatch m;
            if (outer) {
                if (std::regex_search(head, m, type_head))
                    scope = m[2] == "namespace" ? Scope::Namespace : m[2] == "enum" ? Scope::Other : Scope::Class;
                else if (std::regex_search(head, std::regex(R"(^extern\s*$)")))
                    scope = Scope::Namespace; // extern "C" { (the literal is blanked)
                else if (std::regex_search(head, params) || std::regex_search(head, initializers))
                    scope = Scope::Function;
            }
            int first = line;
            for (std::size_t k = start; k < i; ++k)
                if (text[k] == '\n') --first;
            const std::size_t eol = source.find('\n', start);
            stack.push_back({scope, outer, first, source.substr(start, (eol == std::string::npos ? i : eol) - start)});
            // A brace initializer at namespace or class scope (a member
            // initializer, a variable, an enum) is part of what follows:
            // the declaration goes on past it.
            if (scope == Scope::Other && outer) continue;
        } else if (c == '}') {
            if (!stack.empty()) {
                const Open open = stack.back();
                stack.pop_back();
                if (open.scope == Scope::Function) spans.push_back({open.signature, open.line, line - open.line + 1});
                if (open.scope == Scope::Other && open.outer) continue; // (as above)
            }
        }
        since = i + 1;
    }
    return spans;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string listed(const std::vector<FunctionSpan>& spans) {
    std::string out = "found:\n";
    for (const FunctionSpan& f : spans)
        out += "  line " + std::to_string(f.first_line) + ", " + std::to_string(f.lines) + " lines: " + f.signature + "\n";
    return out;
}

std::string lines_of(int n, const std::string& line) {
    std::string out;
    for (int i = 0; i < n; ++i) out += line + "\n";
    return out;
}

} // namespace

TEST(FunctionLength, ScannerFindsFunctionsOfEveryForm) {
    const std::string source = "namespace a {\n"                                 // 1
                               "int free(int x) {\n"                             // 2
                               "    if (x) { return 1; }\n"                      // 3
                               "    auto f = [&](int y) { return y; };\n"        // 4
                               "    const char* s = \"}{\"; // }\n"              // 5
                               "    return '}' + f(x);\n"                        // 6
                               "}\n"                                             // 7
                               "class C {\n"                                     // 8
                               "  public:\n"                                     // 9
                               "    C(int a, int b)\n"                           // 10
                               "        : a_(a), b_{b} {}\n"                     // 11
                               "    int get() const {\n"                         // 12
                               "        return a_; /* } */\n"                    // 13
                               "    }\n"                                         // 14
                               "    struct Inner { int v() const noexcept { return 1; } };\n" // 15
                               "    int a_, b_;\n"                               // 16
                               "};\n"                                            // 17
                               "template <class T> auto g(T t) -> T {\n"         // 18
                               "    return t;\n"                                 // 19
                               "}\n"                                             // 20
                               "enum class E { X, Y };\n"                        // 21
                               "const int table[] = {1, 2, 3};\n"                // 22
                               "int C2::h() const\n"                             // 23
                               "{\n"                                             // 24
                               "    return R\"x(})x\"[0];\n"                     // 25
                               "}\n"                                             // 26
                               "} // namespace a\n";
    const auto spans = function_spans(source);
    ASSERT_EQ(spans.size(), 6u) << listed(spans);
    EXPECT_EQ(spans[0].first_line, 2);
    EXPECT_EQ(spans[0].lines, 6);
    EXPECT_EQ(spans[1].first_line, 10); // the constructor, from its name
    EXPECT_EQ(spans[1].lines, 2);
    EXPECT_EQ(spans[2].first_line, 12);
    EXPECT_EQ(spans[2].lines, 3);
    EXPECT_EQ(spans[3].first_line, 15); // a member of a nested class
    EXPECT_EQ(spans[4].first_line, 18);
    EXPECT_EQ(spans[4].lines, 3);
    EXPECT_EQ(spans[5].first_line, 23);
    EXPECT_EQ(spans[5].lines, 4);
}

TEST(FunctionLength, ScannerMeasuresALongFunction) {
    const std::string source = "void long_one() {\n" + lines_of(kMaxLines, "    step();") + "}\n" +
                               "struct S {\n    void member() {\n" + lines_of(10, "        x();") + "    }\n};\n";
    const auto spans = function_spans(source);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_EQ(spans[0].lines, kMaxLines + 2);
    EXPECT_EQ(spans[1].lines, 12);
}

TEST(FunctionLength, ScannerFindsEveryFunctionOfAHeader) {
    // A real header of the library, every function of which is listed here
    // by hand: free, inline, members, a template.
    const auto spans = function_spans(read(fs::path(SNAXELS_SOURCE_DIR) / "core" / "planarmap" / "region.h"));
    std::vector<std::string> found;
    for (const FunctionSpan& f : spans) found.push_back(std::regex_replace(f.signature, std::regex(R"(^\s+)"), ""));
    const std::vector<std::string> expected_starts = {
        "inline bool region_class_has_level", "ShadingClasses(bool shadow", "int count() const", "int bands() const",
        "int first_highlight() const", "bool has_shadow() const", "RegionClass region_class(int cls) const",
        "double level(int cls) const", "template <class InBand, class InHighlight>", "int from_nl(double nl) const",
        "template <class MapInput> ShadingClasses shading_classes"};
    ASSERT_EQ(found.size(), expected_starts.size()) << listed(spans);
    for (std::size_t i = 0; i < found.size(); ++i)
        EXPECT_EQ(found[i].rfind(expected_starts[i], 0), 0u) << found[i] << " should start with " << expected_starts[i];
}

/// Checks every function in the folder @p name of the source tree; returns
/// how many it found.
std::size_t check_folder(const std::string& name) {
    const fs::path root = fs::path(SNAXELS_SOURCE_DIR);
    std::size_t functions = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root / name)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".h" && ext != ".cpp") continue;
        for (const FunctionSpan& f : function_spans(read(entry.path()))) {
            ++functions;
            EXPECT_LE(f.lines, kMaxLines) << fs::relative(entry.path(), root).generic_string() << ":" << f.first_line
                                          << ": " << f.lines << " lines: " << f.signature;
        }
    }
    return functions;
}

TEST(FunctionLength, NoCoreFunctionLongerThanTheLimit) {
    // The scan found the library's functions (about 570 on 2026-12-02).
    EXPECT_GT(check_folder("core"), 450u);
}

TEST(FunctionLength, NoApplicationFunctionLongerThanTheLimit) {
    // The widgets and the window, and the programs' entry points and CLI
    // commands: the scan finds them (178 and 40 on 2026-12-03).
    const std::size_t ui = check_folder("ui"), app = check_folder("app");
    std::printf("functions: ui %zu, app %zu\n", ui, app);
    EXPECT_GT(ui, 140u);
    EXPECT_GT(app, 30u);
}
