#pragma once
/// The parts of a scene as the engine sees them: per face of a mesh, the
/// object (a node of the file's scene graph) and the material it belongs
/// to, and the selectors styles pick parts with.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/elements.h"
#include "snaxels/mesh/triangle_soup.h"

namespace snaxels {

/// Per face: the index of its object and of its material.
struct FaceParts {
    std::vector<SceneObject> objects;
    std::vector<SceneMaterial> materials;
    FaceData<std::uint32_t> object, material;

    /// More than one object or more than one material: a scene whose parts
    /// outputs name (contours JSON, stats); one mesh of one material is
    /// written as it was before parts were kept.
    bool several() const { return objects.size() > 1 || materials.size() > 1; }
};


/// The parts of @p mesh's faces (LoadedMesh::objects and its kin), or null
/// when it has none.
std::shared_ptr<const FaceParts> loaded_parts(const LoadedMesh& mesh);

/// Which parts of the scene a line set or a fill takes. Each list holds
/// glob patterns (`*` any run of characters, `?` one; matched without
/// regard to case); a pattern beginning with `!` excludes what it matches.
/// An object matches by its name or its path in the scene graph. A face is
/// selected when its object passes the object patterns and its material
/// the material patterns; a list passes a name when none of its excluding
/// patterns matches it and, if it has including ones, one of them does.
/// Empty lists select every face.
struct PartSelector {
    std::vector<std::string> objects, materials;
    /// A visual contour's stretches where it lies over another object in
    /// the image (what lies just past its silhouette is another object):
    /// the outline of each object against the others, not against the
    /// background or itself.
    bool over_objects = false;

    bool empty() const { return objects.empty() && materials.empty() && !over_objects; }
    /// "object=A,B material=!C over=objects" (what is set), or "".
    std::string text() const;
    bool operator==(const PartSelector&) const = default;
};

/// @p text matched against the glob @p pattern (no `!`), ignoring case.
bool glob_match(const std::string& pattern, const std::string& text);

/// Splits a selector attribute's value at commas, trimming blanks around
/// each pattern; empty patterns are left out.
std::vector<std::string> split_patterns(const std::string& value);

/// A selector resolved against one scene's parts: which objects and
/// materials it takes.
class PartMatcher {
  public:
    /// @p parts may be null (a mesh without parts: every face is selected).
    PartMatcher(const PartSelector& selector, const FaceParts* parts);
    /// Every face is selected: nothing to cut.
    bool all() const { return all_; }
    /// Whether object @p o, or material @p m, passes its patterns.
    bool object(std::uint32_t o) const { return all_ || (o < objects_.size() && objects_[o]); }
    bool material(std::uint32_t m) const { return all_ || (m < materials_.size() && materials_[m]); }
    bool face(FaceId f) const {
        return all_ || (f.valid() && objects_[parts_->object[f]] && materials_[parts_->material[f]]);
    }

  private:
    const FaceParts* parts_ = nullptr;
    bool all_ = true;
    std::vector<std::uint8_t> objects_, materials_;
};

/// @p loaded without the faces of the objects @p patterns match (by name or
/// path, as PartSelector matches them): what a scene is with those objects
/// hidden, neither drawn nor hiding anything. Vertices keep their order
/// (those only hidden faces used are dropped), faces theirs; vertex_source,
/// corner normals and the faces' parts follow; the report stays the
/// loaded mesh's (the framing does not jump when a part is hidden).
/// Nothing (std::nullopt) when no face is hidden. Throws snaxels::Error
/// when every face would be.
std::optional<LoadedMesh> without_objects(const LoadedMesh& loaded, const std::vector<std::string>& patterns);

/// The patterns of @p selector that match no object or material of
/// @p parts, each with what the scene has: "object \"X\" matches none of
/// the scene's objects (A, B)". Empty when every pattern matches.
std::vector<std::string> unmatched_patterns(const PartSelector& selector, const FaceParts& parts);

} // namespace snaxels
