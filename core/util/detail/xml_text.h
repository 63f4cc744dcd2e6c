#pragma once
/// Text written into XML (an attribute's value, or character data) with
/// its special characters escaped: shared by the SVG writers and the
/// style edits (snaxels/style/style_edit.h).

#include <string>

namespace snaxels {

/// @p text with XML's special characters escaped, for an attribute's value.
inline std::string xml_text(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

} // namespace snaxels
