#pragma once
/// The XML style language (reference: docs/styles.md): what to draw of each
/// contour kind, visible and hidden, and how; the canvas; the light.

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "snaxels/error.h"
#include "snaxels/mesh/sharp_edges.h"
#include "snaxels/planarmap/region.h"
#include "snaxels/scene/camera.h"
#include "snaxels/style/page.h"
#include "snaxels/snaxel/contour_function.h"

namespace snaxels {

/// Default stroke colour of a contour kind (until styles say otherwise).
const char* default_stroke(ContourKind kind);

struct StrokeStyle {
    bool draw = true;
    std::string colour = "#111111";
    double width = 1.5;
    double opacity = 1.0;
    std::vector<double> dash;           ///< on, off, ... in pixels; empty: solid
    bool dash_on_surface = false;       ///< dashes fastened to the surface, not the screen
    std::string cap = "round";          ///< butt | round | square
    std::string join = "round";         ///< miter | round | bevel
    double smoothing = 0.0;             ///< Bézier fit tolerance in pixels; 0: polyline

    // Line weight (docs/styles.md, "Line weight"). Width at a point of a run:
    // the base width (width, or width-min to width-max by width_by), times
    // the taper toward the run's ends, times the calligraphic nib's factor.
    /// taper="START END": lengths over which the width grows from 0 at a
    /// run's start and falls to 0 at its end; pixels, or fractions of the
    /// run's length where the flag says so. 0: no taper at that end.
    double taper_start = 0.0, taper_end = 0.0;
    bool taper_start_fraction = false, taper_end_fraction = false;
    /// width-by: what the width follows between width_min and width_max.
    enum class WidthBy { None, Depth, Light, Curvature, Qi, Strength };
    WidthBy width_by = WidthBy::None;
    double width_min = -1.0, width_max = -1.0; ///< negative: half and one and a half times width
    /// calligraphy="ANGLE RATIO": a flat nib at ANGLE degrees (from the
    /// image's x axis, counter-clockwise as seen); a line drawn along the nib
    /// is RATIO times as wide as one drawn across it. 1: none.
    double calligraphy_angle = 0.0, calligraphy_ratio = 1.0;
    /// wobble="AMPLITUDE WAVELENGTH": the line displaced across itself by
    /// a smooth noise along the stroke parameter (pixels); 0: none.
    double wobble_amplitude = 0.0, wobble_wavelength = 20.0;
    /// boil="RATE": the wobble's noise drawn afresh RATE times a second.
    double boil_rate = 0.0;

    /// The width varies along the line: drawn as a filled outline.
    bool variable_width() const {
        return taper_start > 0.0 || taper_end > 0.0 || width_by != WidthBy::None || calligraphy_ratio < 1.0;
    }
    /// The line reads the stroke parameter carried on the surface
    /// (DrawnLoop::u): it is variable-width, wobbles, or has dashes
    /// fastened to the surface.
    bool needs_parameter() const { return variable_width() || carries_parameter(); }
    /// The line reads the parameter's values, not only arc length along its
    /// runs: it wobbles or has dashes fastened to the surface (a line that
    /// only varies in width needs none carried through an animation).
    bool carries_parameter() const { return wobble_amplitude > 0.0 || (dash_on_surface && !dash.empty()); }
    double min_width() const { return width_min >= 0.0 ? width_min : 0.5 * width; }
    double max_width() const { return width_max >= 0.0 ? width_max : 1.5 * width; }
};

/// The name width-by gives @p by ("none", "depth", ...).
const char* width_by_name(StrokeStyle::WidthBy by);

struct ContourStyle {
    ContourSpec spec;
    StrokeStyle visible, hidden;
    /// Suggestive contours: the strength (suggestive_strength, how far past
    /// its threshold the test passes) at which a width-by="strength" stroke
    /// is half way from width-min to width-max: its weight is m / (fade + m)
    /// for strength m > 0 (rtsc's fading). Negative: the test's default,
    /// kDefaultFade for rtsc's and kDefaultDerivativeFade for the derivative's.
    double fade = -1.0;
    static constexpr double kDefaultFade = 0.03, kDefaultDerivativeFade = 1.0;
    double fade_or_default() const {
        return fade >= 0.0 ? fade : spec.test == SuggestiveTest::Rtsc ? kDefaultFade : kDefaultDerivativeFade;
    }
};

/// How one class of planar-map region is filled.
struct RegionStyle {
    RegionClass cls = RegionClass::Lit;
    double k = 0.0;        ///< band: the isophote level it starts at; highlight: the gleam threshold
    std::string fill = "#cccccc";
    double opacity = 1.0;
    double erosion = 0.0;  ///< pixels the fill is shrunk by, to part it from the strokes
    /// fill="material": the region's material's colour, shaded by `shade`
    /// (fill then holds the colour for a region without a material).
    bool fill_material = false;
    /// The factor a material's colour is shaded by: below 1 darker (times
    /// the colour), above 1 lighter (that far toward white: 2 is white);
    /// negative: the class's default (region_shade).
    double shade = -1.0;
    PartSelector parts{}; ///< the parts whose regions of the class it fills (<region object= material=>)
};

struct Style {
    int width = 800, height = 800;      ///< the canvas in CSS pixels (from the paper, when it has one)
    /// Pixels between the mesh's bounding circle and the edge; on paper,
    /// the page's margin, which every view stays inside.
    double margin = 32.0;
    Page page; ///< the paper, fit and scale (core/style/page.h); none by default
    std::string background = "#ffffff"; ///< or "none"
    std::optional<Light> light;
    SurfaceOptions surface; ///< where the surface's edges are sharp
    std::vector<ContourStyle> contours;
    std::vector<RegionStyle> regions; ///< fills; empty: none
    /// Object patterns of <object draw="false">: parts kept as occluders,
    /// hiding what lies behind them, with none of their lines drawn.
    std::vector<std::string> occluders;
    /// Object patterns of <object hide="true">: parts left out of the
    /// scene, neither drawn nor hiding anything (scene_surface).
    std::vector<std::string> hidden_objects;
    /// Every part selector of the document and where it is, to be checked
    /// against a scene's parts (check_parts).
    struct PartPatterns {
        PartSelector selector;
        int line = 0, column = 0;
    };
    std::vector<PartPatterns> part_patterns;

    /// The contours the fills need besides those drawn: the shadow contour
    /// for lit and shadow, an isophote per band, a gleam per highlight.
    std::vector<ContourSpec> fill_contours() const;
    /// The fill of a region class (nullptr: not filled): the first
    /// <region> of the class (whatever its parts).
    const RegionStyle* region(RegionClass cls, double k) const;
    /// The fill of @p region: the first <region> of its class that takes its
    /// part (its object and material, named in @p parts), or nullptr.
    const RegionStyle* region(const MapRegion& region, const FaceParts* parts) const;

    /// The style of @p spec: the <contour> of its kind and parts, else the
    /// first of its kind, else the defaults for its kind.
    ContourStyle contour(const ContourSpec& spec) const;
    /// @p spec drawn without the occluder-only objects (occluders).
    ContourSpec drawn(ContourSpec spec) const;
};

/// Default strokes of a kind: the colour of its kind, solid when visible,
/// thinner, faded and dashed when hidden.
ContourStyle default_contour_style(const ContourSpec& spec);

/// A linear colour channel (0 to 1, clamped) as an sRGB byte, as screens
/// and SVG colours take it.
int srgb_byte(double linear);

/// A region class's default shade for fill="material": shadow 0.55, lit 1,
/// a band 1.2, a highlight 1.7.
double region_shade(RegionClass cls);

/// The colour @p region is filled with by @p style: the style's colour, or
/// with fill="material" its material's (from @p parts; linear RGB shaded,
/// then written as sRGB #rrggbb).
std::string region_fill_colour(const RegionStyle& style, const MapRegion& region, const FaceParts* parts);

/// The 0xRRGGBB value of a colour the style language accepts (#rrggbb,
/// #rgb, a CSS colour name; lower case as the parser stores it).
std::uint32_t colour_rgb(const std::string& colour);

/// The built-in style: the visual contour in ink, hidden lines dashed.
Style default_style();

/// A problem in a style document at a line and column (1-based).
struct StyleDiagnostic {
    int line = 0, column = 0;
    std::string message;
};

/// A style that cannot be used; what() is "SOURCE:LINE:COL: message".
class StyleError : public Error {
  public:
    StyleError(const std::string& source, StyleDiagnostic diagnostic);
    const StyleDiagnostic& diagnostic() const { return diagnostic_; }

  private:
    StyleDiagnostic diagnostic_;
};

/// One attribute of a style element: its name, the words it takes (all of
/// them where it is one of a few words: cap, kind, class...; the special
/// ones beside numbers or colours: background="none"; else none) and what
/// it does in one line, as the style reference (docs/styles.md) begins
/// its meaning.
struct StyleAttribute {
    std::string name;
    std::vector<std::string> values;
    std::string summary;
};

/// One element of the style language, what it is in one line, and every
/// attribute it takes.
struct StyleElement {
    std::string name;
    std::string summary;
    std::vector<StyleAttribute> attributes;
};

/// The style language's vocabulary: every element, its attributes, their
/// words and what each does. The parser checks documents against it (an
/// attribute not listed warns; a word not listed is an error), the
/// application's style editor completes and explains from it, and the
/// style reference's tables begin each meaning with its summaries (a test
/// holds them to it), so none of them can drift apart.
const std::vector<StyleElement>& style_vocabulary();
/// The element called @p name in style_vocabulary(), or nullptr.
const StyleElement* style_element(const std::string& name);

/// Parses style XML. Errors throw StyleError; unknown elements and
/// attributes are added to @p warnings (named, with their position) and
/// otherwise ignored. @p source names the document in messages.
Style parse_style(const std::string& text, const std::string& source, std::vector<StyleDiagnostic>* warnings);

/// The style's part patterns that match nothing in @p parts, as warnings
/// at their elements, each naming the pattern and what the scene has.
std::vector<StyleDiagnostic> check_parts(const Style& style, const FaceParts& parts);

/// Reads and parses a style file; an unreadable file throws snaxels::Error.
Style load_style(const std::string& path, std::vector<StyleDiagnostic>* warnings);

} // namespace snaxels
