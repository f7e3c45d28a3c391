// A user's first program: the umbrella header, a filled circle, one PNG. Checks three pixels of
// what it drew and exits 1 when one is wrong.
// Usage: consumer OUT.png
#include <cstdio>

#include "casteljau/casteljau.hpp"

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    try {
        casteljau::Pixmap pixmap(64, 64);
        casteljau::Canvas canvas(pixmap);
        canvas.clear(casteljau::Color::white());
        casteljau::Path circle;
        circle.add_circle({32, 32}, 20);
        canvas.fill_path(circle, casteljau::Paint::solid(casteljau::Color::rgba(200, 0, 0)));
        casteljau::write_png(pixmap, argv[1]);

        const casteljau::PremulPixel centre = pixmap.pixel(32, 32);
        const casteljau::PremulPixel corner = pixmap.pixel(1, 1);
        const casteljau::PremulPixel edge = pixmap.pixel(17, 17);  // crossed by the circle at (17.86, 17.86)
        const bool ok = centre == casteljau::PremulPixel{200, 0, 0, 255} &&
                        corner == casteljau::PremulPixel{255, 255, 255, 255} && edge.g > 0 && edge.g < 255;
        if (!ok) {
            std::fprintf(stderr, "consumer: wrong pixels: centre %d,%d,%d corner %d,%d,%d edge %d,%d,%d\n", centre.r,
                         centre.g, centre.b, corner.r, corner.g, corner.b, edge.r, edge.g, edge.b);
            return 1;
        }
    } catch (const casteljau::Error& e) {
        std::fprintf(stderr, "consumer: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
