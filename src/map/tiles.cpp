// Map stage: tile pyramids by metatiles, sharding and worker threads (see include/casteljau/tiles.hpp).
#include "casteljau/tiles.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "core/for_each_index.hpp"
#include "map/simplify_map.hpp"

namespace casteljau {

std::vector<Metatile> list_metatiles(int min_zoom, int max_zoom, int metatile) {
    std::vector<Metatile> out;
    for (int z = min_zoom; z <= max_zoom; ++z) {
        const std::int64_t dim = std::int64_t{1} << z;
        const int n = static_cast<int>(std::min<std::int64_t>(metatile, dim));
        for (std::int64_t y = 0; y < dim; y += n)
            for (std::int64_t x = 0; x < dim; x += n) out.push_back({z, static_cast<int>(x), static_cast<int>(y), n});
    }
    return out;
}

std::pair<std::size_t, std::size_t> shard_range(std::size_t count, int shard, int shards) {
    const auto c = static_cast<unsigned long long>(count);
    return {static_cast<std::size_t>(c * static_cast<unsigned>(shard) / static_cast<unsigned>(shards)),
            static_cast<std::size_t>(c * static_cast<unsigned>(shard + 1) / static_cast<unsigned>(shards))};
}

namespace {

void check_options(const TileOptions& o) {
    auto bad = [](const std::string& m) { throw Error(ErrorKind::InvalidArgument, m); };
    if (o.min_zoom < 0 || o.max_zoom > limits::kMaxTileZoom || o.min_zoom > o.max_zoom)
        bad("zoom range must be within 0.." + std::to_string(limits::kMaxTileZoom) + " with min <= max");
    if (o.tile_px < 16 || o.tile_px > 4096) bad("tile size must be 16 to 4096 pixels");
    if (o.metatile < 1 || o.metatile > 64) bad("metatile must be 1 to 64 tiles");
    if (o.buffer < 0 || o.buffer > 1024) bad("buffer must be 0 to 1024 pixels");
    if (o.threads < 1 || o.threads > 256) bad("threads must be 1 to 256");
    if (o.shards < 1 || o.shard < 0 || o.shard >= o.shards) bad("shard must be I/N with 0 <= I < N");
    if (!(o.simplify >= 0) || !std::isfinite(o.simplify)) bad("simplify must be a finite number of pixels >= 0");
    const long long side = static_cast<long long>(o.metatile) * o.tile_px + 2LL * o.buffer;
    if (const Limits lim = current_limits(); side > lim.canvas_dimension || side * side > lim.canvas_pixels)
        bad("metatile x tile size + 2 x buffer exceeds the canvas limits");
}

// Zoom z's projected-to-pixel transform for a metatile whose first pixel is (ox, oy) of the world.
Affine zoom_transform(int z, int tile_px, double ox, double oy) {
    const double world = static_cast<double>(tile_px) * static_cast<double>(std::int64_t{1} << z);
    const double half = kPi * kWebMercatorRadius;
    const double s = world / (2 * half);
    return Affine{s, 0, 0, -s, half * s - ox, half * s - oy};
}

}  // namespace

namespace {

// The geometry of every zoom level: each level's simplified copy, made in the frame of the world
// at that zoom (which a metatile's frame only translates) when the first of its metatiles needs
// it, and released when the last of them is done. The border nodes do not depend on the zoom:
// found once. Sparse data are drawn as they are at the zooms where simplifying them would not
// pay (map_detail::worth_simplifying): one copy of the features' bounds serves those.
class ZoomLevels {
public:
    ZoomLevels(const MapData& data, const MapProjection& merc, const TileOptions& opts,
               const std::vector<Metatile>& metatiles)
        : data_(data), merc_(merc), opts_(opts) {
        if (opts.simplify > 0) {
            as_is_ = map_detail::bounds_only(data, merc, 1);
            nodes_ = map_detail::find_border_nodes(data);
        }
        for (int z = opts.min_zoom; z <= opts.max_zoom; ++z) levels_.push_back(std::make_unique<Level>());
        for (const Metatile& m : metatiles) level(m.z).left += 1;
    }

    const map_detail::SimplifiedMap& simplified(int z) {
        Level& l = level(z);
        std::call_once(l.once, [&] {
            const Affine world = zoom_transform(z, opts_.tile_px, 0, 0);
            l.simplified = map_detail::worth_simplifying(as_is_, merc_, world);
            if (l.simplified) l.map = map_detail::simplify_map(data_, nodes_, merc_, world, opts_.simplify, 1);
        });
        return l.simplified ? l.map : as_is_;
    }

    // One metatile of zoom z is done.
    void finished(int z) {
        Level& l = level(z);
        if (l.left.fetch_sub(1) == 1) l.map = map_detail::SimplifiedMap{};
    }

private:
    struct Level {
        std::once_flag once;
        bool simplified = false;  // else the data are drawn as they are
        map_detail::SimplifiedMap map;
        std::atomic<std::size_t> left{0};  // metatiles of this level still to finish
    };
    Level& level(int z) { return *levels_[static_cast<std::size_t>(z - opts_.min_zoom)]; }

    const MapData& data_;
    const MapProjection& merc_;
    const TileOptions& opts_;
    map_detail::SimplifiedMap as_is_;
    map_detail::BorderNodes nodes_;
    std::vector<std::unique_ptr<Level>> levels_;
};

// The tiles of one metatile, encoded, and what it left out.
struct MetatileTiles {
    std::vector<std::tuple<int, int, std::vector<std::uint8_t>>> tiles;  // x, y, PNG
    std::uint64_t empty = 0, existing = 0;
};

// Copies tile (i, j) of the metatile drawn in `pm` (with a buffer of B pixels) into `tile`; true when
// every pixel is the background `bg`.
bool cut_tile(const Pixmap& pm, int i, int j, int B, PremulPixel bg, Pixmap& tile) {
    const int T = tile.width();
    bool is_empty = true;
    for (int r = 0; r < T; ++r) {
        const std::uint8_t* src = pm.row(B + j * T + r) + static_cast<std::size_t>(B + i * T) * 4;
        std::copy(src, src + static_cast<std::size_t>(T) * 4, tile.row(r));
        if (is_empty)
            for (int c = 0; c < T; ++c)
                if (!(PremulPixel{src[c * 4], src[c * 4 + 1], src[c * 4 + 2], src[c * 4 + 3]} == bg)) {
                    is_empty = false;
                    break;
                }
    }
    return is_empty;
}

}  // namespace

TileStats render_tiles(const MapData& data, const MapStyle& style, const TileOptions& opts, const TileSink& sink,
                       const TileExists& exists, const std::function<void(std::uint64_t, std::uint64_t)>& progress) {
    check_options(opts);
    const std::vector<Metatile> all = list_metatiles(opts.min_zoom, opts.max_zoom, opts.metatile);
    const std::pair<std::size_t, std::size_t> range = shard_range(all.size(), opts.shard, opts.shards);
    const std::vector<Metatile> mine(all.begin() + static_cast<std::ptrdiff_t>(range.first),
                                     all.begin() + static_cast<std::ptrdiff_t>(range.second));
    const MapProjection merc = MapProjection::parse("mercator");
    const PremulPixel bg = premultiply(style.background);
    MapOptions mo;
    mo.seamless = opts.seamless;
    mo.tolerance = opts.tolerance;
    mo.simplify = opts.simplify;
    mo.exact_overlaps = opts.exact_overlaps;
    mo.sampled_strokes = opts.sampled_strokes;
    mo.threads = 1;  // the worker threads take a metatile each
    ZoomLevels levels(data, merc, opts, mine);

    // One metatile: rendered whole with its buffer, cut into tiles (those not already there), each
    // encoded unless it is empty and empty tiles are skipped.
    auto render = [&](const Metatile& m) {
        const std::int64_t dim = std::int64_t{1} << m.z;
        const int nx = static_cast<int>(std::min<std::int64_t>(m.n, dim - m.x0));
        const int ny = static_cast<int>(std::min<std::int64_t>(m.n, dim - m.y0));
        MetatileTiles out;
        std::vector<char> todo(static_cast<std::size_t>(nx * ny), 1);
        if (opts.resume && exists)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                    if (exists(m.z, m.x0 + i, m.y0 + j)) {
                        todo[static_cast<std::size_t>(j * nx + i)] = 0;
                        ++out.existing;
                    }
        if (out.existing == static_cast<std::uint64_t>(nx * ny)) return out;
        const int T = opts.tile_px, B = opts.buffer;
        MapFrame fr;
        fr.width = nx * T + 2 * B;
        fr.height = ny * T + 2 * B;
        fr.to_pixel = zoom_transform(m.z, T, static_cast<double>(m.x0) * T - B, static_cast<double>(m.y0) * T - B);
        Pixmap pm(fr.width, fr.height);
        if (opts.simplify > 0)
            map_detail::render_simplified_map(data, levels.simplified(m.z), merc, fr, style, mo, pm);
        else
            render_map(data, merc, fr, style, mo, pm);
        Pixmap tile(T, T);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                if (!todo[static_cast<std::size_t>(j * nx + i)]) continue;
                if (cut_tile(pm, i, j, B, bg, tile) && opts.skip_empty)
                    ++out.empty;
                else
                    out.tiles.emplace_back(m.x0 + i, m.y0 + j, encode_png(tile));
            }
        return out;
    };

    std::mutex mu;  // guards sink, stats and progress
    TileStats stats;
    std::atomic<bool> stop{false};  // a metatile failed: later ones are not handed to the sink
    std::uint64_t done = 0;
    auto metatile = [&](int, std::size_t index) {
        const Metatile& m = mine[index];
        struct Done {
            ZoomLevels& levels;
            int z;
            ~Done() { levels.finished(z); }
        } done_guard{levels, m.z};
        // Outside the try: a failure once it is taken sets `stop` before it is released, so a
        // worker waiting for it does not hand on its tiles.
        std::unique_lock<std::mutex> lock(mu, std::defer_lock);
        try {
            MetatileTiles out = render(m);
            lock.lock();
            if (stop.load()) return;
            for (auto& [x, y, png] : out.tiles) sink(m.z, x, y, png);
            stats.metatiles += 1;
            stats.written += out.tiles.size();
            stats.skipped_empty += out.empty;
            stats.skipped_existing += out.existing;
            ++done;
            if (progress) progress(done, mine.size());
        } catch (...) {
            stop.store(true);
            throw;
        }
    };
    parallel::for_each_index(opts.threads, mine.size(), metatile);
    return stats;
}

}  // namespace casteljau
