#pragma once
// Internal to core/export: a contour sequence's life as its animated
// stroke paths are made from it (stroke_paths in animated_strokes.cpp):
// each frame's loop parameterized by arc length, its visibility runs
// followed from frame to frame, and the writer that plans a path's keys
// and shapes them (stroke_writer.cpp), with the same shapes for one-frame
// contours (run_polyline). Not installed.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/export/detail/animated_paths.h"
#include "snaxels/export/detail/animated_strokes.h"
#include "snaxels/export/stroke_shape.h"
#include "snaxels/export/stroke_weight.h"

namespace snaxels::detail {

/// A canonical segment (keys of one vertex set) spans at most this many frames.
constexpr std::size_t kMaxSegmentFrames = 8;

inline double wrap01(double u) { return u - std::floor(u); }

/// One loop of one frame, parameterized by arc length: u in [0, 1) runs
/// round the loop from an anchor that follows the snaxels' identities.
struct ParamLoop {
    bool closed = true;
    std::vector<glm::dvec2> pts;
    std::vector<double> cum; ///< arc length at each point from point 0
    double length = 0.0;
    double anchor = 0.0;     ///< arc length where u = 0 (closed loops)
    double spacing = 1.0;    ///< mean distance between its points
    std::vector<std::uint64_t> ids;
    std::vector<ClassSpan> spans;
    /// Screen dashes: arc lengths where the QI changes (restarts_of).
    std::vector<double> restarts;
    /// With line weight: the drawn loop's stroke parameter and weights,
    /// and the frame's time (the wobble's boil).
    std::shared_ptr<const LoopAttributes> attributes;
    double u_period = 0.0;
    double seconds = 0.0;

    double arc_of_u(double u) const {
        return closed ? std::fmod(anchor + wrap01(u) * length, length) : std::clamp(u, 0.0, 1.0) * length;
    }
    double u_of_arc(double arc) const {
        if (length <= 0.0) return 0.0;
        return closed ? wrap01((arc - anchor) / length) : std::clamp(arc / length, 0.0, 1.0);
    }
    glm::dvec2 at_arc(double arc) const {
        if (pts.size() == 1 || length <= 0.0) return pts[0];
        const std::size_t n = pts.size();
        const std::size_t segs = closed ? n : n - 1;
        std::size_t k = std::size_t(std::upper_bound(cum.begin(), cum.end(), arc) - cum.begin());
        k = std::clamp<std::size_t>(k, 1, segs);
        const std::size_t i = k - 1, j = k % n;
        const double seg = (k < n ? cum[k] : length) - cum[i];
        const double t = seg > 0.0 ? std::clamp((arc - cum[i]) / seg, 0.0, 1.0) : 0.0;
        return (1.0 - t) * pts[i] + t * pts[j];
    }
    glm::dvec2 at(double u) const { return at_arc(arc_of_u(u)); }
    /// The stroke point at @p u (its position that of at(u)).
    StrokePoint stroke_at(double u) const {
        StrokePoint p = attributes ? attributes->at(arc_of_u(u)) : StrokePoint{};
        p.q = at(u);
        return p;
    }
};

/// A visibility run of one frame, in u aligned with the run it continues.
struct Run {
    int id = 0;
    ClassSpan span;
};

/// One frame of a contour sequence's life.
struct LifeFrame {
    const ParamLoop* loop = nullptr;
    bool jump = false; ///< not interpolated from the frame before
    ByClass<std::vector<Run>> runs; ///< per class, sorted by id
};

inline double extent(const ClassSpan& s) { return s.whole ? 1.0 : s.u1 - s.u0; }

/// A key of a path: the shape at time `time` (frames), between life frame
/// `i` and the next at fraction `s`, each subpath drawing `spans[j]`.
struct Key {
    std::size_t i = 0;
    double s = 0.0;
    double time = 0.0;
    std::vector<ClassSpan> spans;
};

/// Keys of one structure (a segment): subpaths `ids` (run ids; -1 is a
/// lone move, for frames without runs), whole rings or open.
struct Plan {
    std::vector<int> ids;
    std::vector<Key> keys;
};

class StrokeWriter {
  public:
    StrokeWriter(const std::vector<LifeFrame>& life, int first_frame, const AnimatedSvgOptions& options)
        : life_(life), first_frame_(first_frame), options_(options) {}

    /// A segment of a plan: its first and last life frames, the time of its
    /// first key.
    struct Range {
        std::size_t first, last;
        double start;
        bool hold_after = false; ///< a jump follows: hold the last shape until then
    };

    /// The runs of @p cls that @p keep selects, over life frames [a, b]:
    /// the path's segments. A segment's subpaths are the runs alive in any
    /// of its frames; in frames before a run appears it is a point where it
    /// will appear (the middle of its first span), after it vanishes a
    /// point where it was, so it grows and shrinks between frames.
    template <class Select>
    std::vector<Plan> plan(StrokeClass cls, std::size_t a, std::size_t b, Select keep) const {
        std::vector<std::vector<Run>> runs(b - a + 1);
        for (std::size_t i = a; i <= b; ++i)
            for (const Run& r : life_[i].runs[cls])
                if (keep(r.id)) runs[i - a].push_back(r);
        const std::vector<Range> ranges = ranges_of(runs, a, b);
        std::vector<Plan> plans;
        for (std::size_t q = 0; q < ranges.size(); ++q) {
            const Range& rg = ranges[q];
            if (q > 0 && ranges[q - 1].last + 1 == rg.first && !ranges[q - 1].hold_after)
                plans.push_back(transition(runs[rg.first - 1 - a], runs[rg.first - a], rg.first - 1));
            plans.push_back(plan_of(runs, a, rg));
        }
        return plans;
    }

    /// A plan's frames: the runs of life frames [a, b] (@p runs, from a)
    /// cut into segments where a run jumps, appears or vanishes, or travels
    /// too far for one vertex set.
    std::vector<Range> ranges_of(const std::vector<std::vector<Run>>& runs, std::size_t a, std::size_t b) const;

    /// The plan of one segment @p rg of the runs @p runs (life frames from
    /// @p a): a subpath per run alive in any of its frames, a point where
    /// it will appear or was before it appears or after it vanishes.
    Plan plan_of(const std::vector<std::vector<Run>>& runs, std::size_t a, const Range& rg) const;

    /// The segment of @p plan: geometry at every key, vertices and keys
    /// reduced; the kept keys.
    PathSegment emit(const Plan& plan, const StrokeStyle& stroke) const;

  private:
    /// A key's shape with line weight: each subpath's stroke points from
    /// the loop the key draws (its parameter, weight and time), wobbled, and
    /// outlined where the width varies. @p shape is the key's centre lines
    /// on the plan's grid (@p grid, @p ring: emit's).
    anim::Shape weighed_shape(const Plan& plan, const Key& k, const anim::Shape& shape,
                              const std::vector<std::vector<double>>& grid, const std::vector<char>& ring,
                              const StrokeStyle& stroke) const;

    /// A dash of a key's run: its id, the loop's arc length at its ends,
    /// and how many points draw it (the same for an id in every key).
    struct KeyDash {
        std::int64_t id = 0;
        double from = 0.0, to = 0.0;
        std::size_t points = 2;
    };

    /// The dashes of subpath @p j at key @p k, in arc length along the
    /// loop the key draws: screen dashes measured from the run's start
    /// (from the loop's first point round a whole ring), as the static
    /// frame's dash array is; surface dashes by the stroke parameter.
    std::vector<KeyDash> key_dashes(const Key& k, std::size_t j, bool ring, const StrokeStyle& stroke) const;

    /// The dashes over arcs [a0, a1] of loop @p w (one stretch whose dash
    /// measure starts at a0, or the stroke parameter).
    std::vector<KeyDash> key_dashes_over(const ParamLoop& w, double a0, double a1, const StrokeStyle& stroke) const;

    /// Key @p k's shape with its runs' subpaths replaced by their dashes,
    /// one subpath per id of @p ids (an id the key lacks is a point at the
    /// end of the dash before it, or the start of the one after).
    anim::Shape dash_shape(const Plan& plan, const Key& k, const anim::Shape& shape,
                           const std::vector<std::map<std::int64_t, std::size_t>>& ids, const StrokeStyle& stroke) const;

    /// Whether the runs of frame @p i interpolate to those of the next:
    /// every run end (a run that appears or vanishes at the middle of its
    /// span) moves along a stretch of the loop that is straight within
    /// max_sweep_px in both frames. Where an end glides round a bend,
    /// interpolation would cut across it: the path jumps there instead.
    bool glides(const std::vector<Run>& from, const std::vector<Run>& to, std::size_t i) const;

    Plan transition(const std::vector<Run>& from, const std::vector<Run>& to, std::size_t i) const;

    const std::vector<LifeFrame>& life_;
    int first_frame_;
    const AnimatedSvgOptions& options_;
};

/// A run of one frame's loop as a polyline at the loop's own density,
/// simplified within the tolerance (appended to @p out; with line weight,
/// as the stroke draws it).
void run_polyline(const ParamLoop& p, const ClassSpan& span, const StrokeStyle& stroke, const AnimatedSvgOptions& options,
                  anim::Shape& out);

} // namespace snaxels::detail
