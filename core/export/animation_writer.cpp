#include "snaxels/export/animation_writer.h"
#include "snaxels/export/stroke_dashes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>

#include "snaxels/error.h"
#include "snaxels/export/detail/animated_paths.h"
#include "snaxels/export/detail/smil.h"
#include "snaxels/export/detail/svg_writer.h"

namespace snaxels {
namespace {

/// A piece of text in the spill file.
struct Fragment {
    long offset = 0;
    std::size_t size = 0;
};

/// Text kept out of memory until the document is assembled: an unlinked
/// temporary file (nothing is left behind, whatever ends the process).
class Spill {
  public:
    Spill() : file_(std::tmpfile()) {
        if (!file_) throw Error("cannot create a temporary file for the animation: " + std::string(std::strerror(errno)));
    }
    ~Spill() { std::fclose(file_); }
    Spill(const Spill&) = delete;
    Spill& operator=(const Spill&) = delete;

    Fragment put(const std::string& text) {
        Fragment f{end_, text.size()};
        if (text.empty()) return f;
        if (std::fseek(file_, end_, SEEK_SET) != 0 || std::fwrite(text.data(), 1, text.size(), file_) != text.size())
            throw Error("cannot write the animation's temporary file: " + std::string(std::strerror(errno)));
        end_ += long(text.size());
        return f;
    }
    void get(const Fragment& f, const std::function<void(std::string_view)>& sink) {
        if (f.size == 0) return;
        buffer_.resize(f.size);
        if (std::fseek(file_, f.offset, SEEK_SET) != 0 || std::fread(buffer_.data(), 1, f.size, file_) != f.size)
            throw Error("cannot read the animation's temporary file back");
        sink(std::string_view(buffer_.data(), f.size));
    }

  private:
    std::FILE* file_;
    long end_ = 0;
    std::string buffer_;
};

/// Text written in pieces: kept in memory up to a size, then spilled.
struct SpilledText {
    std::vector<Fragment> fragments;
    std::string pending;
    void flush(Spill& spill) {
        if (pending.empty()) return;
        fragments.push_back(spill.put(pending));
        pending.clear();
    }
    void maybe_flush(Spill& spill) {
        if (pending.size() > (64u << 10)) flush(spill);
    }
    void write(Spill& spill, const std::function<void(std::string_view)>& sink) {
        for (const Fragment& f : fragments) spill.get(f, sink);
        sink(pending);
    }
};

/// One path of the document, written as its pieces come.
struct Record {
    AnimatedPathData meta; ///< identity, first and last frame; no segments
    std::array<std::int64_t, 4> order{};
    std::size_t segments = 0, vertices = 0;
    bool open = true;
    // SVG: the d animation's keyTimes and values.
    std::optional<smil::KeyTimePrinter> printer;
    SpilledText times, values;
    std::string first_value, last_value; ///< spilled once the path is done
    Fragment first_spilled, last_spilled;
    double last_time = -1e300;
    bool moves = false;
    std::size_t svg_keys = 0;
    // Lottie: a layer per segment, written once the next segment's start
    // (its out point) is known.
    std::optional<PathSegment> pending;
    std::size_t pending_number = 0;
    std::vector<std::pair<Fragment, std::size_t>> layers; ///< body, segment number
    std::size_t lottie_keys = 0;
};

} // namespace

struct AnimationWriter::Impl {
    AnimationFormat format;
    std::size_t frames_total;
    double fps;
    AnimatedSvgOptions options;
    Style style;
    smil::Clock clock;
    Spill spill;

    std::vector<AnimationFrame> buffer;
    int chunk_start = 0, chunk_index = 0;
    bool header = false, with_visibility = false;
    int width = 16, height = 16;
    std::vector<ContourSpec> specs;
    /// The scene's parts when strokes are grouped by object (groups_by_object).
    std::shared_ptr<const FaceParts> parts;
    std::map<std::uint64_t, std::int64_t> track_rank; ///< region tracks in order of appearance
    std::vector<std::unique_ptr<Record>> records;
    std::vector<Record*> open; ///< the records that may still go on (a chunk scans these, not all)

    Impl(AnimationFormat f, std::size_t n, double rate, const AnimatedSvgOptions& o, const Style& s)
        : format(f), frames_total(std::max<std::size_t>(n, 1)), fps(rate), options(o), style(s), clock{frames_total, rate} {
        // Lottie keeps screen dashes a dash array: a shape per dash, each
        // keyframed, would make the file four times the SVG's.
        if (format == AnimationFormat::Lottie) options.screen_dash_array = true;
    }

    /// The stroke path @p p is drawn with: its style's, without the dash
    /// array where the dashes are pieces of the line.
    StrokeStyle stroke_of(const AnimatedPathData& p) const { return drawn(p.cls == StrokeClass::Hidden ? style.contour(specs[p.contour]).hidden : style.contour(specs[p.contour]).visible); }
    StrokeStyle drawn(StrokeStyle stroke) const {
        if (dashes_as_geometry(stroke, options.screen_dash_array)) stroke.dash.clear();
        return stroke;
    }

    // --- one segment onto a record --------------------------------------
    void add_segment(Record& r, PathSegment seg) {
        ++r.segments;
        r.vertices = std::max(r.vertices, seg.vertices());
        if (format == AnimationFormat::Svg) {
            for (std::size_t k = 0; k < seg.times.size(); ++k) {
                if (seg.times[k] <= r.last_time) continue; // never two keys at one time
                const std::string v = anim::path_data(seg.shapes[k], seg.knots.empty() ? nullptr : &seg.knots);
                if (!r.printer) {
                    r.printer.emplace(clock);
                    r.first_value = v;
                    if (seg.times[k] > 0.0) { // the first key's shape from time 0
                        r.printer->append(r.times.pending, 0.0);
                        r.values.pending += v;
                    }
                }
                r.moves |= v != r.first_value;
                r.printer->append(r.times.pending, seg.times[k]);
                if (!r.values.pending.empty() || !r.values.fragments.empty()) r.values.pending += ';';
                r.values.pending += v;
                r.last_value = v;
                r.last_time = seg.times[k];
                ++r.svg_keys;
            }
            r.times.maybe_flush(spill);
            r.values.maybe_flush(spill);
        } else {
            if (r.pending) flush_layer(r, seg.times.empty() ? double(r.meta.last + 1) : seg.times.front());
            r.pending = std::move(seg);
            r.pending_number = r.segments;
        }
    }

    void flush_layer(Record& r, double op) {
        const PathSegment& seg = *r.pending;
        if (!seg.times.empty() && op > seg.times.front()) {
            const std::string body = lottie_layer_body(seg, seg.times.front(), op, r.meta,
                                                       r.meta.fill ? StrokeStyle{} : stroke_of(r.meta), r.lottie_keys);
            if (!body.empty()) r.layers.push_back({spill.put(body), r.pending_number});
        }
        r.pending.reset();
    }

    /// A path that goes on no more: what is left of it leaves memory.
    void close(Record& r) {
        if (!r.open) return;
        r.open = false;
        if (r.pending) flush_layer(r, double(r.meta.last + 1));
        r.times.flush(spill);
        r.values.flush(spill);
        r.first_spilled = spill.put(r.first_value);
        r.last_spilled = spill.put(r.last_value);
        std::string().swap(r.times.pending); // (flushed: its capacity too)
        std::string().swap(r.values.pending);
        std::string().swap(r.first_value);
        std::string().swap(r.last_value);
    }

    // --- a chunk ----------------------------------------------------------
    void encode_chunk(bool final) {
        const int s = chunk_start;
        const bool shared = s > 0; // buffer[0] was the last frame of the chunk before
        ChunkContext context;
        context.defer_last = !final;
        if (shared)
            for (const Record* r : open)
                if (!r->meta.fill && !r->meta.brief && r->meta.last == s)
                    context.drawn_first.insert({r->meta.contour, r->meta.track});
        std::vector<AnimatedPathData> paths = animated_paths(buffer, style, options, &context);
        std::vector<Record*> continued;
        for (AnimatedPathData& p : paths) {
            // Chunk frames to the animation's.
            p.first += s;
            p.last += s;
            for (PathSegment& seg : p.segments)
                for (double& t : seg.times) t += s;
            Record* q = shared && p.first == s && !p.brief ? continuation(p, continued) : nullptr;
            if (q) {
                continued.push_back(q);
                join(*q, std::move(p));
                continue;
            }
            auto r = std::make_unique<Record>();
            if (p.fill) {
                auto [it, fresh] = track_rank.try_emplace(p.track, std::int64_t(track_rank.size()));
                r->order = {0, it->second, p.first, 0};
            } else if (p.brief) {
                r->order = {2, chunk_index, 0, 0};
            } else {
                r->order = {1, std::int64_t(p.track), p.first, std::int64_t(chunk_index)};
            }
            std::vector<PathSegment> segments = std::move(p.segments);
            p.segments.clear();
            r->meta = std::move(p);
            for (PathSegment& seg : segments) add_segment(*r, std::move(seg));
            open.push_back(r.get());
            records.push_back(std::move(r));
        }
        // Paths that did not reach the chunk's last frame are done.
        const int end = s + int(buffer.size()) - 1;
        for (Record* r : open)
            if (r->meta.last < end) close(*r);
        open.erase(std::remove_if(open.begin(), open.end(), [](const Record* r) { return !r->open; }), open.end());
        ++chunk_index;
    }

    /// The open path of the chunk before that @p p goes on (it ended on the shared frame).
    Record* continuation(const AnimatedPathData& p, const std::vector<Record*>& taken) {
        for (Record* r : open) {
            const AnimatedPathData& m = r->meta;
            if (m.last != p.first || m.fill != p.fill || m.brief) continue;
            if (std::find(taken.begin(), taken.end(), r) != taken.end()) continue;
            if (m.fill ? m.track == p.track : m.contour == p.contour && m.cls == p.cls && m.track == p.track) return r;
        }
        return nullptr;
    }

    void join(Record& q, AnimatedPathData p) {
        // The first key is the shared frame drawn with this chunk's vertices:
        // it follows the last key of the chunk before a thousandth of a frame on.
        if (!p.segments.empty() && !p.segments.front().times.empty() && p.segments.front().times.front() <= double(p.first))
            p.segments.front().times.front() = double(p.first) + anim::kSwitch;
        q.meta.last = p.last;
        for (PathSegment& seg : p.segments) add_segment(q, std::move(seg));
    }

    // --- the document -----------------------------------------------------
    std::vector<const Record*> drawing_order() const {
        std::vector<const Record*> sorted;
        for (const auto& r : records) sorted.push_back(r.get());
        std::stable_sort(sorted.begin(), sorted.end(), [](const Record* a, const Record* b) { return a->order < b->order; });
        std::vector<const Record*> out;
        for (const Record* r : sorted)
            if (r->meta.fill) out.push_back(r);
        for (const StrokeClass cls : {StrokeClass::Hidden, StrokeClass::Visible})
            for (std::size_t c = 0; c < specs.size(); ++c)
                for (const Record* r : sorted)
                    if (!r->meta.fill && r->meta.contour == c && r->meta.cls == cls) out.push_back(r);
        return out;
    }

    void write_svg(const std::function<void(std::string_view)>& sink, AnimatedSvgStats& st) {
        if (!header) {
            sink(svg::document_start(16, 16, style.background, {}, true) + "</svg>\n");
            return;
        }
        sink(svg::document_start(width, height, style.background, style.page, true));
        const std::vector<const Record*> order = drawing_order();
        auto path = [&](const Record& r, const std::string& attributes, const std::string& label,
                        const std::string& children) {
            if (!r.printer) return; // no key: nothing to draw
            std::string first_value, last_value;
            spill.get(r.first_spilled, [&](std::string_view v) { first_value = v; });
            spill.get(r.last_spilled, [&](std::string_view v) { last_value = v; });
            sink(smil::path_start(attributes, {{r.meta.first, r.meta.last}}, r.moves, first_value, clock));
            if (r.moves) {
                Record& w = const_cast<Record&>(r);
                sink(smil::d_animation_start(clock));
                w.times.write(spill, sink);
                if (r.last_time < double(clock.frames)) { // the last key's shape to the end
                    std::string tail;
                    smil::KeyTimePrinter end = *r.printer;
                    end.append(tail, double(clock.frames));
                    sink(tail);
                }
                sink(smil::kValuesStart);
                w.values.write(spill, sink);
                if (r.last_time < double(clock.frames)) sink(";" + last_value);
                sink(smil::kAnimationEnd);
            }
            sink(children + "</path>\n");
            st.path_stats.push_back(path_stats_of(r, label, r.moves ? r.svg_keys : 1));
        };
        bool any_fill = false;
        for (const Record* r : order) {
            if (!r->meta.fill) continue;
            if (!any_fill)
                sink("<g id=\"fills\" inkscape:groupmode=\"layer\" inkscape:label=\"fills\" stroke=\"none\" "
                     "fill-rule=\"nonzero\">\n");
            any_fill = true;
            std::string attributes = " class=\"region\" data-class=\"" + r->meta.region_class + "\" fill=\"" +
                                     r->meta.fill_colour + "\"";
            if (r->meta.region->opacity < 1.0) {
                attributes += " fill-opacity=\"";
                svg::append_number(attributes, r->meta.region->opacity);
                attributes += "\"";
            }
            path(*r, attributes, r->meta.region_class, {});
        }
        if (any_fill) sink("</g>\n");
        for (const StrokeClass cls : {StrokeClass::Hidden, StrokeClass::Visible}) {
            const bool is_hidden = cls == StrokeClass::Hidden;
            if (is_hidden && !with_visibility) continue;
            const std::string part = is_hidden ? "hidden" : "visible";
            sink("<g id=\"" + part + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + part + " lines\">\n");
            for (std::size_t c = 0; c < specs.size(); ++c) {
                const ContourStyle cs = style.contour(specs[c]);
                const StrokeStyle& stroke = is_hidden ? cs.hidden : cs.visible;
                if (!stroke.draw) continue;
                const std::string label = specs[c].label();
                sink(svg::kind_group(specs[c], drawn(stroke),
                                     " id=\"" + part + "-" + label + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" +
                                         label + " (" + part + ")\""));
                auto write_paths = [&](std::int32_t object) {
                    for (const Record* r : order) {
                        if (r->meta.fill || r->meta.contour != c || r->meta.cls != cls) continue;
                        if (parts && r->meta.object != object) continue;
                        path(*r, r->meta.brief ? " class=\"brief\"" : "", label, {});
                    }
                };
                if (parts) {
                    // A sublayer per object inside the kind's group (docs/styles.md says why).
                    for (std::size_t o = 0; o < parts->objects.size(); ++o) {
                        const bool any = std::any_of(order.begin(), order.end(), [&](const Record* r) {
                            return !r->meta.fill && r->meta.contour == c && r->meta.cls == cls &&
                                   r->meta.object == std::int32_t(o);
                        });
                        if (!any) continue;
                        sink(svg::object_group(parts->objects[o]));
                        write_paths(std::int32_t(o));
                        sink("</g>\n");
                    }
                }
                write_paths(-1);
                sink("</g>\n");
            }
            sink("</g>\n");
        }
        sink("</svg>\n");
    }

    void write_lottie(const std::function<void(std::string_view)>& sink, AnimatedSvgStats& st) {
        sink(lottie_document_start(fps, frames_total, width, height));
        const std::vector<const Record*> order = drawing_order();
        // Layer names and stats in drawing order; Lottie lists the topmost first.
        std::vector<std::string> names(order.size());
        for (std::size_t n = 0; n < order.size(); ++n) {
            const AnimatedPathData& m = order[n]->meta;
            std::string label = m.fill ? m.region_class : specs[m.contour].label();
            const std::string object = parts && m.object >= 0 && m.object < std::int32_t(parts->objects.size())
                                           ? parts->objects[m.object].name + ": "
                                           : "";
            names[n] = (m.fill ? "fill " + label : object + label + (m.cls == StrokeClass::Hidden ? " hidden" : " visible") + (m.brief ? " brief" : "")) +
                       " " + std::to_string(n + 1);
            st.path_stats.push_back(path_stats_of(*order[n], label, order[n]->lottie_keys));
        }
        std::size_t ind = 1;
        bool first = true;
        for (std::size_t n = order.size(); n-- > 0;) {
            const Record& r = *order[n];
            for (auto it = r.layers.rbegin(); it != r.layers.rend(); ++it) {
                if (!first) sink(",\n");
                first = false;
                sink(lottie_layer_start(ind++, names[n] + (r.segments > 1 ? "." + std::to_string(it->second) : std::string())));
                spill.get(it->first, sink);
            }
        }
        if (style.background != "none") {
            if (!first) sink(",\n");
            sink(lottie_background_layer(style, frames_total, width, height, ind));
        }
        sink("]}\n");
    }

    PathStats path_stats_of(const Record& r, const std::string& label, std::size_t keyframes) const {
        PathStats p;
        if (parts && r.meta.object >= 0 && r.meta.object < std::int32_t(parts->objects.size()))
            p.object = parts->objects[r.meta.object].path;
        p.kind = r.meta.fill ? "fill" : "stroke";
        p.label = label;
        p.part = r.meta.fill ? "fill" : r.meta.cls == StrokeClass::Hidden ? "hidden" : "visible";
        p.first = r.meta.first;
        p.last = r.meta.last;
        p.frames_shown = std::size_t(r.meta.last - r.meta.first + 1);
        p.vertices = r.vertices;
        p.keyframes = keyframes;
        p.segments = r.segments;
        return p;
    }
};

AnimationWriter::AnimationWriter(AnimationFormat format, std::size_t frames, double fps, const AnimatedSvgOptions& options,
                                 const Style& style)
    : impl_(std::make_unique<Impl>(format, frames, fps, options, style)) {}

AnimationWriter::~AnimationWriter() = default;

void AnimationWriter::add(AnimationFrame frame) {
    Impl& m = *impl_;
    if (!m.header) {
        m.header = true;
        m.width = frame.drawing.width;
        m.height = frame.drawing.height;
        for (const DrawnContour& c : frame.drawing.contours) m.specs.push_back(c.spec);
        if (groups_by_object(frame.drawing)) m.parts = frame.drawing.parts;
    }
    m.with_visibility |= has_hidden_lines(frame.drawing);
    m.buffer.push_back(std::move(frame));
    if (m.buffer.size() == kChunkFrames + 1) {
        m.encode_chunk(false);
        m.buffer.erase(m.buffer.begin(), m.buffer.end() - 1); // the shared frame
        m.chunk_start += int(kChunkFrames);
    }
}

void AnimationWriter::finish(const std::function<void(std::string_view)>& sink, AnimatedSvgStats* stats) {
    Impl& m = *impl_;
    if (!m.buffer.empty()) m.encode_chunk(true); // (a lone shared frame too: it may hold contours left to it)
    m.buffer.clear();
    for (auto& r : m.records) m.close(*r);
    AnimatedSvgStats local;
    AnimatedSvgStats& st = stats ? *stats : local;
    st = {};
    if (m.format == AnimationFormat::Svg) m.write_svg(sink, st);
    else m.write_lottie(sink, st);
    sum_stats(st);
}

std::string animation_document(AnimationFormat format, const std::vector<AnimationFrame>& frames, double fps,
                               const AnimatedSvgOptions& options, const Style& style, AnimatedSvgStats* stats) {
    AnimationWriter writer(format, frames.size(), fps, options, style);
    for (const AnimationFrame& f : frames) writer.add(f);
    std::string out;
    writer.finish([&](std::string_view piece) { out += piece; }, stats);
    return out;
}

} // namespace snaxels
