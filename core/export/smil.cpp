#include "snaxels/export/detail/smil.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "snaxels/export/detail/svg_writer.h"

namespace snaxels::smil {

std::string Clock::dur() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6gs", double(frames) / fps);
    return buf;
}

namespace {

/// @p x (in [0, 1]) to @p digits significant digits, rounded down: a key
/// printed late would let a seek at its own frame time land before it,
/// where a shape that switches there still shows the frame before.
void print_down(char* buf, std::size_t size, double x, int digits) {
    if (x > 0.0) {
        const double scale = std::pow(10.0, double(digits - 1) - std::floor(std::log10(x)));
        x = std::floor(x * scale * (1.0 + 1e-12)) / scale;
    }
    std::snprintf(buf, size, "%.*g", digits, x);
}

} // namespace

void KeyTimePrinter::append(std::string& out, double t) {
    const double x = std::clamp(t / double(clock_.frames), 0.0, 1.0);
    char buf[32];
    for (int digits = 6; digits <= 12; ++digits) {
        print_down(buf, sizeof buf, x, digits);
        if (std::strtod(buf, nullptr) > printed_before_ || x <= printed_before_) break;
    }
    printed_before_ = std::strtod(buf, nullptr);
    if (!first_) out += ';';
    first_ = false;
    out += buf;
}

std::string key_times(const std::vector<double>& times, const Clock& clock) {
    std::string out;
    KeyTimePrinter printer(clock);
    for (const double t : times) printer.append(out, t);
    return out;
}

namespace {

std::string display_animation(const ShownRanges& shown, const Clock& clock) {
    std::vector<double> times;
    std::string values;
    auto add = [&](double t, const char* v) {
        if (!times.empty() && times.back() == t) { // a range that starts where the last ended
            values.erase(values.rfind(';') == std::string::npos ? 0 : values.rfind(';'));
            times.pop_back();
        }
        if (!values.empty()) values += ';';
        values += v;
        times.push_back(t);
    };
    if (shown.front().first > 0) add(0.0, "none");
    for (const auto& [first, last] : shown) {
        add(double(first), "inline");
        if (last + 1 < int(clock.frames)) add(double(last + 1), "none");
    }
    return "<animate attributeName=\"display\" dur=\"" + clock.dur() +
           "\" repeatCount=\"indefinite\" calcMode=\"discrete\" keyTimes=\"" + key_times(times, clock) +
           "\" values=\"" + values + "\"/>";
}

} // namespace

std::string path_start(const std::string& attributes, const ShownRanges& shown, bool moves,
                       const std::string& first_value, const Clock& clock) {
    const bool at_start = !shown.empty() && shown.front().first == 0;
    const bool always = shown.size() == 1 && at_start && shown.front().second + 1 >= int(clock.frames);
    // Without SMIL a path not shown at frame 0 is hidden, so its d need not
    // draw anything; with SMIL the d animation gives its shapes.
    std::string out = "<path" + attributes + " d=\"" + (at_start || !moves ? first_value : std::string("M0 0")) + "\"";
    if (!at_start) out += " display=\"none\"";
    out += ">";
    if (!always && !shown.empty()) out += display_animation(shown, clock);
    return out;
}

std::string d_animation_start(const Clock& clock) {
    return "<animate attributeName=\"d\" dur=\"" + clock.dur() + "\" repeatCount=\"indefinite\" keyTimes=\""; // calcMode linear, the default
}

std::size_t append_path(std::string& out, const std::string& attributes, const AnimatedPath& path, const Clock& clock,
                        const std::string& children) {
    const bool moves = std::any_of(path.values.begin(), path.values.end(),
                                   [&](const std::string& v) { return v != path.values.front(); });
    out += path_start(attributes, path.shown, moves, path.values.front(), clock);
    std::size_t keys = 1;
    if (moves) {
        std::string times, values;
        KeyTimePrinter printer(clock);
        auto add = [&](double t, const std::string& v) {
            if (!values.empty()) values += ';';
            values += v;
            printer.append(times, t);
        };
        if (path.times.front() > 0.0) add(0.0, path.values.front());
        for (std::size_t k = 0; k < path.times.size(); ++k) add(path.times[k], path.values[k]);
        if (path.times.back() < double(clock.frames)) add(double(clock.frames), path.values.back());
        out += d_animation_start(clock) + times + kValuesStart + values + kAnimationEnd;
        keys = path.times.size();
    }
    out += children;
    out += "</path>\n";
    return keys;
}

} // namespace snaxels::smil
