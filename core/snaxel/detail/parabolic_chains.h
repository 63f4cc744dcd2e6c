#pragma once
// The parabolic curves' last stage (find_parabolic in
// snaxels/snaxel/parabolic.h): the marks the visual events leave, clustered
// and chained into curves traced across the faces. Not installed.

#include <vector>

#include "snaxels/snaxel/parabolic.h"

namespace snaxels::detail {

/// Chains clustered marks into curves across the faces: marks within
/// @p link of each other cluster, clusters of fewer than @p min_members
/// marks are left out, chain ends within @p reach join. See docs/parabolic.md.
std::vector<ParabolicCurve> chain_curves(const MeshTopology& topo, const std::vector<ParabolicPoint>& points,
                                         double link, double reach, int min_members);

} // namespace snaxels::detail
