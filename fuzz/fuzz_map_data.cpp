// libFuzzer target: the map readers (GeoJSON, GeoJSON lines, TopoJSON) and, for small inputs that
// read, the map stage (antimeridian split, projection, fit, seamless fills, strokes) at 64 x 32.
// The first byte picks the reader so that each one sees every input shape.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/map.hpp"

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
        (void)render_map(d, proj, style, o);
    } catch (const Error&) {}
    return 0;
}
