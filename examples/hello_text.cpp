// hello_text: one line of text to a PNG through the installed casteljau library, in a few calls:
// load a Font, lay the text out, make a Pixmap and a Canvas, draw_text, write_png.
//
//   hello_text FONT.ttf OUT.png ["TEXT"] [SIZE_PX]
//
// Build it against an installed casteljau (see examples/CMakeLists.txt):
//   cmake -S examples -B build-examples -DCMAKE_PREFIX_PATH=/where/casteljau/is/installed
//   cmake --build build-examples
//   ./build-examples/hello_text fonts/DejaVuSans.ttf hello.png "Hello, world"
#include <casteljau/canvas.hpp>
#include <casteljau/error.hpp>
#include <casteljau/font.hpp>
#include <casteljau/png.hpp>
#include <casteljau/text.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: hello_text FONT OUT.png [TEXT] [SIZE_PX]\n";
        return 2;
    }
    const std::string text = argc > 3 ? argv[3] : "Hello, world! AV To fi";
    const double size = argc > 4 ? std::atof(argv[4]) : 40.0;
    try {
        const casteljau::Font font = casteljau::Font::load(argv[1]);

        casteljau::TextStyle style;
        style.size = size;
        const casteljau::TextLayout layout = casteljau::layout_text(text, font, style);

        const int margin = 12;
        const casteljau::Rect box = layout.bounds();
        casteljau::Pixmap pixmap(static_cast<int>(std::ceil(box.width())) + 2 * margin,
                                 static_cast<int>(std::ceil(box.height())) + 2 * margin);
        pixmap.fill(casteljau::Color::white());
        casteljau::Canvas canvas(pixmap);
        casteljau::draw_text(canvas, layout, {margin - box.x0, margin - box.y0},
                             casteljau::Paint::solid(casteljau::parse_color("#1a237e")));

        casteljau::write_png(pixmap, argv[2]);
    } catch (const casteljau::Error& e) {
        std::cerr << "hello_text: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
