// libFuzzer target: the map readers (GeoJSON, GeoJSON lines, TopoJSON) and, for small inputs that
// read, the map stage (antimeridian split, projection, fit, seamless fills, strokes) at 64 x 32,
// and with a MapCache (first byte, bit 5) in that frame and another, within one level of the
// renders without it.
// The first byte picks the reader so that each one sees every input shape.
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/map.hpp"

namespace {

void expect_close(const casteljau::Pixmap& a, const casteljau::Pixmap& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const casteljau::PremulPixel p = a.pixel(x, y), q = b.pixel(x, y);
            if (std::abs(p.r - q.r) > 1 || std::abs(p.g - q.g) > 1 || std::abs(p.b - q.b) > 1 ||
                std::abs(p.a - q.a) > 1) {
                std::fprintf(stderr, "fuzz_map_data: a render with a MapCache differs at (%d, %d)\n", x, y);
                std::abort();
            }
        }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace casteljau;
    if (size < 1) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        MapData d;
        switch (data[0] % 4) {
            case 0: d = read_map_data(text); break;
            case 1: d = read_geojson(text); break;
            case 2: d = read_geojson_lines(text); break;
            default: d = read_topojson(text); break;
        }
        // Rendering cost grows with the outline complexity per pixel (strokes of a whole world in
        // 64 x 32 pixels take seconds under the sanitizers): render only small inputs.
        if (d.position_count() > 2000) return 0;
        MapStyle style;
        style.layers[0].stroke = Color::rgba(0, 0, 0, 128);
        style.layers[0].fill_by = "n";
        MapOptions o;
        o.width = 64;
        o.height = 32;
        o.seamless = (data[0] & 4) == 0;
        if (data[0] & 8) o.bbox = Rect{-180, -90, 180, 90};
        const MapProjection proj = MapProjection::parse((data[0] & 16) ? "mercator" : "equirectangular");
        const Pixmap plain = render_map(d, proj, style, o);
        // With a MapCache (data[0] bit 5): its first render, then one in a frame of another scale
        // and offset, each within one level of the render without it (both exact).
        if (data[0] & 32) {
            MapCache cache;
            MapOptions kept = o;
            kept.cache = &cache;
            expect_close(render_map(d, proj, style, kept), plain);
            MapOptions other = o;
            other.width = 48;
            other.height = 40;
            other.padding = 3.5;
            const Pixmap without = render_map(d, proj, style, other);
            other.cache = &cache;
            expect_close(render_map(d, proj, style, other), without);
        }
    } catch (const Error&) {}
    return 0;
}
