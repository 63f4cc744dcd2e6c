// Checks that a screenshot of a filled style paints each shading class
// where an independent reference puts it: the z-buffer rasterizer of
// tests/support/reference_raster.h, from the mesh file alone, seen as the
// CLI sees it (orthographic along VIEW with UP, the image fitting the
// bounding box's sphere within MARGIN pixels) and lit by the default light
// (from the viewer's upper left: -forward + up - right). Away from class
// boundaries (every pixel within 4 px shares the class) and from the
// image's other colours, at least 90% of each class's pixels must show that
// class's colour more than any other colour of the palette.
//   class_check SHOT.png MESH VIEW UP MARGIN CLASS=#rrggbb... [-- #rrggbb...]
// CLASS: shadow, lit, or band:K (the level N.L >= K); the colours after --
// are the image's others (background, strokes, highlights), which a pixel
// may show instead of any class (they are not counted).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <QColor>
#include <QGuiApplication>
#include <QImage>

#include "tests/support/reference_raster.h"

namespace {

glm::dvec3 vec3(const std::string& text) {
    std::stringstream s(text);
    glm::dvec3 v;
    char comma;
    s >> v.x >> comma >> v.y >> comma >> v.z;
    return v;
}

double distance(const QColor& a, const QColor& b) {
    return std::hypot(a.red() - b.red(), a.green() - b.green(), a.blue() - b.blue());
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 7) {
        std::fprintf(stderr, "usage: class_check SHOT.png MESH VIEW UP MARGIN CLASS=#rrggbb... [-- #rrggbb...]\n");
        return 2;
    }
    QGuiApplication app(argc, argv);
    const QImage shot = QImage(argv[1]).convertToFormat(QImage::Format_RGB32);
    if (shot.isNull()) {
        std::fprintf(stderr, "FAIL: cannot read %s\n", argv[1]);
        return 1;
    }
    const snaxels::ref::Mesh mesh = snaxels::ref::read_mesh(argv[2]);
    snaxels::ref::View view;
    view.orthographic = true;
    view.dir = glm::normalize(vec3(argv[3]));
    view.up = vec3(argv[4]);
    view.margin = std::atof(argv[5]);
    view.width = shot.width(), view.height = shot.height();
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    view.centre = 0.5 * (lo + hi);
    view.radius = 0.5 * glm::length(hi - lo);

    struct Class {
        std::string name;
        int index; // in class_image's numbering
        QColor colour;
        long pixels = 0, right = 0;
    };
    std::vector<Class> classes;
    std::vector<double> bands;
    std::vector<QColor> others;
    bool after = false;
    for (int i = 6; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") {
            after = true;
            continue;
        }
        if (after) {
            others.emplace_back(QString::fromStdString(arg));
            continue;
        }
        const auto eq = arg.find('=');
        const std::string name = arg.substr(0, eq);
        Class c{name, 0, QColor(QString::fromStdString(arg.substr(eq + 1)))};
        if (name == "shadow") c.index = 0;
        else if (name == "lit") c.index = 1;
        else if (name.rfind("band:", 0) == 0) {
            bands.push_back(std::atof(name.substr(5).c_str()));
            c.index = 1 + int(bands.size());
        } else {
            std::fprintf(stderr, "unknown class %s\n", name.c_str());
            return 2;
        }
        classes.push_back(c);
    }
    // The default light: from the viewer's upper left.
    const glm::dvec3 fwd = view.dir;
    const glm::dvec3 right = glm::normalize(glm::cross(fwd, glm::normalize(view.up)));
    const glm::dvec3 up = glm::cross(right, fwd);
    const std::vector<int> truth = snaxels::ref::class_image(mesh, view, -fwd + up - right, bands);

    const int W = view.width, H = view.height, R = 4;
    for (int y = R; y < H - R; ++y)
        for (int x = R; x < W - R; ++x) {
            const int cls = truth[std::size_t(y) * std::size_t(W) + std::size_t(x)];
            if (cls < 0) continue;
            bool inner = true;
            for (int dy = -R; dy <= R && inner; ++dy)
                for (int dx = -R; dx <= R && inner; ++dx) inner = truth[std::size_t(y + dy) * std::size_t(W) + std::size_t(x + dx)] == cls;
            if (!inner) continue;
            Class* mine = nullptr;
            for (Class& c : classes)
                if (c.index == cls) mine = &c;
            if (!mine) continue;
            const QColor p(shot.pixel(x, y));
            double best = 1e300;
            const QColor* nearest = nullptr;
            for (const Class& c : classes)
                if (distance(p, c.colour) < best) best = distance(p, c.colour), nearest = &c.colour;
            bool other = false;
            for (const QColor& o : others)
                if (distance(p, o) < best) other = true;
            if (other) continue;
            ++mine->pixels;
            mine->right += nearest == &mine->colour;
        }
    int failures = 0;
    for (const Class& c : classes) {
        const double share = c.pixels ? double(c.right) / double(c.pixels) : 0.0;
        const bool ok = c.pixels >= 200 && share >= 0.9;
        std::printf("%s %s: %ld pixels inside the reference's class, %.1f%% show its colour%s\n", c.name.c_str(),
                    qPrintable(c.colour.name()), c.pixels, 100.0 * share, ok ? "" : "  FAIL");
        failures += !ok;
    }
    return failures ? 1 : 0;
}
