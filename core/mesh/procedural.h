#pragma once
/// Procedural closed meshes at any resolution, for tests, defaults and
/// benchmarks. Each generator aims at a face count; the result is within a
/// few percent of it (grids are whole numbers of cells).

#include <cstddef>
#include <string>
#include <vector>

#include "snaxels/mesh/triangle_soup.h"

namespace snaxels {

/// Torus around +Z with major radius 1 and minor radius 0.4.
TriangleSoup make_torus(std::size_t target_faces);
/// Unit sphere: a subdivided cube projected onto the sphere (no poles).
TriangleSoup make_sphere(std::size_t target_faces);
/// Sphere with radial sine bumps: r = 1 + 0.12 sin(6x) sin(6y) sin(6z).
TriangleSoup make_bumpy_sphere(std::size_t target_faces);
/// A head-like closed surface facing +Z: nose, nostrils, brows and chin
/// bumps and hollow eye sockets and mouth:
/// many saddles, so the visual contour changes topology often as it turns.
TriangleSoup make_nose(std::size_t target_faces);
/// The nose as a 3-D scanner gives it: every point off the surface by up
/// to a twentieth of an edge (a fixed pseudo-random value per point) and
/// ripples a few edges long. Its contours break into many small loops, as
/// a scan's do: the mesh the speed benchmarks measure beside the horse.
TriangleSoup make_scan(std::size_t target_faces);

/// The generator names accepted by make_procedural.
std::vector<std::string> procedural_names();

/// Parses "NAME[:FACES]" (for instance "torus:100000"); FACES defaults to
/// 20000. Throws snaxels::Error on an unknown name or a bad face count.
TriangleSoup make_procedural(const std::string& description);

} // namespace snaxels
