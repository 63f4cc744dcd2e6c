// Pages: paper sizes, lengths and scales read as printers and drawing
// programs mean them (expected values from ISO 216 and the ANSI sizes, not
// from the code), a <canvas paper> read into the canvas, and the drawing's
// projection at a scale of 1:N, fitting or filling the page.

#include <gtest/gtest.h>

#include <cmath>

#include "snaxels/error.h"
#include "snaxels/style/page.h"
#include "snaxels/style/style.h"

using namespace snaxels;

namespace {

std::string parse_error(const std::string& xml) {
    try {
        parse_style(xml, "t.xml", nullptr);
    } catch (const StyleError& e) {
        return e.what();
    }
    return "";
}

TEST(Page, PaperSizesAreTheStandardOnes) {
    EXPECT_EQ(*paper_size("A4"), glm::dvec2(210.0, 297.0));
    EXPECT_EQ(*paper_size("a3"), glm::dvec2(297.0, 420.0));
    EXPECT_EQ(*paper_size("A0"), glm::dvec2(841.0, 1189.0));
    EXPECT_EQ(*paper_size("Letter"), glm::dvec2(215.9, 279.4));
    EXPECT_EQ(*paper_size("legal"), glm::dvec2(215.9, 355.6));
    EXPECT_EQ(*paper_size("300x200mm"), glm::dvec2(300.0, 200.0));
    EXPECT_NEAR(paper_size("8.5x11in")->x, 215.9, 1e-9);
    EXPECT_NEAR(paper_size("8.5x11in")->y, 279.4, 1e-9);
    EXPECT_EQ(*paper_size("30x20cm"), glm::dvec2(300.0, 200.0));
    for (const char* bad : {"A9", "", "300x200", "x200mm", "300xmm", "-3x4mm", "3x4px", "0x4mm", "A4 "})
        EXPECT_FALSE(paper_size(bad)) << bad;
}

TEST(Page, LengthsScalesAndUnits) {
    EXPECT_NEAR(*length_pixels("10mm"), 10.0 * 96.0 / 25.4, 1e-9);
    EXPECT_NEAR(*length_pixels("1in"), 96.0, 1e-9);
    EXPECT_NEAR(*length_pixels("72pt"), 96.0, 1e-9);
    EXPECT_NEAR(*length_pixels("2.54cm"), 96.0, 1e-9);
    EXPECT_EQ(*length_pixels("32"), 32.0);
    EXPECT_EQ(*length_pixels("32px"), 32.0);
    EXPECT_EQ(*length_pixels("0"), 0.0);
    for (const char* bad : {"", "mm", "ten", "10 mm", "10km", "-4mm", "nan"}) EXPECT_FALSE(length_pixels(bad)) << bad;
    EXPECT_EQ(*parse_scale("1:50"), 50.0);
    EXPECT_EQ(*parse_scale("2:1"), 0.5);
    for (const char* bad : {"50", "1:0", ":5", "1:", "a:b", "1:-2"}) EXPECT_FALSE(parse_scale(bad)) << bad;
    EXPECT_EQ(*model_unit_mm("m"), 1000.0);
    EXPECT_EQ(*model_unit_mm("ft"), 304.8);
    EXPECT_EQ(*model_unit_mm("in"), 25.4);
    EXPECT_FALSE(model_unit_mm("furlong"));
}

TEST(Page, ACanvasOnPaperIsThePaperInPixels) {
    const Style s = parse_style(R"(<style><canvas paper="A4" orientation="landscape" scale="1:20"/></style>)", "t.xml", nullptr);
    EXPECT_EQ(s.page.width_mm, 297.0);
    EXPECT_EQ(s.page.height_mm, 210.0);
    EXPECT_EQ(s.width, 1123); // 297 mm at 96 to the inch: 1122.5
    EXPECT_EQ(s.height, 794); // 210 mm: 793.7
    EXPECT_NEAR(s.margin, 10.0 * 96.0 / 25.4, 1e-9);
    EXPECT_EQ(s.page.scale, 20.0);
    EXPECT_EQ(s.page.unit_mm, 1000.0);
    const Style portrait = parse_style(R"(<style><canvas paper="letter" margin="0.5in" model-units="cm" scale="1:2"/></style>)", "t.xml", nullptr);
    EXPECT_EQ(portrait.width, 816); // 8.5 in
    EXPECT_EQ(portrait.height, 1056);
    EXPECT_EQ(portrait.margin, 48.0);
    EXPECT_EQ(portrait.page.unit_mm, 10.0);
    // A custom paper turns as written.
    EXPECT_EQ(parse_style(R"(<style><canvas paper="300x200mm"/></style>)", "t.xml", nullptr).page.width_mm, 300.0);
    // A canvas of pixels has no paper.
    EXPECT_FALSE(default_style().page.paper());

    EXPECT_NE(parse_error(R"(<style><canvas paper="A4" width="900"/></style>)").find("excludes width"), std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas paper="A11"/></style>)").find("must be A0"), std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas orientation="landscape"/></style>)").find("needs paper"), std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas paper="A4" orientation="sideways"/></style>)").find("must be one of portrait, landscape"),
              std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas scale="1:20" fit="fill"/></style>)").find("excludes fit"), std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas scale="twenty"/></style>)").find("a ratio such as 1:50"), std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas margin="3 mm"/></style>)").find("is not a length"), std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas paper="A6" margin="60mm"/></style>)").find("leaves no room"), std::string::npos);
    EXPECT_NE(parse_error(R"(<style><canvas paper="1x1mm"/></style>)").find("outside 16 .. 20000"), std::string::npos);
}

/// Pixels per world unit of @p p along the screen's right at @p at.
double pixels_per_unit(const ImageProjection& p, const Camera& c, const glm::dvec3& at) {
    glm::dvec3 right, up;
    c.screen_basis(right, up);
    return glm::length(p.project(at + right) - p.project(at));
}

TEST(Page, ToScaleAModelUnitIsItsLengthOverNOnPaper) {
    Style style = parse_style(R"(<style><canvas paper="A4" orientation="landscape" scale="1:50"/></style>)", "t.xml", nullptr);
    Camera ortho; // fitted: the command line's orthographic view
    ortho.view_dir = glm::normalize(glm::dvec3(-1.0, -1.0, -1.0));
    const glm::dvec3 centre(3.0, 1.0, -2.0);
    const ImageProjection p = drawing_projection(style, ortho, centre, 2.0);
    // A metre at 1:50 is 20 mm on paper: 20 * 96 / 25.4 pixels.
    EXPECT_NEAR(pixels_per_unit(p, ortho, centre), 20.0 * 96.0 / 25.4, 1e-9);
    EXPECT_NEAR(p.project(centre).x, 1123 / 2.0, 1e-9); // centred on the mesh
    EXPECT_NEAR(p.project(centre).y, 794 / 2.0, 1e-9);
    style.page.unit_mm = 10.0; // centimetres: a unit is 0.2 mm
    EXPECT_NEAR(pixels_per_unit(drawing_projection(style, ortho, centre, 2.0), ortho, centre), 0.2 * 96.0 / 25.4, 1e-9);
    // The application's framed orthographic view keeps its own line.
    Camera framed = ortho;
    framed.eye = centre + glm::dvec3(0.5, -0.5, 0.0);
    framed.ortho_height = 7.0;
    style.page.unit_mm = 1000.0;
    const ImageProjection q = drawing_projection(style, framed, centre, 2.0);
    EXPECT_NEAR(pixels_per_unit(q, framed, centre), 20.0 * 96.0 / 25.4, 1e-9);
    EXPECT_NEAR(q.project(framed.eye).x, 1123 / 2.0, 1e-9);
}

TEST(Page, FitKeepsTheViewInsideThePageAndFillCoversIt) {
    Style style = parse_style(R"(<style><canvas paper="A4" orientation="landscape"/></style>)", "t.xml", nullptr);
    const double margin = 10.0 * 96.0 / 25.4;
    Camera ortho;
    ortho.view_dir = glm::dvec3(0.0, 0.0, -1.0);
    const glm::dvec3 centre(0.0);
    // Fit: the bounding circle's diameter spans the smaller side within the margin.
    EXPECT_NEAR(pixels_per_unit(drawing_projection(style, ortho, centre, 2.0), ortho, centre), (794 - 2.0 * margin) / 4.0, 1e-9);
    style.page.fit = Page::Fit::Fill; // across the larger side, margin or not
    EXPECT_NEAR(pixels_per_unit(drawing_projection(style, ortho, centre, 2.0), ortho, centre), 1123 / 4.0, 1e-9);
    // Perspective: the field of view spans the side; at the target's depth
    // (distance 10, 40 degrees) a unit is (span / 2) / (10 tan 20) pixels.
    Camera persp;
    persp.projection = Camera::Projection::Perspective;
    persp.eye = glm::dvec3(0.0, 0.0, 10.0);
    persp.target = centre;
    persp.fov_deg = 40.0;
    const double t = 10.0 * std::tan(20.0 * M_PI / 180.0);
    EXPECT_NEAR(pixels_per_unit(drawing_projection(style, persp, centre, 2.0), persp, centre), (1123 / 2.0) / t, 1e-6);
    style.page.fit = Page::Fit::Fit;
    EXPECT_NEAR(pixels_per_unit(drawing_projection(style, persp, centre, 2.0), persp, centre), ((794 - 2.0 * margin) / 2.0) / t,
                1e-6);
    // A canvas of pixels draws as it always has: no margin for a perspective view.
    Style pixels = default_style();
    EXPECT_NEAR(pixels_per_unit(drawing_projection(pixels, persp, centre, 2.0), persp, centre), 400.0 / t, 1e-6);
}

} // namespace
