#include "app/cli/scene_options.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

#include "snaxels/error.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/scene/orbit.h"

namespace snaxels::cli {

glm::dvec3 parse_vec3(const std::string& option, const std::string& text, bool direction) {
    glm::dvec3 v{};
    std::istringstream in(text);
    char comma = 0;
    in >> v.x >> comma;
    bool ok = bool(in) && comma == ',';
    in >> v.y >> comma;
    ok = ok && bool(in) && comma == ',';
    in >> v.z;
    ok = ok && !in.fail() && (in >> std::ws).eof();
    if (!ok || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw UsageError("--" + option + " takes three numbers X,Y,Z, not '" + text + "'");
    if (direction && glm::length(v) < 1e-12)
        throw UsageError("--" + option + " must not be the zero vector");
    return v;
}

namespace {

// The whole of @p text as a number, or NaN.
double whole_number(const std::string& text) {
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    return used == 0 || used != text.size() ? std::numeric_limits<double>::quiet_NaN() : v;
}

} // namespace

double parse_closed_number(const std::string& option, const std::string& text, double lo, double hi,
                           const std::string& takes) {
    const double v = whole_number(text);
    if (!(v >= lo && v <= hi)) throw UsageError("--" + option + " takes " + takes + ", not '" + text + "'");
    return v;
}

double parse_number(const std::string& option, const std::string& text, double lo, double hi) {
    const double v = whole_number(text);
    if (!(v > lo && v < hi)) {
        std::ostringstream msg;
        msg << "--" << option << " takes a number between " << lo << " and " << hi << ", not '" << text << "'";
        throw UsageError(msg.str());
    }
    return v;
}

int parse_int(const std::string& option, const std::string& text, int lo, int hi) {
    std::size_t used = 0;
    long v = 0;
    try {
        v = std::stol(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || v < lo || v > hi)
        throw UsageError("--" + option + " takes a whole number from " + std::to_string(lo) + " to " +
                         std::to_string(hi) + ", not '" + text + "'");
    return int(v);
}

std::vector<OptionSpec> scene_option_specs() {
    std::string views;
    for (const NamedView& v : named_views()) views += (views.empty() ? "" : ", ") + std::string(v.name);
    return {{"view-dir", "X,Y,Z",
             "orthographic view: the direction the camera looks (default: at the model's front, +Z for +Y up, from a "
             "little above and to the side)"},
            {"view", "NAME",
             "a named orthographic view in the model's frame (its up and front): " + views +
                 " (iso, dimetric and trimetric are the axonometric views of technical illustration: docs/cli.md)"},
            {"projection", "orthographic|perspective",
             "perspective without --eye: an eye along the view's direction (--view, --view-dir or the default) "
             "that frames the model at --fov (default: orthographic, or perspective with --eye)"},
            {"eye", "X,Y,Z", "perspective view from this point"},
            {"target", "X,Y,Z", "perspective: the point looked at (default: the mesh's centre)"},
            {"fov", "DEG", "perspective: vertical field of view in degrees (default 35)"},
            {"camera", "NAME",
             "draw from the file's camera NAME (or its index; info lists them) with its field of view, and its "
             "aspect unless --size is given"},
            {"up", "X,Y,Z",
             "the model's up axis: shown upward, turned about by --turntable (default 0,1,0; FBX and Collada files "
             "are turned upright from their own axes on import; 0,0,1 for Z-up scans and Blender's axes)"},
            {"light-dir", "X,Y,Z", "directional light: the direction toward the light"},
            {"light-pos", "X,Y,Z", "point light at this position"},
            {"kind", "KIND", "contour to find: " + contour_kind_usages(", ") + " (default visual)", true},
            {"style", "FILE.xml", "how to draw: strokes per contour kind, canvas, light (docs/styles.md)"},
            {"size", "WxH", "image size in pixels (default: the style's canvas, 800x800)"},
            {"paper", "NAME|WxHmm",
             "draw on a page of paper: " + paper_names() + "; the SVG's size is the paper's and a PDF's page is it "
             "(the canvas in pixels at 96 to the inch); excludes --size"},
            {"orientation", "portrait|landscape", "the paper upright or on its side (default: portrait, or as WxH says)"},
            {"margin", "LENGTH",
             "the page's margin, which the view stays inside: pixels, or with mm, cm, in or pt (default: 10mm on paper, "
             "else the style's)"},
            {"fit", "fit|fill", "the view fits inside the page (default) or fills it, cropped at its edges"},
            {"scale", "1:N",
             "an orthographic view drawn at 1:N: a model unit --model-units long on paper divided by N (centred on "
             "the view; excludes --fit)"},
            {"model-units", "m|cm|mm|in|ft", "the length of the model's unit, for --scale (default m)"},
            {"no-visibility", "", "skip hidden-line classification (no qi, no dashed runs)"},
            {"planar-map", "snaxel|post",
             "the planar map the style's fills come from: snaxel (the snaxel-defined visible-surface map, default) "
             "or post (polygon clipping); contours --json then lists its regions"},
            {"refine", "auto|0-3",
             "split each face into 4^N on its own plane, new vertices taking the interpolated normal, so contours "
             "and regions follow the smooth shading of a coarse mesh (default auto: meshes under 20000 faces are "
             "refined to at least that)"},
            {"sharp-angle", "DEG|file",
             "edges whose faces meet at more than DEG degrees are drawn sharp (hard-edged shading; 180: none); "
             "file (default): where the file's own normals part; without normals, past 30 degrees along feature lines"},
            {"check", "", "check the snaxel invariants after every iteration (slower)"}};
}

namespace {

/// The direction of the named view @p name for a model standing on @p up.
glm::dvec3 named_view_dir(const std::string& name, const glm::dvec3& up) {
    if (const NamedView* v = find_named_view(name)) return view_dir_at(up, v->yaw, v->pitch);
    std::string names;
    for (const NamedView& v : named_views()) names += (names.empty() ? "" : ", ") + std::string(v.name);
    throw UsageError("--view " + name + ": no such view (" + names + ")");
}

/// --paper, --orientation, --margin, --fit, --scale and --model-units over
/// the style's canvas; --size makes it a canvas of pixels.
void apply_page_options(const Args& args, Style& style) {
    if (args.flag("size")) {
        if (args.flag("paper")) throw UsageError("--size and --paper both set the canvas's size: give one");
        style.page.width_mm = style.page.height_mm = 0.0;
    }
    const auto orientation = args.value("orientation");
    if (orientation && *orientation != "portrait" && *orientation != "landscape")
        throw UsageError("--orientation takes portrait or landscape, not '" + *orientation + "'");
    glm::dvec2 paper(style.page.width_mm, style.page.height_mm);
    if (const auto name = args.value("paper")) {
        const auto mm = paper_size(*name);
        if (!mm) throw UsageError("--paper " + *name + ": no such paper (" + paper_names() + ")");
        paper = *mm;
    } else if (orientation && !style.page.paper()) {
        throw UsageError("--orientation turns a paper: give --paper (or a style whose canvas has one)");
    }
    if (args.flag("paper") || orientation) {
        const bool landscape = orientation ? *orientation == "landscape" : paper.x > paper.y;
        const double margin = style.margin;
        try {
            set_paper(style, paper, landscape);
        } catch (const Error& e) {
            throw UsageError(std::string("--paper: ") + e.what());
        }
        if (!args.flag("paper")) style.margin = margin; // turned: the style's margin stays
    }
    if (const auto m = args.value("margin")) {
        const auto px = length_pixels(*m);
        if (!px) throw UsageError("--margin takes a length (pixels, or with mm, cm, in or pt), not '" + *m + "'");
        style.margin = *px;
    }
    if (2.0 * style.margin >= std::min(style.width, style.height))
        throw UsageError("the margin (" + std::to_string(int(style.margin)) + " px) leaves no room for the drawing");
    if (args.flag("fit") && args.flag("scale")) throw UsageError("--scale sets the drawing's size: it excludes --fit");
    if (const auto fit = args.value("fit")) {
        if (*fit != "fit" && *fit != "fill") throw UsageError("--fit takes fit or fill, not '" + *fit + "'");
        style.page.fit = *fit == "fill" ? Page::Fit::Fill : Page::Fit::Fit;
        style.page.scale = 0.0;
    }
    if (const auto scale = args.value("scale")) {
        const auto n = parse_scale(*scale);
        if (!n) throw UsageError("--scale takes a ratio such as 1:50, not '" + *scale + "'");
        style.page.scale = *n;
        style.page.fit = Page::Fit::Fit;
    }
    if (const auto units = args.value("model-units")) {
        const auto mm = model_unit_mm(*units);
        if (!mm) throw UsageError("--model-units takes m, cm, mm, in or ft, not '" + *units + "'");
        style.page.unit_mm = *mm;
    }
}

/// --up, --view-dir, --view, --eye, --target and --fov into @p o's camera
/// (@p perspective: an eye given or asked for).
void parse_view(const Args& args, bool perspective, SceneOptions& o) {
    if (const auto up = args.value("up")) o.camera.up = parse_vec3("up", *up, true);
    if (const auto v = args.value("view-dir")) o.camera.view_dir = glm::normalize(parse_vec3("view-dir", *v, true));
    else if (const auto name = args.value("view")) o.camera.view_dir = named_view_dir(*name, o.camera.up);
    else o.camera.view_dir = default_view_dir(o.camera.up);
    if (perspective) {
        o.camera.projection = Camera::Projection::Perspective;
        if (const auto eye = args.value("eye")) o.camera.eye = parse_vec3("eye", *eye, false);
        else o.place_eye = true;
        if (const auto t = args.value("target")) o.target = parse_vec3("target", *t, false);
        if (const auto fov = args.value("fov")) o.camera.fov_deg = parse_number("fov", *fov, 0.0, 180.0);
    }
}

} // namespace

SceneOptions parse_scene_options(const Args& args) {
    SceneOptions o;
    if (args.flag("view-dir") && args.flag("eye"))
        throw UsageError("--view-dir (orthographic) and --eye (perspective) exclude each other");
    if (args.flag("view") && (args.flag("view-dir") || args.flag("eye")))
        throw UsageError("--view (a named orthographic view) excludes --view-dir and --eye");
    const std::optional<std::string> projection = args.value("projection");
    if (projection && *projection != "orthographic" && *projection != "perspective")
        throw UsageError("--projection takes orthographic or perspective, not '" + *projection + "'");
    const bool perspective = args.flag("eye") || projection == "perspective";
    if (args.flag("eye") && projection == "orthographic")
        throw UsageError("--eye places a perspective eye: it excludes --projection orthographic");
    if (!perspective && (args.flag("target") || args.flag("fov")))
        throw UsageError("--target and --fov need a perspective view (--eye, or --projection perspective)");
    if (args.flag("camera"))
        for (const char* view : {"view-dir", "view", "eye", "target", "fov", "up", "projection"})
            if (args.flag(view)) throw UsageError(std::string("--camera and --") + view + " exclude each other (the file's camera sets the view)");
    if (args.flag("light-dir") && args.flag("light-pos"))
        throw UsageError("--light-dir and --light-pos exclude each other");
    std::vector<bool> valued; // per --kind: whether it gave its values (suggestive:D, crease:DEG)
    for (const std::string& k : args.values("kind")) {
        try {
            o.overrides.kinds.push_back(ContourSpec::parse(k));
            valued.push_back(k.find(':') != std::string::npos);
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
    }
    if (const auto path = args.value("style")) {
        std::vector<StyleDiagnostic> warnings;
        o.style = load_style(*path, &warnings);
        o.style_source = *path;
        for (const StyleDiagnostic& w : warnings)
            std::cerr << "snaxels-cli: " << *path << ":" << w.line << ":" << w.column << ": warning: " << w.message << '\n';
    }
    // A kind named without its values takes the style's, where the style
    // draws that kind: --kind suggestive with a style's min-derivative and
    // min-angle, --kind crease with its angle and least length.
    for (std::size_t i = 0; i < o.overrides.kinds.size(); ++i) {
        ContourSpec& spec = o.overrides.kinds[i];
        const ContourValue value = contour_kind_info(spec.kind).value;
        if (valued[i] || (value != ContourValue::Suggestive && value != ContourValue::Angle)) continue;
        for (const ContourStyle& cs : o.style.contours)
            if (cs.spec.kind == spec.kind) {
                spec.k = cs.spec.k;
                spec.test = cs.spec.test;
                spec.min_angle = cs.spec.min_angle;
                spec.min_length = cs.spec.min_length;
                break;
            }
    }
    o.file_camera = args.value("camera");
    o.size_given = args.flag("size");
    if (const auto size = args.value("size")) {
        const auto x = size->find('x');
        bool ok = x != std::string::npos;
        try {
            if (ok) {
                o.style.width = parse_int("size", size->substr(0, x), 16, 20000);
                o.style.height = parse_int("size", size->substr(x + 1), 16, 20000);
                o.style.margin = std::min(o.style.margin, 0.25 * std::min(o.style.width, o.style.height));
            }
        } catch (const UsageError&) {
            ok = false;
        }
        if (!ok) throw UsageError("--size takes WIDTHxHEIGHT in pixels (16 to 20000), not '" + *size + "'");
    }
    apply_page_options(args, o.style);
    parse_view(args, perspective, o);
    if (const auto d = args.value("light-dir")) {
        Light l;
        l.dir = glm::normalize(parse_vec3("light-dir", *d, true));
        o.overrides.light = l;
    }
    if (const auto p = args.value("light-pos")) {
        Light l;
        l.point = true;
        l.pos = parse_vec3("light-pos", *p, false);
        o.overrides.light = l;
    }
    if (const auto m = args.value("planar-map")) {
        if (*m != "snaxel" && *m != "post")
            throw UsageError("--planar-map takes snaxel or post, not '" + *m + "'");
        o.overrides.planar_map = parse_planar_map_kind(*m);
    }
    if (const auto r = args.value("refine")) {
        if (*r == "auto") o.overrides.refine = kAutoRefine;
        else if (r->size() == 1 && (*r)[0] >= '0' && (*r)[0] <= char('0' + kMaxRefineLevels)) o.overrides.refine = (*r)[0] - '0';
        else throw UsageError("--refine takes auto or a level from 0 to " + std::to_string(kMaxRefineLevels) + ", not '" + *r + "'");
    }
    if (const auto a = args.value("sharp-angle"))
        o.style.surface.sharp_angle =
            *a == "file" ? kFileNormals : parse_closed_number("sharp-angle", *a, 0.0, 180.0, "degrees from 0 to 180, or file");
    o.overrides.visibility = !args.flag("no-visibility");
    if (args.flag("check")) o.overrides.check_invariants = true;
    return o;
}

void warn_about_parts(const Style& style, const LoadedMesh& mesh, const std::string& source) {
    if (const auto parts = loaded_parts(mesh))
        for (const StyleDiagnostic& w : check_parts(style, *parts))
            std::cerr << "snaxels-cli: " << source << ":" << w.line << ":" << w.column << ": warning: " << w.message << '\n';
}

SceneSettings complete_scene(const SceneOptions& o, const MeshReport& report, const std::string& mesh_path,
                             double seconds) {
    SceneOverrides overrides = o.overrides;
    if (overrides.refine > 0 && refine_levels(report.faces, overrides.refine) < overrides.refine) {
        const int levels = refine_levels(report.faces, overrides.refine);
        std::cerr << "snaxels-cli: warning: --refine " << overrides.refine << " would make "
                  << report.faces * (std::size_t(1) << (2 * overrides.refine)) << " faces; refining by " << levels
                  << (levels == 1 ? " level" : " levels") << " (at most " << kMaxRefinedFaces << " faces)\n";
        overrides.refine = levels;
    }
    Camera camera = o.camera;
    Style style = o.style;
    if (o.file_camera) {
        const CameraTrack track(mesh_path, *o.file_camera);
        camera = track.at(seconds);
        if (!o.size_given && !style.page.paper()) style.height = canvas_height_for(track.info(), style.width, style.height);
        // Lit from the camera's upper left where it starts, as the
        // application and a project render light it.
        overrides.light = job_light(style, track.info().first, overrides.light);
    } else if (!camera.orthographic()) {
        camera.target = o.target.value_or(report.centre());
        if (o.place_eye) {
            // As the application frames a model: its bounding sphere fills
            // the field of view, with a little room.
            const double radius = std::max(0.5 * glm::length(report.bbox_max - report.bbox_min), 1e-9);
            camera.eye = camera.target - camera.view_dir * framing_distance(radius, camera.fov_deg);
        }
        if (glm::length(camera.target - camera.eye) < 1e-12)
            throw UsageError("--eye and --target are the same point");
    }
    return scene_settings(style, camera, overrides);
}

} // namespace snaxels::cli
