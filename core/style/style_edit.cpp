#include "snaxels/style/style_edit.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include <pugixml.hpp>

#include "snaxels/mesh/parts.h"
#include "snaxels/util/detail/xml_text.h"

namespace snaxels {

namespace {

/// The style's text parsed: its elements know their offsets in the text
/// (pugixml's offset_debug, valid while the document is unchanged).
struct ParsedStyle {
    pugi::xml_document doc;
    pugi::xml_node root;
};

bool parsed(const std::string& text, ParsedStyle& out) {
    if (!out.doc.load_buffer(text.data(), text.size(), pugi::parse_default)) return false;
    out.root = out.doc.child("style");
    return bool(out.root);
}

/// Where @p node's element starts in the text parsed: its '<' (pugixml
/// gives the offset of its name).
std::size_t element_start(const pugi::xml_node& node) { return std::size_t(node.offset_debug()) - 1; }

/// The byte just past the tag that starts at @p at ('<'), quotes respected.
std::size_t tag_end(const std::string& text, std::size_t at) {
    char quote = 0;
    for (std::size_t i = at; i < text.size(); ++i) {
        const char c = text[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '>') {
            return i + 1;
        }
    }
    return text.size();
}

/// The byte just past @p node's element: its empty tag, or its end tag.
std::size_t element_end(const std::string& text, const pugi::xml_node& node) {
    const std::size_t start = element_start(node);
    std::size_t at = tag_end(text, start);
    if (at >= 2 && text[at - 2] == '/') return at;
    // Content: skip to the matching end tag (comments, CDATA and
    // processing instructions hold no tags).
    int depth = 1;
    while (depth > 0) {
        at = text.find('<', at);
        if (at == std::string::npos) return text.size();
        auto skip = [&](const char* open, const char* close) {
            if (text.compare(at, std::char_traits<char>::length(open), open) != 0) return false;
            const std::size_t e = text.find(close, at);
            at = e == std::string::npos ? text.size() : e + std::char_traits<char>::length(close);
            return true;
        };
        if (skip("<!--", "-->") || skip("<![CDATA[", "]]>") || skip("<?", "?>")) continue;
        const bool closing = text.compare(at, 2, "</") == 0;
        const std::size_t end = tag_end(text, at);
        if (closing) --depth;
        else if (!(end >= 2 && text[end - 2] == '/')) ++depth;
        at = end;
    }
    return at;
}

/// The bytes of @p node's element and, when it stands on a line of its
/// own, that line (its indent and its newline).
std::pair<std::size_t, std::size_t> element_line(const std::string& text, const pugi::xml_node& node) {
    std::size_t a = element_start(node), b = element_end(text, node);
    std::size_t s = a;
    while (s > 0 && (text[s - 1] == ' ' || text[s - 1] == '\t')) --s;
    std::size_t e = b;
    while (e < text.size() && (text[e] == ' ' || text[e] == '\t')) ++e;
    const bool line_start = s == 0 || text[s - 1] == '\n';
    const bool line_end = e == text.size() || text[e] == '\n' || text[e] == '\r';
    if (line_start && line_end) {
        if (e < text.size() && text[e] == '\r') ++e;
        if (e < text.size() && text[e] == '\n') ++e;
        return {s, e};
    }
    return {a, b};
}

/// @p text without the elements @p doomed (spans of element_line).
std::string without(const std::string& text, std::vector<std::pair<std::size_t, std::size_t>> doomed) {
    std::sort(doomed.begin(), doomed.end());
    std::string out;
    std::size_t at = 0;
    for (const auto& [a, b] : doomed) {
        if (a < at) continue; // inside one removed already
        out.append(text, at, a - at);
        at = b;
    }
    out.append(text, at, std::string::npos);
    return out;
}

/// Where a new last child of <style> goes in @p text: the start of the line
/// of its end tag (or the end tag itself when other content shares its line).
std::size_t end_tag_line(const std::string& text) {
    const std::size_t end = text.rfind("</style");
    if (end == std::string::npos) return text.size();
    std::size_t at = end;
    while (at > 0 && (text[at - 1] == ' ' || text[at - 1] == '\t')) --at;
    return at > 0 && text[at - 1] != '\n' ? end : at;
}

/// @p text (a style whose root has content) with @p element appended as
/// the root's last child, on a line of its own, two spaces in.
std::string with_last_child(const std::string& text, const std::string& element) {
    std::string out = text;
    const std::size_t at = end_tag_line(out);
    const bool own_line = at == 0 || out[at - 1] == '\n';
    out.insert(at, (own_line ? "" : "\n") + std::string("  ") + element + "\n");
    return out;
}

/// Where attribute @p name of the tag at @p start ('<') is in @p text: the
/// span of the whole attribute (name to closing quote) and of its value
/// (inside the quotes); nothing when the tag has no such attribute.
struct AttributeSpan {
    std::size_t at = 0, end = 0, value = 0, value_end = 0;
};
std::optional<AttributeSpan> attribute_span(const std::string& text, std::size_t start, const std::string& name) {
    const std::size_t end = tag_end(text, start);
    const std::string tag = text.substr(start, end - start);
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    // The attribute's name, then its value in either quotes.
    for (std::size_t at = tag.find(name); at != std::string::npos; at = tag.find(name, at + 1)) {
        if (at == 0 || !blank(tag[at - 1])) continue; // the end of another attribute's name
        std::size_t v = at + name.size();
        while (v < tag.size() && blank(tag[v])) ++v;
        if (v >= tag.size() || tag[v] != '=') continue;
        ++v;
        while (v < tag.size() && blank(tag[v])) ++v;
        if (v >= tag.size() || (tag[v] != '"' && tag[v] != '\'')) continue;
        const std::size_t close = tag.find(tag[v], v + 1);
        if (close == std::string::npos) continue;
        return AttributeSpan{start + at, start + close + 1, start + v + 1, start + close};
    }
    return std::nullopt;
}

/// @p text with @p splices (on disjoint spans) applied.
std::string spliced(std::string text, std::vector<TextSplice> splices) {
    std::sort(splices.begin(), splices.end(), [](const TextSplice& a, const TextSplice& b) { return a.at > b.at; });
    for (const TextSplice& s : splices) text = s.applied_to(text);
    return text;
}

bool is_intersection_set(const pugi::xml_node& node) {
    return std::string(node.name()) == "contour" && std::string(node.attribute("kind").value()) == "intersection";
}

/// @p text with the root's children @p doomed removed and @p element (if
/// any) added last; a root written as an empty tag (<style/>) is opened.
std::optional<std::string> edited(const std::string& text, const ParsedStyle& style,
                                  const std::function<bool(const pugi::xml_node&)>& doomed, const std::string& element) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    for (const pugi::xml_node& child : style.root.children())
        if (child.type() == pugi::node_element && doomed(child)) spans.push_back(element_line(text, child));
    std::string out = without(text, spans);
    if (element.empty()) return out;
    const std::size_t root = element_start(style.root), root_tag = tag_end(text, root);
    if (root_tag >= 2 && text[root_tag - 2] == '/') { // <style/>: opened, the element its content
        std::size_t open_end = root_tag - 2;
        while (open_end > root && (text[open_end - 1] == ' ' || text[open_end - 1] == '\t')) --open_end;
        return text.substr(0, open_end) + ">\n  " + element + "\n</style>" + text.substr(root_tag);
    }
    return with_last_child(out, element);
}

} // namespace

std::optional<std::string> with_object_drawing(const std::string& text, const std::string& name, ObjectDrawing state) {
    ParsedStyle style;
    if (!parsed(text, style)) return std::nullopt;
    const std::string element =
        state == ObjectDrawing::Drawn ? std::string()
                                      : "<object name=\"" + xml_text(name) + "\" " +
                                            (state == ObjectDrawing::Hidden ? "hide=\"true\"" : "draw=\"false\"") + "/>";
    return edited(
        text, style,
        [&](const pugi::xml_node& n) { return std::string(n.name()) == "object" && n.attribute("name").value() == name; },
        element);
}

std::optional<std::string> with_intersection_lines(const std::string& text, const std::string& name, bool on) {
    ParsedStyle style;
    if (!parsed(text, style)) return std::nullopt;
    const std::string element = on ? "<contour kind=\"intersection\" object=\"" + xml_text(name) + "\"/>" : std::string();
    // Only a set with nothing else to it (no strokes of its own, no other
    // selector) is the one this edit adds and removes.
    return edited(
        text, style,
        [&](const pugi::xml_node& n) {
            if (!is_intersection_set(n) || n.first_child() || n.attribute("object").value() != name) return false;
            return std::distance(n.attributes_begin(), n.attributes_end()) == 2;
        },
        element);
}

std::optional<TextSplice> attribute_splice(const std::string& text, const std::string& element, const std::string& name,
                                          const std::optional<std::string>& value) {
    ParsedStyle style;
    if (!parsed(text, style)) return std::nullopt;
    const std::string attribute = value ? name + "=\"" + xml_text(*value) + "\"" : std::string();
    if (const pugi::xml_node node = style.root.child(element.c_str())) {
        const std::size_t start = element_start(node);
        if (const auto a = attribute_span(text, start, name)) {
            if (value) return TextSplice{a->at, a->end - a->at, attribute};
            std::size_t at = a->at; // removed with the blank before it
            while (at > start && (text[at - 1] == ' ' || text[at - 1] == '\t')) --at;
            return TextSplice{at, a->end - at, ""};
        }
        if (!value) return TextSplice{start, 0, ""}; // nothing to remove
        return TextSplice{start + 1 + element.size(), 0, " " + attribute};
    }
    if (!value) return TextSplice{0, 0, ""};
    const std::size_t root = element_start(style.root), root_tag = tag_end(text, root);
    if (root_tag >= 2 && text[root_tag - 2] == '/') return std::nullopt; // <style/>: no content to add to
    return TextSplice{root_tag, 0, "\n  <" + element + " " + attribute + "/>"};
}

std::optional<TextSplice> sharp_angle_splice(const std::string& text, const std::string& value) {
    return attribute_splice(text, "surface", "sharp-angle", value);
}

std::optional<std::string> with_canvas(const std::string& text,
                                       const std::vector<std::pair<std::string, std::optional<std::string>>>& attributes) {
    std::string out = text;
    for (const auto& [name, value] : attributes) {
        const auto splice = attribute_splice(out, "canvas", name, value);
        if (!splice) return std::nullopt;
        out = splice->applied_to(out);
    }
    return out;
}

std::optional<std::string> with_page_of(const std::string& text, const std::string& from) {
    ParsedStyle source;
    if (!parsed(from, source)) return text; // no page to keep
    const pugi::xml_node canvas = source.root.child("canvas");
    const bool paper = canvas.attribute("paper");
    std::vector<std::pair<std::string, std::optional<std::string>>> page;
    if (paper) page = {{"width", std::nullopt}, {"height", std::nullopt}};
    // The margin is the page's on paper; on pixels it is the canvas's own.
    for (const char* name : {"paper", "orientation", "margin", "fit", "scale", "model-units"}) {
        if (!paper && (std::string(name) == "margin" || std::string(name) == "orientation")) continue;
        if (const pugi::xml_attribute a = canvas.attribute(name)) page.emplace_back(name, std::string(a.value()));
    }
    if (page.empty()) return text;
    return with_canvas(text, page);
}

std::optional<std::string> without_absent_objects(const std::string& text,
                                                  const std::function<bool(const std::string&)>& has_object) {
    ParsedStyle style;
    if (!parsed(text, style)) return std::nullopt;
    auto exact_and_absent = [&](const std::string& name) {
        return !name.empty() && name.find_first_of("*?,!") == std::string::npos && !has_object(name);
    };
    return edited(
        text, style,
        [&](const pugi::xml_node& n) {
            const std::string element = n.name();
            if (element == "object") return exact_and_absent(n.attribute("name").value());
            return is_intersection_set(n) && exact_and_absent(n.attribute("object").value());
        },
        std::string());
}

namespace {

/// A visual line set that takes every object (no object pattern but
/// exclusions, no material, not over="objects"): where one object's own
/// line set leaves it out.
bool takes_every_object(const pugi::xml_node& n) {
    if (std::string(n.name()) != "contour" || std::string(n.attribute("kind").value()) != "visual") return false;
    if (n.attribute("material") || n.attribute("over")) return false;
    for (const std::string& p : split_patterns(n.attribute("object").value()))
        if (p.empty() || p[0] != '!') return false;
    return true;
}

/// The splices that add "!NAME" to (@p exclude), or take it from, the object
/// patterns of every visual line set that takes every object.
std::vector<TextSplice> exclusions(const std::string& text, const ParsedStyle& style, const std::string& name, bool exclude) {
    std::vector<TextSplice> out;
    const std::string excluded = "!" + name;
    for (const pugi::xml_node& n : style.root.children()) {
        if (n.type() != pugi::node_element || !takes_every_object(n)) continue;
        std::vector<std::string> patterns = split_patterns(n.attribute("object").value());
        const auto it = std::find(patterns.begin(), patterns.end(), excluded);
        if (exclude == (it != patterns.end())) continue; // as it should be already
        if (exclude) patterns.push_back(excluded);
        else patterns.erase(it);
        std::string value;
        for (const std::string& p : patterns) value += (value.empty() ? "" : ",") + p;
        const std::size_t start = element_start(n);
        const auto a = attribute_span(text, start, "object");
        if (!a) { // last in the tag, before its '>' or '/>'
            std::size_t at = tag_end(text, start) - 1;
            if (at > start && text[at - 1] == '/') --at;
            while (at > start && (text[at - 1] == ' ' || text[at - 1] == '\t')) --at;
            out.push_back({at, 0, " object=\"" + xml_text(value) + "\""});
        }
        else if (value.empty()) out.push_back({a->at - 1, a->end - a->at + 1, ""}); // with the blank before it
        else out.push_back({a->value, a->value_end - a->value, xml_text(value)});
    }
    return out;
}

} // namespace

std::optional<std::string> with_object_lines(const std::string& text, const std::string& name,
                                             const std::optional<ObjectLines>& lines) {
    ParsedStyle style;
    if (!parsed(text, style)) return std::nullopt;
    const std::string first = spliced(text, exclusions(text, style, name, lines.has_value()));
    ParsedStyle again;
    if (!parsed(first, again)) return std::nullopt;
    std::string element;
    if (lines) {
        char width[32], hidden_width[32];
        std::snprintf(width, sizeof width, "%g", lines->width);
        std::snprintf(hidden_width, sizeof hidden_width, "%g", lines->width * 2.0 / 3.0);
        const std::string colour = xml_text(lines->colour);
        element = "<contour kind=\"visual\" object=\"" + xml_text(name) + "\"><visible stroke=\"" + colour +
                  "\" width=\"" + width + "\"/>" +
                  (lines->hidden ? "<hidden stroke=\"" + colour + "\" width=\"" + hidden_width +
                                       "\" opacity=\"0.55\" dash=\"4 3\" cap=\"butt\"/>"
                                 : std::string("<hidden draw=\"false\"/>")) +
                  "</contour>";
    }
    // The object's own line set: a visual contour on exactly NAME, with strokes of its own.
    return edited(
        first, again,
        [&](const pugi::xml_node& n) {
            return std::string(n.name()) == "contour" && std::string(n.attribute("kind").value()) == "visual" &&
                   n.attribute("object").value() == name && !n.attribute("material") && !n.attribute("over");
        },
        element);
}

} // namespace snaxels
