// Renders frames of a Lottie file with rlottie (Debian's librlottie) into a
// grid PNG, one CELL x CELL image per frame, COLS a row, over white.
//   rlottie_render ANIM.json OUT.png CELL COLS FRAME...

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <QImage>
#include <QPainter>

#include <rlottie.h>

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr, "usage: rlottie_render ANIM.json OUT.png CELL COLS FRAME...\n");
        return 2;
    }
    std::ifstream in(argv[1], std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "cannot read %s\n", argv[1]);
        return 1;
    }
    std::stringstream text;
    text << in.rdbuf();
    // The key names the animation in rlottie's cache; the cache is off.
    std::unique_ptr<rlottie::Animation> anim = rlottie::Animation::loadFromData(text.str(), argv[1], "", false);
    if (!anim) {
        std::fprintf(stderr, "rlottie could not load %s\n", argv[1]);
        return 1;
    }
    const int cell = std::atoi(argv[3]), cols = std::atoi(argv[4]);
    std::vector<int> frames;
    for (int i = 5; i < argc; ++i) frames.push_back(std::atoi(argv[i]));
    const int rows = (int(frames.size()) + cols - 1) / cols;
    QImage grid(cols * cell, rows * cell, QImage::Format_ARGB32_Premultiplied);
    grid.fill(Qt::white);
    QPainter painter(&grid);
    std::printf("%s: %zu frames at %g fps, %zux%zu\n", argv[1], anim->totalFrame(), anim->frameRate(),
                std::size_t(cell), std::size_t(cell));
    for (std::size_t k = 0; k < frames.size(); ++k) {
        QImage img(cell, cell, QImage::Format_ARGB32_Premultiplied);
        img.fill(Qt::transparent);
        rlottie::Surface surface(reinterpret_cast<std::uint32_t*>(img.bits()), std::size_t(cell), std::size_t(cell),
                                 std::size_t(img.bytesPerLine()));
        anim->renderSync(std::size_t(frames[k]), surface);
        painter.drawImage(int(k % std::size_t(cols)) * cell, int(k / std::size_t(cols)) * cell, img);
    }
    painter.end();
    if (!grid.save(argv[2])) {
        std::fprintf(stderr, "cannot write %s\n", argv[2]);
        return 1;
    }
    return 0;
}
