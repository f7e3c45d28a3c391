// C API: tile pyramids (casteljau_map.h, casteljau_tile_*), written the way `casteljau tiles` does.
#include <string>

#include "capi/handles.hpp"

using namespace casteljau;
using casteljau::capi::check_range;
using casteljau::capi::guard;
using casteljau::capi::need;

namespace {

template <class F>
casteljau_status edit(casteljau_tile_options* options, F&& f) noexcept {
    return guard([&] { f(*need(options, "options")); });
}

// The pyramid's options and style at the options' scale: pixels per tile, buffer, stroke widths
// and point radii all grow with it, as --scale does.
TileOptions scaled_options(const casteljau_tile_options& o) {
    TileOptions to = o.options;
    to.tile_px = o.tile_size * o.scale;
    to.buffer = o.buffer * o.scale;
    to.threads = map_threads(0);
    return to;
}

MapStyle scaled_style(const casteljau_map_style* style, int scale) {
    MapStyle st = style ? style->style : MapStyle{};
    for (MapLayerStyle& l : st.layers) l.stroke_width *= scale;
    st.point_radius *= scale;
    return st;
}

}  // namespace

extern "C" {

casteljau_tile_options* casteljau_tile_options_create(void) {
    return casteljau::capi::create_default<casteljau_tile_options>();
}

void casteljau_tile_options_destroy(casteljau_tile_options* options) { delete options; }

casteljau_status casteljau_tile_options_set_zoom(casteljau_tile_options* options, int min_zoom, int max_zoom) {
    return edit(options, [&](casteljau_tile_options& o) {
        check_range(min_zoom, 0, limits::kMaxTileZoom, "minimum zoom");
        check_range(max_zoom, min_zoom, limits::kMaxTileZoom, "maximum zoom");
        o.options.min_zoom = min_zoom;
        o.options.max_zoom = max_zoom;
    });
}

casteljau_status casteljau_tile_options_set_tile_size(casteljau_tile_options* options, int size, int scale) {
    return edit(options, [&](casteljau_tile_options& o) {
        if (size != 256 && size != 512) throw Error(ErrorKind::InvalidArgument, "tile size must be 256 or 512");
        check_range(scale, 1, 4, "scale");
        o.tile_size = size;
        o.scale = scale;
    });
}

casteljau_status casteljau_tile_options_set_metatile(casteljau_tile_options* options, int tiles) {
    return edit(options, [&](casteljau_tile_options& o) {
        check_range(tiles, 1, 64, "metatile");
        o.options.metatile = tiles;
    });
}

casteljau_status casteljau_tile_options_set_buffer(casteljau_tile_options* options, int pixels) {
    return edit(options, [&](casteljau_tile_options& o) {
        check_range(pixels, 0, 1024, "buffer");
        o.buffer = pixels;
    });
}

casteljau_status casteljau_tile_options_set_skip_empty(casteljau_tile_options* options, int skip) {
    return edit(options, [&](casteljau_tile_options& o) { o.options.skip_empty = skip != 0; });
}

casteljau_status casteljau_tile_options_set_resume(casteljau_tile_options* options, int resume) {
    return edit(options, [&](casteljau_tile_options& o) { o.options.resume = resume != 0; });
}

casteljau_status casteljau_tile_options_set_shard(casteljau_tile_options* options, int shard, int shards) {
    return edit(options, [&](casteljau_tile_options& o) {
        check_range(shards, 1, 1000000, "shards");
        check_range(shard, 0, shards - 1, "shard");
        o.options.shard = shard;
        o.options.shards = shards;
    });
}

casteljau_status casteljau_tile_options_set_name(casteljau_tile_options* options, const char* name) {
    return edit(options, [&](casteljau_tile_options& o) { o.name = need(name, "name"); });
}

casteljau_status casteljau_tile_options_set_separate(casteljau_tile_options* options, int separate) {
    return edit(options, [&](casteljau_tile_options& o) { o.options.seamless = separate == 0; });
}

casteljau_status casteljau_tile_options_set_exact_overlaps(casteljau_tile_options* options, int exact) {
    return edit(options, [&](casteljau_tile_options& o) { o.options.exact_overlaps = exact != 0; });
}

casteljau_status casteljau_tile_options_set_tolerance(casteljau_tile_options* options, double tolerance) {
    return edit(options, [&](casteljau_tile_options& o) {
        check_range(tolerance, 1e-4, 10, "tolerance");
        o.options.tolerance = tolerance;
    });
}

casteljau_status casteljau_map_render_tiles(const casteljau_map* map, const casteljau_map_style* style,
                                            const casteljau_tile_options* options, const char* output,
                                            casteljau_tile_progress progress, void* user, casteljau_tile_stats* stats) {
    if (stats) *stats = {};
    return guard([&] {
        const MapData& data = need(map, "map")->data;
        const casteljau_tile_options& o = *need(options, "options");
        const std::string out = need(output, "output");
        if (out.empty()) throw Error(ErrorKind::InvalidArgument, "the output is empty");
        auto report = [&](std::uint64_t done, std::uint64_t total) {
            if (progress && progress(done, total, user) != 0) throw casteljau::capi::Cancelled{};
        };
        const TileStats st = write_tiles(data, scaled_style(style, o.scale), scaled_options(o), out, o.name, report);
        if (stats) *stats = {st.metatiles, st.written, st.skipped_empty, st.skipped_existing};
    });
}

}  // extern "C"
