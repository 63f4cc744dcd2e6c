#pragma once
/// Hard edges. A surface is shaded with one normal per face corner: where the
/// corners at a vertex agree across an edge the surface is smooth there; where
/// they part, the edge is sharp (a box's edges, a car's panel lines, a
/// smoothing-group boundary). The engine works on vertex normals, so a sharp
/// edge is given a width of zero: each vertex is copied once per wedge of
/// faces between sharp edges, and the copies are joined by faces of zero
/// area (a strip along each sharp edge, a fan where three or more wedges
/// meet). The surface stays one closed piece; across a strip the normal
/// turns from one side's to the other's as if the edge were rounded with a
/// radius of zero, so every contour that crosses the edge follows it for as
/// long as the two sides disagree (docs/engine.md, "Sharp edges").

#include <cstddef>
#include <optional>

#include "snaxels/mesh/build.h"

namespace snaxels {

/// SurfaceOptions::sharp_angle for "where the file's own normals part".
inline constexpr double kFileNormals = -1.0;

/// How a surface's sharp edges are found.
struct SurfaceOptions {
    /// Degrees: an edge whose faces meet at more than this angle is sharp (an
    /// auto-smooth angle; 180 makes every edge smooth). kFileNormals (the
    /// default): the edges where the file's corner normals part; when the
    /// file has no normals, the edges whose faces meet at more than
    /// kNoNormalsSharpAngle, where they make feature lines (see there).
    double sharp_angle = kFileNormals;

    bool operator==(const SurfaceOptions&) const = default;
};

/// A mesh without normals (a CAD export, a subdivision cage, a scan) is
/// shaded as Blender's smooth-by-angle default shades it: an edge whose
/// faces meet at more than this many degrees is sharp. Only sharp edges
/// that make feature lines count: sets of joined sharp edges whose runs
/// (between ends and branchings) are on the average at least
/// kFeatureLineShare of the bounding box's diagonal long (a box's edges, a
/// cylinder's rims, a part's creases, any coarse mesh's edges); the short
/// runs and branching networks of a scanner's noise or a fine mesh's tight
/// spots stay smooth.
inline constexpr double kNoNormalsSharpAngle = 30.0;
inline constexpr double kFeatureLineShare = 0.05;

/// Two of a file's normals at one vertex closer than this many degrees are
/// the same normal (exporters round normals to single precision, and some
/// write one per corner without merging them).
inline constexpr double kSameNormalDegrees = 1.0;

/// What split_sharp_edges did.
struct SharpSplit {
    std::size_t sharp_edges = 0; ///< edges found sharp
    std::size_t copies = 0;      ///< vertex copies made (one per extra wedge)
    std::size_t strip_faces = 0; ///< zero-area faces added along sharp edges and at corners
};

/// @p loaded with its sharp edges split (see the file comment): the original
/// vertices keep their ids and come first, copies follow (vertex_source
/// names the same input vertex as their original, so an animated pose moves
/// them together), the original faces keep their ids and the zero-area
/// faces come last. Vertex normals: the mean of the file's normals at each
/// vertex's corners when the file's normals decide, else area-weighted
/// over each wedge (as make_pose computes them for a moved pose).
/// When no vertex has two wedges the mesh is smooth everywhere: then it
/// comes back unsplit with the file's normals (their mean at each vertex)
/// where the file's normals decide and differ from the mesh's own, and
/// nothing (std::nullopt) otherwise: the mesh is used as it is.
std::optional<LoadedMesh> split_sharp_edges(const LoadedMesh& loaded, const SurfaceOptions& options,
                                            SharpSplit* what = nullptr);

/// split_sharp_edges' result when there is one, else @p loaded: the mesh the
/// engine should draw. @p storage holds the split mesh.
const LoadedMesh& with_sharp_edges(const LoadedMesh& loaded, const SurfaceOptions& options,
                                   std::optional<LoadedMesh>& storage);

} // namespace snaxels
