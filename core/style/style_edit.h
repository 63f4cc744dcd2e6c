#pragma once
/// Edits of a style's XML text made for the user (the Objects panel's
/// states, Style > Sharp Edges, a scene replaced), found with pugixml and
/// spliced into the text: everything else stays as the user wrote it
/// (comments, spacing, quotes, attribute order), and an element that only
/// looks like one (inside a comment, say) is never touched.
///
/// Each takes the whole text and gives the new text, or std::nullopt when
/// the text is no style (it does not parse as XML, or its root is not
/// <style>): there is then no element to edit, and the caller says so.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace snaxels {

/// How a style draws an object: its <object> element's hide and draw.
enum class ObjectDrawing { Drawn, Occluder, Hidden };

/// One replacement in a text: @p length bytes at byte @p at become @p text.
struct TextSplice {
    std::size_t at = 0, length = 0;
    std::string text;
    std::string applied_to(const std::string& original) const {
        return std::string(original).replace(at, length, text);
    }
};

/// @p text with the object named exactly @p name drawn as @p state: the
/// <object> elements whose name is exactly @p name are removed (with the
/// line they stand on) and, unless @p state is Drawn, one element setting
/// it goes last in <style>, on a line of its own. Patterns that match it
/// among others stay as they are.
std::optional<std::string> with_object_drawing(const std::string& text, const std::string& name, ObjectDrawing state);

/// @p text with the line set drawing exactly @p name's intersection lines
/// (<contour kind="intersection" object="NAME"/>) added last in <style>
/// (@p on) or removed (with the line it stands on).
std::optional<std::string> with_intersection_lines(const std::string& text, const std::string& name, bool on);

/// How the Objects panel draws one object's outline: its colour, width and
/// whether its hidden stretches are drawn (dashed).
struct ObjectLines {
    std::string colour = "#111111";
    double width = 1.5;
    bool hidden = false;
};

/// @p text with the visual contour on the object named exactly @p name
/// drawn as @p lines: the line set <contour kind="visual" object="NAME">
/// with those strokes goes last in <style> (replacing the one there was),
/// and every visual line set that takes all objects (no object pattern of
/// its own but exclusions, no material, not over="objects") leaves NAME to
/// it (",!NAME" in its object patterns). Without @p lines, the object's line
/// set goes and the others take NAME again.
std::optional<std::string> with_object_lines(const std::string& text, const std::string& name,
                                             const std::optional<ObjectLines>& lines);

/// The replacement that sets attribute @p name of the first <@p element>
/// in <style> to @p value: the value replaced where it is given, the
/// attribute added to an element without it, or the element made first in
/// <style>; without @p value, the attribute removed (an empty splice where
/// there is none).
std::optional<TextSplice> attribute_splice(const std::string& text, const std::string& element, const std::string& name,
                                          const std::optional<std::string>& value);

/// The replacement that sets <surface sharp-angle="VALUE"> (attribute_splice).
std::optional<TextSplice> sharp_angle_splice(const std::string& text, const std::string& value);

/// @p text with <canvas>'s @p attributes set (a value) or removed (none),
/// in order, as attribute_splice does: the page setup's edit.
std::optional<std::string> with_canvas(const std::string& text,
                                       const std::vector<std::pair<std::string, std::optional<std::string>>>& attributes);

/// @p text on the page of style @p from: its <canvas> takes @p from's
/// paper, orientation and margin (on paper, replacing its own width and
/// height), fit, scale and model-units, where @p from gives them. What a
/// preset chosen keeps of the style it replaces. @p text as it is when
/// @p from gives none of these (or is no style).
std::optional<std::string> with_page_of(const std::string& text, const std::string& from);

/// @p text without the elements that name, exactly (a name with no glob
/// character), an object @p has_object denies: <object name="NAME"> and
/// <contour kind="intersection" object="NAME"> (with the line each stands
/// on). What a scene's own parts leave in a style when another scene
/// replaces it; patterns stay, as they may suit any scene.
std::optional<std::string> without_absent_objects(const std::string& text,
                                                  const std::function<bool(const std::string&)>& has_object);

} // namespace snaxels
