// The backend scene, in C++ against the installed package (find_package(casteljau CONFIG)).
// The same scene is drawn by examples/c/scene.c and examples/python/scene.py; tests/install/
// check_install.sh compares the three PNGs with golden/install_scene.png.
// Usage: example_scene OUT.png FONT.ttf
#include <cstdio>
#include <memory>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/png.hpp"
#include "casteljau/text.hpp"

using namespace casteljau;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s OUT.png FONT.ttf\n", argv[0]);
        return 2;
    }
    try {
        Pixmap pm(200, 120);
        Canvas c(pm);
        c.clear(Color::white());
        // Shapes: a red rectangle and a linear gradient from blue to green.
        c.fill_rect({10, 10, 70, 50}, Paint::solid(Color::rgba(255, 0, 0)));
        c.fill_rect({80, 10, 190, 50},
                    Paint::shaded(
                        Shader::linear({80, 0}, {190, 0}, {{0, Color::rgba(0, 0, 255)}, {1, Color::rgba(0, 255, 0)}})));
        // A clip: an orange band seen through a circle.
        c.save();
        Path circle;
        circle.add_circle({50, 90}, 25);
        c.clip_path(circle);
        c.fill_rect({0, 60, 200, 120}, Paint::solid(Color::rgba(255, 165, 0)));
        c.restore();
        // A stroke.
        Path line;
        line.move_to(90, 70).line_to(190, 70);
        StrokeStyle st;
        st.width = 4;
        c.stroke_path(line, st, Paint::solid(Color::black()));
        // An image: a 2x2 checker scaled 10x with nearest sampling.
        Pixmap checker(2, 2);
        checker.set_pixel(0, 0, premultiply(Color::rgba(255, 0, 0)));
        checker.set_pixel(1, 0, premultiply(Color::rgba(0, 255, 0)));
        checker.set_pixel(0, 1, premultiply(Color::rgba(0, 0, 255)));
        checker.set_pixel(1, 1, premultiply(Color::white()));
        c.draw_image(checker, Affine::translate(170, 80) * Affine::scale(10, 10), ImageSampling::Nearest);
        // Text.
        const Font font = Font::load(argv[2]);
        draw_text(c, "casteljau", font, 14, {90, 90}, Paint::solid(Color::rgba(40, 40, 40)));
        write_png(pm, argv[1]);
    } catch (const Error& e) {
        std::fprintf(stderr, "example_scene: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
