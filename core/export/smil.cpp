#include "core/export/smil.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "core/export/svg_writer.h"

namespace snaxels::smil {

std::string Clock::dur() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6gs", double(frames) / fps);
    return buf;
}

std::string key_times(const std::vector<double>& times, const Clock& clock) {
    std::string out;
    double printed_before = -1.0;
    for (const double t : times) {
        const double x = std::clamp(t / double(clock.frames), 0.0, 1.0);
        char buf[32];
        for (int digits = 6; digits <= 12; ++digits) {
            std::snprintf(buf, sizeof buf, "%.*g", digits, x);
            if (std::strtod(buf, nullptr) > printed_before || x <= printed_before) break;
        }
        printed_before = std::strtod(buf, nullptr);
        if (!out.empty()) out += ';';
        out += buf;
    }
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

std::size_t append_path(std::string& out, const std::string& attributes, const AnimatedPath& path, const Clock& clock,
                        const std::string& children) {
    const bool at_start = !path.shown.empty() && path.shown.front().first == 0;
    const bool always = path.shown.size() == 1 && at_start && path.shown.front().second + 1 >= int(clock.frames);
    const bool moves = std::any_of(path.values.begin(), path.values.end(),
                                   [&](const std::string& v) { return v != path.values.front(); });
    // Without SMIL a path not shown at frame 0 is hidden, so its d need not
    // draw anything; with SMIL the d animation gives its shapes.
    out += "<path" + attributes + " d=\"" + (at_start || !moves ? path.values.front() : std::string("M0 0")) + "\"";
    if (!at_start) out += " display=\"none\"";
    out += ">";
    if (!always && !path.shown.empty()) out += display_animation(path.shown, clock);
    std::size_t keys = 1;
    if (moves) {
        std::vector<double> times;
        std::string values;
        auto add = [&](double t, const std::string& v) {
            if (!values.empty()) values += ';';
            values += v;
            times.push_back(t);
        };
        if (path.times.front() > 0.0) add(0.0, path.values.front());
        for (std::size_t k = 0; k < path.times.size(); ++k) add(path.times[k], path.values[k]);
        if (path.times.back() < double(clock.frames)) add(double(clock.frames), path.values.back());
        out += "<animate attributeName=\"d\" dur=\"" + clock.dur() +
               "\" repeatCount=\"indefinite\" keyTimes=\"" + key_times(times, clock) + "\" values=\"" + values +
               "\"/>"; // calcMode linear, the default
        keys = path.times.size();
    }
    out += children;
    out += "</path>\n";
    return keys;
}

std::string number_animation(const std::string& attribute, const std::vector<double>& times,
                             const std::vector<double>& values, const Clock& clock) {
    std::vector<double> t;
    std::string v;
    auto add = [&](double time, double value) {
        if (!v.empty()) v += ';';
        svg::append_number(v, value);
        t.push_back(time);
    };
    if (times.front() > 0.0) add(0.0, values.front());
    for (std::size_t k = 0; k < times.size(); ++k) add(times[k], values[k]);
    if (times.back() < double(clock.frames)) add(double(clock.frames), values.back());
    return "<animate attributeName=\"" + attribute + "\" dur=\"" + clock.dur() +
           "\" repeatCount=\"indefinite\" calcMode=\"linear\" keyTimes=\"" + key_times(t, clock) + "\" values=\"" + v +
           "\"/>";
}

} // namespace snaxels::smil
