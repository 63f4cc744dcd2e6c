// Edits of a style's text for the user (snaxels/style/style_edit.h): the
// element edited changes, everything else of the text stays byte for byte
// (comments, quotes, spacing, look-alikes inside comments), and the result
// is a style the parser reads as the edit means.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "snaxels/style/style.h"
#include "snaxels/style/style_edit.h"

namespace {

using snaxels::ObjectDrawing;

const std::string kStyle = "<?xml version=\"1.0\"?>\n"
                           "<!-- hide with <object name=\"Box\" hide=\"true\"/> -->\n"
                           "<style version='1'>\n"
                           "  <contour kind='visual'>\n"
                           "    <visible stroke='#112233' width='2'/>\n"
                           "  </contour>\n"
                           "  <object name=\"wheel*\" hide=\"true\"/>\n"
                           "\t<object   name=\"Box\" draw=\"false\" />\n"
                           "</style>\n";

snaxels::Style parsed(const std::string& text) { return snaxels::parse_style(text, "test", nullptr); }

TEST(StyleEdit, HidingAnObjectReplacesItsElementAndKeepsTheRest) {
    const auto out = snaxels::with_object_drawing(kStyle, "Box", ObjectDrawing::Hidden);
    ASSERT_TRUE(out);
    // The element named Box, and no other line, is now the one that hides it.
    std::string expected = kStyle;
    const std::string before = "\t<object   name=\"Box\" draw=\"false\" />\n";
    expected.replace(expected.find(before), before.size(), "");
    expected.insert(expected.rfind("</style>"), "  <object name=\"Box\" hide=\"true\"/>\n");
    EXPECT_EQ(*out, expected);
    const snaxels::Style style = parsed(*out);
    EXPECT_EQ(style.hidden_objects, (std::vector<std::string>{"wheel*", "Box"}));
    EXPECT_TRUE(style.occluders.empty());
}

TEST(StyleEdit, DrawingAnObjectRemovesOnlyItsExactElement) {
    const auto out = snaxels::with_object_drawing(kStyle, "Box", ObjectDrawing::Drawn);
    ASSERT_TRUE(out);
    std::string expected = kStyle;
    expected.erase(expected.find("\t<object   name"), std::string("\t<object   name=\"Box\" draw=\"false\" />\n").size());
    EXPECT_EQ(*out, expected);
    // The comment's look-alike and the pattern stay; an object the style
    // does not name leaves the text as it was.
    EXPECT_EQ(*snaxels::with_object_drawing(kStyle, "Lamp", ObjectDrawing::Drawn), kStyle);
    // A name with markup characters is escaped, and reads back.
    const auto amp = snaxels::with_object_drawing(kStyle, "Tom & \"Jerry\"", ObjectDrawing::Occluder);
    ASSERT_TRUE(amp);
    EXPECT_NE(amp->find("<object name=\"Tom &amp; &quot;Jerry&quot;\" draw=\"false\"/>"), std::string::npos);
    EXPECT_EQ(parsed(*amp).occluders.back(), "Tom & \"Jerry\"");
    EXPECT_EQ(*snaxels::with_object_drawing(*amp, "Tom & \"Jerry\"", ObjectDrawing::Drawn), kStyle);
}

TEST(StyleEdit, AStyleWithoutContentOrOnOneLineTakesTheElement) {
    EXPECT_EQ(*snaxels::with_object_drawing("<style/>\n", "A", ObjectDrawing::Hidden),
              "<style>\n  <object name=\"A\" hide=\"true\"/>\n</style>\n");
    EXPECT_EQ(*snaxels::with_object_drawing("<style version=\"1\" />", "A", ObjectDrawing::Hidden),
              "<style version=\"1\">\n  <object name=\"A\" hide=\"true\"/>\n</style>");
    EXPECT_EQ(*snaxels::with_object_drawing("<style><contour kind=\"visual\"/></style>", "A", ObjectDrawing::Occluder),
              "<style><contour kind=\"visual\"/>\n  <object name=\"A\" draw=\"false\"/>\n</style>");
}

TEST(StyleEdit, NoStyleNoEdit) {
    EXPECT_FALSE(snaxels::with_object_drawing("not a style", "A", ObjectDrawing::Hidden));
    EXPECT_FALSE(snaxels::with_object_drawing("<style><contour", "A", ObjectDrawing::Hidden));
    EXPECT_FALSE(snaxels::with_object_drawing("<drawing/>", "A", ObjectDrawing::Hidden));
    EXPECT_FALSE(snaxels::with_intersection_lines("", "A", true));
    EXPECT_FALSE(snaxels::sharp_angle_splice("not a style", "30"));
    EXPECT_FALSE(snaxels::without_absent_objects("<style>", [](const std::string&) { return false; }));
}

TEST(StyleEdit, IntersectionLinesOnAndOff) {
    const std::string text = "<style>\n  <contour kind=\"visual\"/>\n"
                             "  <contour kind=\"intersection\" object=\"Ball,Box\">\n    <visible stroke=\"#ff0000\"/>\n  </contour>\n"
                             "</style>\n";
    const auto on = snaxels::with_intersection_lines(text, "Ball", true);
    ASSERT_TRUE(on);
    std::string expected = text;
    expected.insert(expected.rfind("</style>"), "  <contour kind=\"intersection\" object=\"Ball\"/>\n");
    EXPECT_EQ(*on, expected);
    EXPECT_NO_THROW(parsed(*on));
    // Off removes the plain set it added; the one with strokes of its own is the user's.
    EXPECT_EQ(*snaxels::with_intersection_lines(*on, "Ball", false), text);
    EXPECT_EQ(*snaxels::with_intersection_lines(text, "Ball", false), text);
    const std::string own = "<style>\n  <contour kind=\"intersection\" object=\"Ball\">\n    <visible stroke=\"#ff0000\"/>\n"
                            "  </contour>\n</style>\n";
    EXPECT_EQ(*snaxels::with_intersection_lines(own, "Ball", false), own);
}

TEST(StyleEdit, SharpAngleReplacesAddsOrMakesTheSurface) {
    auto apply = [](const std::string& text, const std::string& value) {
        const auto s = snaxels::sharp_angle_splice(text, value);
        return s ? s->applied_to(text) : std::string("(none)");
    };
    EXPECT_EQ(apply("<style>\n  <surface sharp-angle = '20' smooth=\"1\"/>\n</style>\n", "file"),
              "<style>\n  <surface sharp-angle=\"file\" smooth=\"1\"/>\n</style>\n");
    EXPECT_EQ(apply("<style>\n  <surface/>\n</style>\n", "45"), "<style>\n  <surface sharp-angle=\"45\"/>\n</style>\n");
    EXPECT_EQ(apply("<style version=\"1\">\n  <contour kind=\"visual\"/>\n</style>\n", "30"),
              "<style version=\"1\">\n  <surface sharp-angle=\"30\"/>\n  <contour kind=\"visual\"/>\n</style>\n");
    // An attribute whose name only ends the same is not the one.
    EXPECT_EQ(apply("<style>\n  <surface x-sharp-angle=\"1\"/>\n</style>\n", "45"),
              "<style>\n  <surface sharp-angle=\"45\" x-sharp-angle=\"1\"/>\n</style>\n");
    // Offsets are bytes: text of several bytes per character before it.
    const std::string accented = "<!-- ångström é -->\n<style><surface sharp-angle=\"1\"/></style>";
    EXPECT_EQ(apply(accented, "60"), "<!-- ångström é -->\n<style><surface sharp-angle=\"60\"/></style>");
    EXPECT_EQ(parsed(apply("<style>\n  <surface sharp-angle=\"20\"/>\n</style>\n", "180")).surface.sharp_angle, 180.0);
}

TEST(StyleEdit, AnotherScenesObjectsLeaveTheStyle) {
    const std::string text = "<style>\n  <contour kind=\"visual\"/>\n"
                             "  <!-- <object name=\"Box\" hide=\"true\"/> -->\n"
                             "  <object name=\"Box\" hide=\"true\"/>\n"
                             "  <object name=\"Ball\" draw=\"false\"/>\n"
                             "  <object name=\"wheel*\" hide=\"true\"/>\n"
                             "  <contour kind=\"intersection\" object=\"Box\"/>\n"
                             "</style>\n";
    const std::set<std::string> scene{"ball"}; // names match ignoring case, as patterns do
    const auto out = snaxels::without_absent_objects(text, [&](const std::string& name) {
        std::string lower = name;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        return scene.count(lower) > 0;
    });
    ASSERT_TRUE(out);
    EXPECT_EQ(*out, "<style>\n  <contour kind=\"visual\"/>\n"
                    "  <!-- <object name=\"Box\" hide=\"true\"/> -->\n"
                    "  <object name=\"Ball\" draw=\"false\"/>\n"
                    "  <object name=\"wheel*\" hide=\"true\"/>\n"
                    "</style>\n");
}

} // namespace

// Restyling one object's outline: its own line set goes last, the visual
// line sets that take every object leave it to that set (so it is drawn
// once, in its own stroke), and taking the restyle back restores the text.
TEST(StyleEdit, AnObjectsOwnLinesTakeItFromTheLineSetsOfAll) {
    const std::string text = "<style version=\"1\">\n"
                             "  <contour kind=\"visual\" object=\"!Floor\">\n"
                             "    <visible stroke=\"#111111\" width=\"1.5\"/>\n"
                             "  </contour>\n"
                             "  <contour kind=\"visual\" over=\"objects\"><visible width=\"3\"/></contour>\n"
                             "  <contour kind=\"shadow\"/>\n"
                             "</style>\n";
    snaxels::ObjectLines red;
    red.colour = "#cc2200";
    red.width = 2.5;
    const auto restyled = snaxels::with_object_lines(text, "Cube", red);
    ASSERT_TRUE(restyled);
    const snaxels::Style style = snaxels::parse_style(*restyled, "test", nullptr);
    ASSERT_EQ(style.contours.size(), 4u);
    // The line set of all objects now leaves Cube out, as it left the floor.
    EXPECT_EQ(style.contours[0].spec.parts.objects, (std::vector<std::string>{"!Floor", "!Cube"}));
    EXPECT_TRUE(style.contours[1].spec.parts.over_objects); // a decoration over others: untouched
    EXPECT_TRUE(style.contours[1].spec.parts.objects.empty());
    EXPECT_EQ(style.contours[2].spec.kind, snaxels::ContourKind::Shadow);
    // Cube's own, last: its colour and width, no hidden lines.
    const snaxels::ContourStyle& own = style.contours[3];
    EXPECT_EQ(own.spec.kind, snaxels::ContourKind::Visual);
    EXPECT_EQ(own.spec.parts.objects, (std::vector<std::string>{"Cube"}));
    EXPECT_EQ(own.visible.colour, "#cc2200");
    EXPECT_DOUBLE_EQ(own.visible.width, 2.5);
    EXPECT_FALSE(own.hidden.draw);
    // Again with hidden lines: replaced, not added; no second exclusion.
    red.hidden = true;
    const auto again = snaxels::with_object_lines(*restyled, "Cube", red);
    ASSERT_TRUE(again);
    const snaxels::Style style2 = snaxels::parse_style(*again, "test", nullptr);
    ASSERT_EQ(style2.contours.size(), 4u);
    EXPECT_EQ(style2.contours[0].spec.parts.objects, (std::vector<std::string>{"!Floor", "!Cube"}));
    EXPECT_TRUE(style2.contours[3].hidden.draw);
    EXPECT_EQ(style2.contours[3].hidden.colour, "#cc2200");
    // Taken back: the text as it was, byte for byte.
    EXPECT_EQ(snaxels::with_object_lines(*again, "Cube", std::nullopt), text);
    // A line set with no object attribute takes one; taken back, it goes.
    const std::string plain = "<style>\n  <contour kind=\"visual\"/>\n</style>\n";
    const auto cut = snaxels::with_object_lines(plain, "Cube", red);
    ASSERT_TRUE(cut);
    EXPECT_NE(cut->find("<contour kind=\"visual\" object=\"!Cube\"/>"), std::string::npos) << *cut;
    EXPECT_EQ(snaxels::with_object_lines(*cut, "Cube", std::nullopt), plain);
    EXPECT_FALSE(snaxels::with_object_lines("not a style", "Cube", red));
}

// A preset chosen keeps the page of the style it replaces: the paper, its
// orientation and margin (the preset's pixel size dropped), fit and scale;
// a style of pixels passes on only its fit or scale.
TEST(StyleEdit, APresetKeepsThePageOfTheStyleItReplaces) {
    using namespace snaxels;
    const std::string preset = "<style>\n  <canvas width=\"800\" height=\"600\" margin=\"32\" background=\"#fff\"/>\n  <contour kind=\"visual\"/>\n</style>\n";
    const std::string page = "<style><canvas paper=\"A4\" orientation=\"landscape\" margin=\"12mm\" scale=\"1:30\"/></style>";
    const auto kept = with_page_of(preset, page);
    ASSERT_TRUE(kept);
    const Style s = parse_style(*kept, "kept", nullptr);
    EXPECT_EQ(s.page.width_mm, 297.0);
    EXPECT_EQ(s.page.height_mm, 210.0);
    EXPECT_EQ(s.page.scale, 30.0);
    EXPECT_NEAR(s.margin, 12.0 * 96.0 / 25.4, 1e-9);
    EXPECT_EQ(s.background, "#fff"); // the preset's own
    EXPECT_EQ(kept->find("width=\"800\""), std::string::npos);
    EXPECT_NE(kept->find("<contour kind=\"visual\"/>"), std::string::npos);
    // Pixels: only the fit goes over; the preset keeps its size and margin.
    const auto filled = with_page_of(preset, "<style><canvas width=\"300\" height=\"300\" margin=\"5\" fit=\"fill\"/></style>");
    ASSERT_TRUE(filled);
    const Style f = parse_style(*filled, "filled", nullptr);
    EXPECT_EQ(f.width, 800);
    EXPECT_EQ(f.margin, 32.0);
    EXPECT_EQ(f.page.fit, Page::Fit::Fill);
    // Nothing of a page: the preset as it is.
    EXPECT_EQ(*with_page_of(preset, "<style><canvas width=\"300\"/></style>"), preset);
    EXPECT_EQ(*with_page_of(preset, "not a style"), preset);
}
