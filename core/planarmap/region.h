#pragma once
/// The regions of a planar map and their classes, in one place for every
/// part that classes the surface: both maps (snaxel_map.h, post_map.h), the
/// exporters, the style's <region> entries and the application's 3-D view.
///
/// A seen point of the surface is in shadow (N.L < 0, when the map has a
/// shadow contour), else lit; a lit point inside isophote bands takes the
/// brightest band whose level it reaches; a point inside gleams takes the
/// highest highlight level it reaches, whatever its shading. Classes are
/// numbered 0 shadow, 1 lit, then one per band (ascending level), then one
/// per highlight level (ascending threshold).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels {

enum class RegionClass { Shadow, Lit, Band, Highlight };

/// "shadow", "lit", "band" or "highlight".
const char* region_class_name(RegionClass cls);
/// The class named @p name (as region_class_name gives it), or none.
std::optional<RegionClass> parse_region_class(std::string_view name);
/// Band and highlight regions come in levels, told apart by their k.
inline bool region_class_has_level(RegionClass cls) { return cls == RegionClass::Band || cls == RegionClass::Highlight; }

struct MapRegion {
    RegionClass cls = RegionClass::Lit;
    double k = 0.0;  ///< band: the isophote level it starts at; highlight: the gleam threshold
    int depth = 0;   ///< depth order of its patch, 0 nearest
    std::vector<std::vector<glm::dvec2>> polygons; ///< image pixels; holes wind the other way (non-zero fill)
    double area = 0.0; ///< square pixels
    /// On a mesh with parts: the object and the material the region shows
    /// (indices into the mesh's FaceParts; a region never spans two);
    /// -1 without parts.
    std::int32_t object = -1, material = -1;
};

/// The numbered classes of one map, from its contours: whether it has a
/// shadow, its band levels and its highlight thresholds (each ascending).
class ShadingClasses {
  public:
    ShadingClasses(bool shadow, std::vector<double> band_levels, std::vector<double> highlight_levels)
        : shadow_(shadow), bands_(std::move(band_levels)), highlights_(std::move(highlight_levels)) {}

    int count() const { return first_highlight() + int(highlights_.size()); }
    int bands() const { return int(bands_.size()); }
    int first_highlight() const { return 2 + bands(); }
    bool has_shadow() const { return shadow_; }

    RegionClass region_class(int cls) const {
        return cls == 0 ? RegionClass::Shadow
               : cls == 1 ? RegionClass::Lit
               : cls < first_highlight() ? RegionClass::Band
                                         : RegionClass::Highlight;
    }
    /// A band's level or a highlight's threshold; 0 for shadow and lit.
    double level(int cls) const {
        return cls >= first_highlight() ? highlights_[cls - first_highlight()]
               : cls >= 2               ? bands_[cls - 2]
                                        : 0.0;
    }

    /// The class of a point from which side of each contour it is on:
    /// @p in_shadow (ignored without a shadow contour), in_band(b) for each
    /// band b and in_highlight(h) for each highlight level h.
    template <class InBand, class InHighlight>
    int classify(bool in_shadow, InBand&& in_band, InHighlight&& in_highlight) const {
        int cls = shadow_ && in_shadow ? 0 : 1;
        for (int b = 0; b < bands(); ++b)
            if (cls != 0 && in_band(b)) cls = 2 + b; // the brightest band wins
        for (int h = 0; h < int(highlights_.size()); ++h)
            if (in_highlight(h)) cls = first_highlight() + h; // the highest threshold met
        return cls;
    }
    /// The class of a point from its N.L alone (no highlight): where only
    /// the light is known, as on the surface's far side.
    int from_nl(double nl) const {
        return classify(nl < 0.0, [&](int b) { return nl >= bands_[b]; }, [](int) { return false; });
    }

  private:
    bool shadow_;
    std::vector<double> bands_, highlights_;
};

/// ShadingClasses::classify in GLSL, for a renderer that classes the surface
/// per pixel (the application's 3-D view): defines
///   int regionClass(float nDotL, float rDotV)
/// numbering classes as ShadingClasses does, from the uniforms
///   bool hasShadow; int bandCount; float bandK[]; int highlightCount; float highlightK[];
/// whose arrays hold @p band_capacity and @p highlight_capacity levels.
std::string region_class_glsl(int band_capacity, int highlight_capacity);

/// The classes of a map made from @p input's contours (a SnaxelMapInput or a
/// PostMapInput: a shadow or none, isophotes and gleams, each ascending).
template <class MapInput> ShadingClasses shading_classes(const MapInput& input) {
    std::vector<double> bands, highlights;
    for (const auto* iso : input.isophotes) bands.push_back(iso->spec.k);
    for (const auto* gleam : input.gleams) highlights.push_back(gleam->spec.k);
    return ShadingClasses(input.shadow != nullptr, std::move(bands), std::move(highlights));
}

} // namespace snaxels
