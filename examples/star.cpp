// A program using the installed library the way a user would: fill and stroke a star, save a PNG.
#include <casteljau/casteljau.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    using namespace casteljau;
    const char* out = argc > 1 ? argv[1] : "star.png";
    try {
        Pixmap pm(200, 200);
        Canvas canvas(pm);
        canvas.clear(Color::white());
        const Path star = parse_svg_path("M100 10 L161 190 L8 78 L192 78 L39 190 Z");
        canvas.fill_path(star, Paint::solid(parse_color("crimson")), FillRule::EvenOdd);
        StrokeStyle style;
        style.width = 4;
        style.join = LineJoin::Round;
        canvas.stroke_path(star, style, Paint::solid(parse_color("#222")));
        write_png(pm, out);
    } catch (const Error& e) {
        std::fprintf(stderr, "star: %s\n", e.what());
        return 1;
    }
    return 0;
}
