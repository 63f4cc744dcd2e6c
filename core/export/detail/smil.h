#pragma once
// Internal to core/export: SMIL animation text for animated SVG paths, one
// writer for strokes and fills. Times are in frames (fractional between
// frames); keyTimes are those over the animation's frame count.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace snaxels::smil {

/// The animation's clock: every <animate> shares its duration and loops.
struct Clock {
    std::size_t frames = 1;
    double fps = 24.0;
    std::string dur() const; ///< "12.5s"
};

/// keyTimes for @p times (frames, increasing): each printed with as few
/// digits as keep it after the one before (a structure switch puts two keys
/// a thousandth of a frame apart).
std::string key_times(const std::vector<double>& times, const Clock& clock);

/// key_times one key at a time, for paths written as they come.
class KeyTimePrinter {
  public:
    explicit KeyTimePrinter(const Clock& clock) : clock_(clock) {}
    /// Appends the key at @p t (frames), after a ';' unless it is the first.
    void append(std::string& out, double t);

  private:
    Clock clock_;
    double printed_before_ = -1.0;
    bool first_ = true;
};

/// Frame ranges [first, last] (inclusive, sorted, disjoint) in which a path is shown.
using ShownRanges = std::vector<std::pair<int, int>>;

/// One animated path: its data at key times and the frames it is shown in.
/// Consecutive keys whose data has the same commands interpolate; a change
/// of commands switches at the later key.
struct AnimatedPath {
    std::vector<double> times;       ///< frames, strictly increasing
    std::vector<std::string> values; ///< path data, parallel to times
    ShownRanges shown;
};

/// The start of append_path's element, up to its d animation: `<path
/// ATTRIBUTES d="..." [display="none"]>` and the display animation. @p moves:
/// whether the d values differ (else the path has no d animation).
std::string path_start(const std::string& attributes, const ShownRanges& shown, bool moves,
                       const std::string& first_value, const Clock& clock);
/// The d animation is d_animation_start, the keyTimes, kValuesStart, the
/// values, kAnimationEnd.
std::string d_animation_start(const Clock& clock);
inline constexpr const char* kValuesStart = "\" values=\"";
inline constexpr const char* kAnimationEnd = "\"/>";

/// Appends `<path ATTRIBUTES d="..." [display="none"]>` with its display and
/// d animations, then @p children, then `</path>`. Without SMIL the path
/// shows its first key's data, and only if it is shown at frame 0.
/// Returns the keyframes written (1 when d does not animate).
std::size_t append_path(std::string& out, const std::string& attributes, const AnimatedPath& path, const Clock& clock,
                        const std::string& children = {});

} // namespace snaxels::smil
