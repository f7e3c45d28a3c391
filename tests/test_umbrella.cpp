// The umbrella header casteljau/casteljau.hpp, included alone, declares the whole C++ API: this file
// includes nothing else of casteljau and uses types of several stages (path data, canvas, limits,
// seamless compositing, text shaping, file I/O).
#include <catch2/catch.hpp>

#include "casteljau/casteljau.hpp"

using namespace casteljau;

TEST_CASE("casteljau.hpp alone: a path parsed, filled on a canvas and composited seamlessly", "[umbrella]") {
    const Path square = parse_svg_path("M1 1H7V7H1Z");
    Pixmap pm(8, 8);
    Canvas canvas(pm);
    canvas.fill_path(square, Paint::solid(Color::black()));
    CHECK(pm.pixel(4, 4) == PremulPixel{0, 0, 0, 255});
    CHECK(pm.pixel(0, 0) == PremulPixel{0, 0, 0, 0});

    SeamlessCompositor compositor(8, 8);
    compositor.add(canvas.rasterizer(), square, FillOptions{}, Color::white());
    CHECK(compositor.taken(4, 4) == 255);

    CHECK(current_limits().canvas_dimension == limits::kMaxCanvasDimension);
    CHECK(kPi == Approx(3.141592653589793));
    CHECK(sniff_image(std::vector<std::uint8_t>{0xff, 0xd8, 0xff}) == ImageFormat::Jpeg);
    CHECK_FALSE(is_atomic_write_temporary("plain.png"));
    CHECK_FALSE(letter_spacing_allowed(U'\u0628'));  // Arabic BEH: letters join
}
