// Compares two screenshots cell by cell: each a grid of COLS x ROWS images
// of CELL pixels. In every cell, at least MIN of the stroke pixels of each
// image must lie within TOL pixels of a stroke pixel of the other; each
// fill colour given likewise (pixels within a small distance of it).
//   compare_grid [--fill-slack N] A.png B.png COLS ROWS CELL [TOL=2] [MIN=0.97] [#RRGGBB...]
// With --fill-slack, a fill colour also agrees in a cell where at most N of
// its pixels (each way) lie farther than TOL from the other image's: a
// region a pixel or two thick (a sliver left between eroded fills) has too
// few pixels for a share to mean anything, and antialiasing alone decides
// whether its thinnest pixels reach the colour.
// Between two frames: a render half way between the frames of B and C must
// keep each fill colour within what B or C cover, and cover what both do.
//   compare_grid --between A.png B.png C.png COLS ROWS CELL TOL MIN #RRGGBB...
// Ink that one image has and the other lacks: the connected components
// (8-neighbours) of A's ink pixels with no ink of B within TOL pixels,
// counted where larger than AREA pixels; fails when there is one (a dot or
// a dash mark an animation draws where its static frame has nothing).
//   compare_grid --extra-ink A.png B.png COLS ROWS CELL [TOL=1] [AREA=2]

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <QGuiApplication>
#include <QColor>
#include <QImage>

namespace {

std::vector<std::uint8_t> strokes(const QImage& img, int x0, int y0, int cell) {
    std::vector<std::uint8_t> s(std::size_t(cell) * cell, 0);
    for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x) s[std::size_t(y) * cell + x] = qGray(img.pixel(x0 + x, y0 + y)) < 200;
    return s;
}

// Pixels of one fill colour (within a distance that leaves out antialiased edges).
std::vector<std::uint8_t> fill(const QImage& img, int x0, int y0, int cell, QRgb colour) {
    std::vector<std::uint8_t> s(std::size_t(cell) * cell, 0);
    for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x) {
            const QRgb p = img.pixel(x0 + x, y0 + y);
            const int dr = qRed(p) - qRed(colour), dg = qGreen(p) - qGreen(colour), db = qBlue(p) - qBlue(colour);
            s[std::size_t(y) * cell + x] = dr * dr + dg * dg + db * db < 24 * 24;
        }
    return s;
}

// Fraction of `a`'s stroke pixels with a stroke pixel of `b` within `tol`.
double covered(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int cell, int tol, long& count) {
    long hit = 0;
    count = 0;
    for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x) {
            if (!a[std::size_t(y) * cell + x]) continue;
            ++count;
            bool found = false;
            for (int dy = -tol; dy <= tol && !found; ++dy)
                for (int dx = -tol; dx <= tol && !found; ++dx) {
                    const int u = x + dx, v = y + dy;
                    found = u >= 0 && v >= 0 && u < cell && v < cell && b[std::size_t(v) * cell + u];
                }
            hit += found;
        }
    return count ? double(hit) / double(count) : 1.0;
}

} // namespace

int between(int argc, char** argv, long fill_slack) {
    if (argc < 11) {
        std::fprintf(stderr, "usage: compare_grid --between A.png B.png C.png COLS ROWS CELL TOL MIN #RRGGBB...\n");
        return 2;
    }
    const QImage a = QImage(argv[2]).convertToFormat(QImage::Format_RGB32);
    const QImage b = QImage(argv[3]).convertToFormat(QImage::Format_RGB32);
    const QImage c = QImage(argv[4]).convertToFormat(QImage::Format_RGB32);
    const int cols = std::atoi(argv[5]), rows = std::atoi(argv[6]), cell = std::atoi(argv[7]);
    const int tol = std::atoi(argv[8]);
    const double min = std::atof(argv[9]);
    for (const QImage* img : {&a, &b, &c})
        if (img->isNull() || img->width() < cols * cell || img->height() < rows * cell) {
            std::fprintf(stderr, "FAIL: screenshots missing or too small\n");
            return 1;
        }
    int failures = 0;
    for (int i = 10; i < argc; ++i) {
        const QColor colour(argv[i]);
        if (!colour.isValid()) return 2;
        for (int r = 0; r < rows; ++r)
            for (int k = 0; k < cols; ++k) {
                const auto fa = fill(a, k * cell, r * cell, cell, colour.rgb());
                const auto fb = fill(b, k * cell, r * cell, cell, colour.rgb());
                const auto fc = fill(c, k * cell, r * cell, cell, colour.rgb());
                std::vector<std::uint8_t> either(fb.size()), both(fb.size());
                for (std::size_t p = 0; p < fb.size(); ++p) either[p] = fb[p] || fc[p], both[p] = fb[p] && fc[p];
                long na = 0, nboth = 0;
                const double inside = covered(fa, either, cell, tol, na);
                const double kept = covered(both, fa, cell, tol, nboth);
                // As for the frames, a few pixels of a thin fill may disagree.
                auto agrees = [&](double share, long count) {
                    return share >= min || double(count) * (1.0 - share) <= double(fill_slack) + 0.5;
                };
                const bool ok = agrees(inside, na) && agrees(kept, nboth);
                std::printf("cell %d: %ld pixels of #%06x half way, %.4f within the two frames, %.4f of their common %ld kept%s\n",
                            r * cols + k, na, unsigned(colour.rgb() & 0xffffff), inside, kept, nboth, ok ? "" : "  FAIL");
                failures += !ok;
            }
    }
    return failures ? 1 : 0;
}

int extra_ink(int argc, char** argv) {
    if (argc < 7) {
        std::fprintf(stderr, "usage: compare_grid --extra-ink A.png B.png COLS ROWS CELL [TOL] [AREA]\n");
        return 2;
    }
    const QImage a = QImage(argv[2]).convertToFormat(QImage::Format_RGB32);
    const QImage b = QImage(argv[3]).convertToFormat(QImage::Format_RGB32);
    const int cols = std::atoi(argv[4]), rows = std::atoi(argv[5]), cell = std::atoi(argv[6]);
    const int tol = argc > 7 ? std::atoi(argv[7]) : 1;
    const long area = argc > 8 ? std::atol(argv[8]) : 2;
    for (const QImage* img : {&a, &b})
        if (img->isNull() || img->width() < cols * cell || img->height() < rows * cell) {
            std::fprintf(stderr, "FAIL: screenshots missing or too small\n");
            return 1;
        }
    long total = 0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const auto sa = strokes(a, c * cell, r * cell, cell), sb = strokes(b, c * cell, r * cell, cell);
            std::vector<std::uint8_t> extra(sa.size(), 0);
            for (int y = 0; y < cell; ++y)
                for (int x = 0; x < cell; ++x) {
                    if (!sa[std::size_t(y) * cell + x]) continue;
                    bool near = false;
                    for (int dy = -tol; dy <= tol && !near; ++dy)
                        for (int dx = -tol; dx <= tol && !near; ++dx) {
                            const int u = x + dx, v = y + dy;
                            near = u >= 0 && v >= 0 && u < cell && v < cell && sb[std::size_t(v) * cell + u];
                        }
                    extra[std::size_t(y) * cell + x] = !near;
                }
            long components = 0, largest = 0;
            std::vector<int> stack;
            for (int start = 0; start < cell * cell; ++start) {
                if (extra[std::size_t(start)] != 1) continue;
                long size = 0;
                int cx = 0, cy = 0;
                stack.assign(1, start);
                extra[std::size_t(start)] = 2;
                while (!stack.empty()) {
                    const int p = stack.back();
                    stack.pop_back();
                    ++size;
                    cx = p % cell, cy = p / cell;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            const int u = cx + dx, v = cy + dy;
                            if (u < 0 || v < 0 || u >= cell || v >= cell || extra[std::size_t(v) * cell + u] != 1) continue;
                            extra[std::size_t(v) * cell + u] = 2;
                            stack.push_back(v * cell + u);
                        }
                }
                if (size > area) {
                    ++components;
                    std::printf("cell %d: %ld pixels of ink at (%d, %d) the other image lacks\n", r * cols + c, size, cx, cy);
                }
                largest = std::max(largest, size);
            }
            std::printf("cell %d: %ld components of extra ink above %ld px (largest %ld)%s\n", r * cols + c, components,
                        area, largest, components ? "  FAIL" : "");
            total += components;
        }
    return total ? 1 : 0;
}

int main(int argc, char** argv) {
    long fill_slack = 0;
    if (argc > 2 && std::string(argv[1]) == "--fill-slack") {
        fill_slack = std::atol(argv[2]);
        argv[2] = argv[0];
        argv += 2;
        argc -= 2;
    }
    if (argc > 1 && std::string(argv[1]) == "--extra-ink") {
        QGuiApplication app(argc, argv);
        return extra_ink(argc, argv);
    }
    if (argc > 1 && std::string(argv[1]) == "--between") {
        QGuiApplication app(argc, argv);
        return between(argc, argv, fill_slack);
    }
    if (argc < 6) {
        std::fprintf(stderr, "usage: compare_grid A.png B.png COLS ROWS CELL [TOL] [MIN] [#RRGGBB...]\n");
        return 2;
    }
    QGuiApplication app(argc, argv);
    const QImage a = QImage(argv[1]).convertToFormat(QImage::Format_RGB32);
    const QImage b = QImage(argv[2]).convertToFormat(QImage::Format_RGB32);
    const int cols = std::atoi(argv[3]), rows = std::atoi(argv[4]), cell = std::atoi(argv[5]);
    const int tol = argc > 6 ? std::atoi(argv[6]) : 2;
    const double min = argc > 7 ? std::atof(argv[7]) : 0.97;
    if (a.isNull() || b.isNull() || a.width() < cols * cell || a.height() < rows * cell ||
        b.width() < cols * cell || b.height() < rows * cell) {
        std::fprintf(stderr, "FAIL: screenshots missing or too small\n");
        return 1;
    }
    std::vector<QRgb> fills;
    for (int i = 8; i < argc; ++i) {
        const QColor colour(argv[i]);
        if (!colour.isValid()) {
            std::fprintf(stderr, "not a colour: %s\n", argv[i]);
            return 2;
        }
        fills.push_back(colour.rgb());
    }
    int failures = 0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const auto sa = strokes(a, c * cell, r * cell, cell), sb = strokes(b, c * cell, r * cell, cell);
            long na = 0, nb = 0;
            const double ab = covered(sa, sb, cell, tol, na), ba = covered(sb, sa, cell, tol, nb);
            const bool ok = na > 50 && nb > 50 && ab >= min && ba >= min;
            std::printf("cell %d: %ld / %ld stroke pixels, %.4f / %.4f within %d px%s\n", r * cols + c, na, nb, ab,
                        ba, tol, ok ? "" : "  FAIL");
            failures += !ok;
            for (const QRgb colour : fills) {
                const auto fa = fill(a, c * cell, r * cell, cell, colour), fb = fill(b, c * cell, r * cell, cell, colour);
                const double fab = covered(fa, fb, cell, tol, na), fba = covered(fb, fa, cell, tol, nb);
                // A colour both images lack (a fill out of view) agrees trivially.
                auto agrees = [&](double share, long count) {
                    return share >= min || double(count) * (1.0 - share) <= double(fill_slack) + 0.5;
                };
                const bool fill_ok = (na == 0 && nb == 0) || (na > 0 && nb > 0 && agrees(fab, na) && agrees(fba, nb));
                std::printf("cell %d: %ld / %ld pixels of #%06x, %.4f / %.4f within %d px%s\n", r * cols + c, na, nb,
                            unsigned(colour & 0xffffff), fab, fba, tol, fill_ok ? "" : "  FAIL");
                failures += !fill_ok;
            }
        }
    return failures ? 1 : 0;
}
