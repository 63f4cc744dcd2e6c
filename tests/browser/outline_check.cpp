// Checks a browser's rendering of `snaxels-cli contours --svg` (visual
// contour, orthographic view) against the mesh itself: the silhouette of the
// mesh's projection, rasterized here, must be traced by drawn pixels all the
// way round, and nothing may be drawn off the mesh.
//   outline_check MESH SCREENSHOT.png VIEW_X,VIEW_Y,VIEW_Z [UP_X,UP_Y,UP_Z [VISIBLE_ONLY.png]]
// With VISIBLE_ONLY.png (the same SVG with its hidden group not displayed),
// the pixels the hidden lines add must exist and lie on the mesh.

#include <cmath>
#include <cstdio>
#include <sstream>

#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include "snaxels/mesh/import.h"
#include "snaxels/scene/camera.h"
#include "snaxels/mesh/topology.h"

using namespace snaxels;

static glm::dvec3 vec3(const char* text) {
    glm::dvec3 v{};
    char c;
    std::istringstream(text) >> v.x >> c >> v.y >> c >> v.z;
    return v;
}

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: outline_check MESH PNG VIEW [UP]\n");
        return 2;
    }
    QGuiApplication app(argc, argv);
    const LoadedMesh m = load_mesh(argv[1]);
    QImage shot(argv[2]);
    if (shot.isNull()) {
        std::fprintf(stderr, "cannot read %s\n", argv[2]);
        return 1;
    }
    shot = shot.convertToFormat(QImage::Format_RGB32);
    Camera cam;
    cam.view_dir = glm::normalize(vec3(argv[3]));
    if (argc > 4) cam.up = vec3(argv[4]);
    const glm::dvec3 centre = 0.5 * (m.report.bbox_min + m.report.bbox_max);
    const double radius = 0.5 * glm::length(m.report.bbox_max - m.report.bbox_min);
    const ImageProjection proj(cam, centre, radius, shot.width(), shot.height());

    // The mesh's projection, filled.
    QImage mask(shot.size(), QImage::Format_Grayscale8);
    mask.fill(0);
    {
        QPainter p(&mask);
        p.setRenderHint(QPainter::Antialiasing, false);
        p.setPen(Qt::NoPen);
        p.setBrush(Qt::white);
        for (const auto fh : m.mesh.faces()) {
            QPolygonF tri;
            for (const auto vh : m.mesh.fv_range(fh)) {
                const glm::dvec2 q = proj.project(to_glm(m.mesh.point(vh)));
                tri << QPointF(q.x, q.y);
            }
            p.drawPolygon(tri);
        }
    }
    const MeshTopology topo = build_topology(m.mesh);
    double edge_px = 0.0;
    for (const auto& e : topo.edge_vertices())
        edge_px += glm::length(proj.project(topo.positions()[e[0]]) - proj.project(topo.positions()[e[1]]));
    edge_px /= double(topo.n_edges());
    // Smooth (normal-interpolated) silhouettes can sit a fraction of an edge
    // inside the polygonal outline.
    const int tol = int(std::ceil(std::max(3.0, 0.75 * edge_px)));

    auto drawn = [&](int x, int y) { return qGray(shot.pixel(x, y)) < 160; };
    auto inside = [&](int x, int y) { return qGray(mask.pixel(x, y)) > 0; };
    auto near = [&](int x, int y, auto&& pred) {
        for (int dy = -tol; dy <= tol; ++dy)
            for (int dx = -tol; dx <= tol; ++dx) {
                const int u = x + dx, v = y + dy;
                if (u >= 0 && v >= 0 && u < shot.width() && v < shot.height() && pred(u, v)) return true;
            }
        return false;
    };
    long silhouette = 0, traced = 0, ink = 0, stray = 0;
    for (int y = 1; y + 1 < shot.height(); ++y)
        for (int x = 1; x + 1 < shot.width(); ++x) {
            if (inside(x, y) && (!inside(x - 1, y) || !inside(x + 1, y) || !inside(x, y - 1) || !inside(x, y + 1))) {
                ++silhouette;
                traced += near(x, y, drawn);
            }
            if (drawn(x, y)) {
                ++ink;
                stray += !near(x, y, inside);
            }
        }
    const double coverage = silhouette ? double(traced) / double(silhouette) : 0.0;
    std::printf("edge %.1f px, tolerance %d px; silhouette pixels %ld, traced %.4f; ink %ld, off-mesh %ld\n",
                edge_px, tol, silhouette, coverage, ink, stray);
    if (silhouette < 100 || ink < 100) {
        std::fprintf(stderr, "FAIL: nothing to compare (is the screenshot blank?)\n");
        return 1;
    }
    if (coverage < 0.995) {
        std::fprintf(stderr, "FAIL: the drawn outline misses %.2f%% of the silhouette\n", 100 * (1 - coverage));
        return 1;
    }
    if (stray > 0) {
        std::fprintf(stderr, "FAIL: %ld drawn pixels lie off the mesh\n", stray);
        return 1;
    }
    if (argc > 5) {
        QImage visible(argv[5]);
        if (visible.size() != shot.size()) {
            std::fprintf(stderr, "FAIL: cannot read %s at the screenshot's size\n", argv[5]);
            return 1;
        }
        visible = visible.convertToFormat(QImage::Format_RGB32);
        long hidden_ink = 0, hidden_off_mesh = 0;
        for (int y = 0; y < shot.height(); ++y)
            for (int x = 0; x < shot.width(); ++x)
                if (qGray(visible.pixel(x, y)) - qGray(shot.pixel(x, y)) > 40) {
                    ++hidden_ink;
                    hidden_off_mesh += !near(x, y, inside);
                }
        std::printf("hidden-line pixels %ld, off-mesh %ld\n", hidden_ink, hidden_off_mesh);
        if (hidden_ink < 50) {
            std::fprintf(stderr, "FAIL: no hidden lines drawn\n");
            return 1;
        }
        if (hidden_off_mesh > 0) {
            std::fprintf(stderr, "FAIL: hidden lines drawn off the mesh\n");
            return 1;
        }
    }
    return 0;
}
