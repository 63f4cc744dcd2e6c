#include "snaxels/planarmap/region.h"

#include <algorithm>

namespace snaxels {

const char* region_class_name(RegionClass cls) {
    switch (cls) {
    case RegionClass::Shadow: return "shadow";
    case RegionClass::Lit: return "lit";
    case RegionClass::Band: return "band";
    case RegionClass::Highlight: return "highlight";
    }
    return "lit";
}

std::optional<RegionClass> parse_region_class(std::string_view name) {
    for (const RegionClass cls : {RegionClass::Shadow, RegionClass::Lit, RegionClass::Band, RegionClass::Highlight})
        if (name == region_class_name(cls)) return cls;
    return std::nullopt;
}

std::string region_class_glsl(int band_capacity, int highlight_capacity) {
    // The rule of ShadingClasses::classify, line for line.
    return "uniform bool hasShadow;\n"
           "uniform int bandCount;\n"
           "uniform float bandK[" + std::to_string(std::max(band_capacity, 1)) + "];\n"
           "uniform int highlightCount;\n"
           "uniform float highlightK[" + std::to_string(std::max(highlight_capacity, 1)) + "];\n"
           "int regionClass(float nDotL, float rDotV) {\n"
           "    int cls = hasShadow && nDotL < 0.0 ? 0 : 1;\n"
           "    for (int b = 0; b < bandCount; ++b)\n"
           "        if (cls != 0 && nDotL >= bandK[b]) cls = 2 + b;\n"
           "    for (int h = 0; h < highlightCount; ++h)\n"
           "        if (rDotV >= highlightK[h]) cls = 2 + bandCount + h;\n"
           "    return cls;\n"
           "}\n";
}

} // namespace snaxels
