// Checks a screenshot for the colours a style should produce: every pixel
// is assigned to the nearest colour of the palette given (the background
// first), and each colour must cover at least its minimum pixel count.
//   colour_check SHOT.png BACKGROUND #rrggbb:MIN [#rrggbb:MIN ...]

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <QColor>
#include <QGuiApplication>
#include <QImage>

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: colour_check SHOT.png BACKGROUND #rrggbb:MIN...\n");
        return 2;
    }
    QGuiApplication app(argc, argv);
    const QImage shot = QImage(argv[1]).convertToFormat(QImage::Format_RGB32);
    if (shot.isNull()) {
        std::fprintf(stderr, "FAIL: cannot read %s\n", argv[1]);
        return 1;
    }
    std::vector<QColor> palette{QColor(argv[2])};
    std::vector<long> minimum{0};
    for (int i = 3; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto colon = arg.find(':');
        palette.emplace_back(QString::fromStdString(arg.substr(0, colon)));
        minimum.push_back(std::atol(arg.substr(colon + 1).c_str()));
    }
    std::vector<long> count(palette.size(), 0);
    for (int y = 0; y < shot.height(); ++y)
        for (int x = 0; x < shot.width(); ++x) {
            const QColor p(shot.pixel(x, y));
            std::size_t best = 0;
            double best_d = 1e300;
            for (std::size_t k = 0; k < palette.size(); ++k) {
                const double d = std::hypot(p.red() - palette[k].red(), p.green() - palette[k].green(),
                                            p.blue() - palette[k].blue());
                if (d < best_d) best_d = d, best = k;
            }
            ++count[best];
        }
    int failures = 0;
    const QColor corner(shot.pixel(1, 1));
    if (std::hypot(corner.red() - palette[0].red(), corner.green() - palette[0].green(), corner.blue() - palette[0].blue()) > 6) {
        std::printf("FAIL: the background is %s, expected %s\n", qPrintable(corner.name()), argv[2]);
        ++failures;
    }
    for (std::size_t k = 1; k < palette.size(); ++k) {
        const bool ok = count[k] >= minimum[k];
        std::printf("%s: %ld pixels (at least %ld)%s\n", qPrintable(palette[k].name()), count[k], minimum[k], ok ? "" : "  FAIL");
        failures += !ok;
    }
    return failures ? 1 : 0;
}
