#pragma once
/// Smoothing: projected polylines as C1 chains of cubic Béziers through a
/// subset of their points, within a pixel tolerance of the polyline.

#include <vector>

#include <glm/glm.hpp>

namespace snaxels {

/// A chain of cubics: knots[k] to knots[k+1] with controls c1[k], c2[k]
/// (closed chains have as many segments as knots).
struct BezierChain {
    std::vector<glm::dvec2> knots, c1, c2;
    bool closed = false;
};

/// Indices of the points the chains pass through, the same for every frame
/// (so animated paths keep one command structure): chosen so that, in every
/// frame, each point lies within @p tolerance of the chain and the chain
/// stays within @p tolerance of the polyline.
std::vector<std::size_t> fit_knots(const std::vector<std::vector<glm::dvec2>>& frames, bool closed, double tolerance);

/// The chain through @p points at @p knots (indices, increasing): tangents
/// follow the neighbouring knots, scaled by the segment's chord; segments
/// that join neighbouring points, or meet a sharp corner, are straight.
BezierChain bezier_chain(const std::vector<glm::dvec2>& points, const std::vector<std::size_t>& knots, bool closed);

/// Smooths one polyline: fit_knots then bezier_chain.
BezierChain smooth_polyline(const std::vector<glm::dvec2>& points, bool closed, double tolerance);

/// Points along the chain (each segment sampled @p per_segment times), for measuring it.
std::vector<glm::dvec2> sample_chain(const BezierChain& chain, int per_segment = 12);

} // namespace snaxels
