#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "snaxels/export/bezier.h"
#include "snaxels/export/drawing.h"
#include "snaxels/mesh/import.h"
#include "snaxels/style/style.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

StyleDiagnostic error_of(const std::string& xml) {
    try {
        parse_style(xml, "test.xml", nullptr);
    } catch (const StyleError& e) {
        return e.diagnostic();
    }
    ADD_FAILURE() << "no error for " << xml;
    return {};
}

} // namespace

TEST(Style, ParsesEveryElementAndAttribute) {
    std::vector<StyleDiagnostic> warnings;
    const Style s = parse_style(R"(<style version="1">
  <canvas width="640" height="480" margin="10" background="none"/>
  <light pos="1,2,3"/>
  <contour kind="visual">
    <visible stroke="#abc" width="2.5" opacity="0.8" dash="3" cap="square" join="bevel" smoothing="0.5"/>
    <hidden draw="false"/>
  </contour>
  <contour kind="gleam" k="0.9"><visible stroke="orange"/></contour>
  <contour kind="crease" angle="42.5" min-length="0.05"><visible stroke="teal"/></contour>
  <contour kind="border"><visible stroke="navy"/></contour>
</style>)", "t.xml", &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 480);
    EXPECT_EQ(s.margin, 10.0);
    EXPECT_EQ(s.background, "none");
    ASSERT_TRUE(s.light && s.light->point);
    EXPECT_EQ(s.light->pos, glm::dvec3(1, 2, 3));
    ASSERT_EQ(s.contours.size(), 4u);
    EXPECT_EQ(s.contours[2].spec.label(), "crease:42.5");
    EXPECT_EQ(s.contours[2].spec.min_length, 0.05);
    EXPECT_EQ(s.contour(ContourSpec{ContourKind::Crease, 42.5, 0.05}).visible.colour, "teal");
    EXPECT_EQ(s.contour(ContourSpec{ContourKind::Border, 0.0}).visible.colour, "navy");
    const ContourStyle v = s.contour(ContourSpec{});
    EXPECT_EQ(v.visible.colour, "#abc");
    EXPECT_EQ(v.visible.width, 2.5);
    EXPECT_EQ(v.visible.opacity, 0.8);
    EXPECT_EQ(v.visible.dash, (std::vector<double>{3, 3}));
    EXPECT_EQ(v.visible.cap, "square");
    EXPECT_EQ(v.visible.join, "bevel");
    EXPECT_EQ(v.visible.smoothing, 0.5);
    EXPECT_FALSE(v.hidden.draw);
    EXPECT_EQ(s.contour(ContourSpec{ContourKind::Gleam, 0.9}).visible.colour, "orange");
    // A kind the style does not name gets its defaults.
    EXPECT_EQ(s.contour(ContourSpec{ContourKind::Shadow, 0.0}).hidden.dash, (std::vector<double>{4, 3}));
}

TEST(Style, ErrorsNameLineAndColumn) {
    auto d = error_of("<style>\n  <canvas width=\"abc\"/>\n</style>");
    EXPECT_EQ(d.line, 2);
    EXPECT_EQ(d.column, 3);
    EXPECT_NE(d.message.find("width=\"abc\" is not a number"), std::string::npos);
    d = error_of("<style>\n<contour kind=\"isophote\"/>\n</style>");
    EXPECT_EQ(d.line, 2);
    EXPECT_NE(d.message.find("needs k"), std::string::npos);
    d = error_of("<style>\n  <contour kind=\"visual\">\n    <visible stroke=\"blu\"/>\n</contour></style>");
    EXPECT_EQ(d.line, 3);
    EXPECT_EQ(d.column, 5);
    EXPECT_NE(d.message.find("not a colour"), std::string::npos);
    d = error_of("<style><contour kind=\"visual\"/><contour kind=\"visual\"/></style>");
    EXPECT_NE(d.message.find("a second <contour> for visual"), std::string::npos);
    EXPECT_NE(error_of("<style><light dir=\"1,2\"/></style>").message.find("three numbers"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"outline\"/></style>").message.find("must be visual"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"crease\" k=\"30\"/></style>").message.find("angle=\"DEGREES\", not k"),
              std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"visual\" angle=\"30\"/></style>").message.find("only a crease"),
              std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"crease\" angle=\"200\"/></style>").message.find("angle"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"visual\" min-length=\"0.1\"/></style>").message.find("only crease, border, material and object"),
              std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"border\" min-length=\"2\"/></style>").message.find("min-length"),
              std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"shadow\" over=\"objects\"/></style>").message.find("only a visual contour takes over"),
              std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"visual\" over=\"things\"/></style>").message.find("over=\"things\""),
              std::string::npos);
    EXPECT_NE(error_of("<styles/>").message.find("root element must be <style>"), std::string::npos);
    EXPECT_NE(error_of("<style><canvas margin=\"500\"/></style>").message.find("no room"), std::string::npos);
    d = error_of("<style>\n<canvas");
    EXPECT_EQ(d.line, 2);
    EXPECT_NE(d.message.find("malformed XML"), std::string::npos);
    try {
        parse_style("<style><canvas width=\"x\"/></style>", "my.xml", nullptr);
    } catch (const StyleError& e) {
        EXPECT_STREQ(e.what(), "my.xml:1:8: width=\"x\" is not a number");
    }
}

TEST(Style, RegionFills) {
    const Style s = parse_style(R"(<style>
  <region class="lit" fill="#ffcc00" erosion="1.5"/>
  <region class="band" k="0.7" fill="white" opacity="0.5"/>
  <region class="highlight" k="0.95" fill="#fff"/>
</style>)", "r.xml", nullptr);
    ASSERT_EQ(s.regions.size(), 3u);
    EXPECT_EQ(s.region(RegionClass::Lit, 0.0)->erosion, 1.5);
    EXPECT_EQ(s.region(RegionClass::Band, 0.7)->opacity, 0.5);
    EXPECT_EQ(s.region(RegionClass::Shadow, 0.0), nullptr);
    EXPECT_EQ(s.region(RegionClass::Band, 0.5), nullptr);
    // The contours the fills need: visual, shadow, the band's isophote, the gleam.
    std::vector<std::string> labels;
    for (const ContourSpec& c : s.fill_contours()) labels.push_back(c.label());
    EXPECT_EQ(labels, (std::vector<std::string>{"visual", "shadow", "isophote:0.7", "gleam:0.95"}));
    EXPECT_NE(error_of("<style><region class=\"band\" fill=\"red\"/></style>").message.find("needs k"), std::string::npos);
    // A misspelt word a colour attribute takes is named among the choices.
    EXPECT_NE(error_of("<style><region class=\"lit\" fill=\"materal\"/></style>").message.find("or material)"),
              std::string::npos);
    EXPECT_NE(error_of("<style><canvas background=\"nope\"/></style>").message.find("or none)"), std::string::npos);
    EXPECT_NE(error_of("<style><region class=\"lit\" k=\"0.5\"/></style>").message.find("takes no k"), std::string::npos);
    EXPECT_NE(error_of("<style><region class=\"glow\"/></style>").message.find("must be one of"), std::string::npos);
}

TEST(Style, UnknownNamesAreWarnings) {
    std::vector<StyleDiagnostic> warnings;
    const Style s = parse_style("<style>\n<contour kind=\"visual\" colour=\"red\"><visible/><outline/></contour>\n<fills/>\n</style>",
                                "w.xml", &warnings);
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_NE(warnings[0].message.find("unknown attribute 'colour' on <contour>"), std::string::npos);
    EXPECT_NE(warnings[1].message.find("unknown element <outline>"), std::string::npos);
    EXPECT_EQ(warnings[2].line, 3);
    EXPECT_EQ(s.contours.size(), 1u);
}

TEST(Style, PresetsParseWithoutWarnings) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(SNAXELS_STYLES_DIR)) {
        if (entry.path().extension() != ".xml") continue;
        std::vector<StyleDiagnostic> warnings;
        EXPECT_NO_THROW(load_style(entry.path().string(), &warnings)) << entry.path();
        EXPECT_TRUE(warnings.empty()) << entry.path() << ": " << (warnings.empty() ? "" : warnings[0].message);
        ++count;
    }
    EXPECT_GE(count, 3);
}

// Done-when 4: smoothed horse outline within tolerance of the polyline, with
// at least three times fewer path commands.
TEST(Bezier, HorseOutlineSmoothedWithinToleranceWithFewerCommands) {
    const LoadedMesh m = import_mesh(test::asset("horse.ply"));
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    Camera cam;
    cam.view_dir = glm::normalize(glm::dvec3(1.0, 0.2, 0.3));
    cam.up = {0, 0, 1};
    const ContourResult r = engine.compute({}, cam, default_light(cam));
    const glm::dvec3 centre = 0.5 * (m.report.bbox_min + m.report.bbox_max);
    const ImageProjection proj(cam, centre, 0.5 * glm::length(m.report.bbox_max - m.report.bbox_min), 800, 800);
    const Drawing d = make_drawing(engine, {r}, proj);
    const double tol = 0.5;
    std::size_t points = 0, commands = 0;
    for (const DrawnLoop& loop : d.contours[0].loops) {
        const BezierChain chain = smooth_polyline(loop.q, loop.closed, tol);
        points += loop.q.size();
        commands += chain.c1.size();
        const std::vector<glm::dvec2> curve = sample_chain(chain, 24);
        auto dist = [](const glm::dvec2& p, const std::vector<glm::dvec2>& line, bool closed) {
            double best = 1e300;
            const std::size_t n = line.size();
            for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
                const glm::dvec2 a = line[i], b = line[(i + 1) % n], ab = b - a;
                const double l2 = glm::dot(ab, ab);
                const double t = l2 > 0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
                best = std::min(best, glm::length(p - (a + t * ab)));
            }
            return best;
        };
        for (const glm::dvec2& p : loop.q) ASSERT_LE(dist(p, curve, false), tol + 1e-6);
        for (const glm::dvec2& c : curve) ASSERT_LE(dist(c, loop.q, loop.closed), tol + 1e-6);
    }
    std::printf("horse outline: %zu polyline points, %zu Bezier segments\n", points, commands);
    EXPECT_LE(3 * commands, points);
}

// The vocabulary's one-line summaries are the style reference's: each
// element has its section in docs/styles.md, and each attribute's row there
// begins its meaning with the summary the editor shows.
TEST(StyleVocabulary, SummariesAreTheReferencesWords) {
    std::ifstream in(std::filesystem::path(SNAXELS_SOURCE_DIR) / "docs" / "styles.md");
    ASSERT_TRUE(in.good());
    // section heading -> its table rows (attribute -> meaning)
    std::map<std::string, std::map<std::string, std::string>> sections;
    std::string line, section;
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) {
            section = line;
            sections[section];
            continue;
        }
        if (section.empty() || line.rfind("| `", 0) != 0) continue;
        std::vector<std::string> cells; // | name | type | default | meaning |
        std::stringstream row(line.substr(1));
        for (std::string cell; std::getline(row, cell, '|');) {
            const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
            cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
        }
        ASSERT_EQ(cells.size(), 4u) << line;
        sections[section][cells[0].substr(1, cells[0].size() - 2)] = cells[3];
    }
    for (const StyleElement& e : style_vocabulary()) {
        EXPECT_FALSE(e.summary.empty()) << e.name;
        const auto it = std::find_if(sections.begin(), sections.end(),
                                     [&](const auto& s) { return s.first.find("`<" + e.name + ">`") != std::string::npos; });
        ASSERT_NE(it, sections.end()) << "no section for <" << e.name << "> in docs/styles.md";
        for (const StyleAttribute& a : e.attributes) {
            const auto row = it->second.find(a.name);
            ASSERT_NE(row, it->second.end()) << "<" << e.name << "> " << a.name << " has no row in docs/styles.md";
            EXPECT_EQ(row->second.rfind(a.summary, 0), 0u)
                << "<" << e.name << "> " << a.name << ": the reference says \"" << row->second << "\", the vocabulary \""
                << a.summary << "\"";
        }
    }
}

// <surface sharp-angle>: degrees, or "file" (the default: the file's own
// normals decide); anything else is an error that says what it takes.
TEST(Style, SurfaceSharpAngle) {
    auto parse = [](const std::string& surface) {
        return parse_style("<style version=\"1\">" + surface + "</style>", "test", nullptr).surface.sharp_angle;
    };
    EXPECT_EQ(parse(""), kFileNormals);
    EXPECT_EQ(parse("<surface sharp-angle=\"30\"/>"), 30.0);
    EXPECT_EQ(parse("<surface sharp-angle=\"0\"/>"), 0.0);
    EXPECT_EQ(parse("<surface sharp-angle=\"180\"/>"), 180.0);
    EXPECT_EQ(parse("<surface sharp-angle=\"file\"/>"), kFileNormals);
    for (const std::string bad : {"x", "-5", "200", "30deg"}) {
        try {
            parse("<surface sharp-angle=\"" + bad + "\"/>");
            ADD_FAILURE() << bad << " was taken";
        } catch (const StyleError& e) {
            EXPECT_NE(std::string(e.what()).find("must be degrees from 0 to 180, or file"), std::string::npos) << e.what();
        }
    }
}

// A suggestive contour's two tests: the derivative test's min-derivative and
// min-angle, rtsc's threshold, and the fade a width-by="strength" stroke
// follows; each test refuses the other's values, and strength and fade
// belong to suggestive contours alone.
TEST(Style, SuggestiveTests) {
    const Style s = parse_style(R"(<style version="1">
  <contour kind="suggestive" test="rtsc" threshold="0.02" fade="0.05">
    <visible width-by="strength" width-min="0" width-max="2"/>
  </contour>
</style>)", "t.xml", nullptr);
    ASSERT_EQ(s.contours.size(), 1u);
    const ContourStyle& cs = s.contours[0];
    EXPECT_EQ(cs.spec.test, SuggestiveTest::Rtsc);
    EXPECT_EQ(cs.spec.k, 0.02);
    EXPECT_EQ(cs.spec.label(), "suggestive:rtsc:0.02");
    EXPECT_TRUE(cs.spec.same_as(ContourSpec::parse("suggestive:rtsc:0.02")));
    EXPECT_FALSE(cs.spec.same_as(ContourSpec::parse("suggestive:0.02:0")));
    EXPECT_EQ(cs.fade_or_default(), 0.05);
    EXPECT_EQ(cs.visible.width_by, StrokeStyle::WidthBy::Strength);

    // Without test: rtsc's, unless the derivative test's values are given.
    const Style d = parse_style("<style><contour kind=\"suggestive\" min-angle=\"15\"/><contour kind=\"suggestive\"/></style>", "t", nullptr);
    ASSERT_EQ(d.contours.size(), 2u);
    EXPECT_EQ(d.contours[1].spec.test, SuggestiveTest::Rtsc);
    EXPECT_EQ(d.contours[0].spec.test, SuggestiveTest::Derivative);
    EXPECT_EQ(d.contours[0].spec.k, kDefaultSuggestiveDerivative);
    EXPECT_EQ(d.contours[0].fade_or_default(), ContourStyle::kDefaultDerivativeFade);
    EXPECT_EQ(d.contours[1].spec.k, kDefaultRtscThreshold);
    EXPECT_EQ(d.contours[1].fade_or_default(), ContourStyle::kDefaultFade);

    EXPECT_NE(error_of("<style><contour kind=\"suggestive\" test=\"rtsc\" min-derivative=\"2\"/></style>").message.find("threshold"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"suggestive\" min-angle=\"10\" threshold=\"0.1\"/></style>").message.find("rtsc"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"visual\" threshold=\"0.1\"/></style>").message.find("suggestive"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"visual\" fade=\"0.1\"/></style>").message.find("suggestive"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"visual\"><visible width-by=\"strength\"/></contour></style>").message.find("strength"), std::string::npos);
    EXPECT_NE(error_of("<style><contour kind=\"suggestive\" fade=\"0\"/></style>").message.find("fade"), std::string::npos);

    // The command line's spelling.
    const ContourSpec rtsc = ContourSpec::parse("suggestive:rtsc");
    EXPECT_EQ(rtsc.test, SuggestiveTest::Rtsc);
    EXPECT_EQ(rtsc.k, kDefaultRtscThreshold);
    EXPECT_EQ(ContourSpec::parse("suggestive:rtsc:0.5").k, 0.5);
    EXPECT_THROW(ContourSpec::parse("suggestive:rtsc:x"), Error);
    EXPECT_THROW(ContourSpec::parse("suggestive:rtsc:-1"), Error);
}
