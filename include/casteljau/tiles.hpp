// casteljau/tiles.hpp: XYZ tile pyramids (Web Mercator) rendered by metatiles, written to a folder
// tree DIR/z/x/y.png or to an MBTiles 1.3 file (SQLite), and sharded over processes.
//
// Pipeline position: the map stage (map.hpp) run once per metatile. A metatile is a block of
// metatile x metatile tiles (8 x 8 by default, fewer at low zooms) rendered as one image with a
// buffer of `buffer` pixels on every side, so that strokes, point disks and anti-aliasing that
// cross a tile edge are computed from the same geometry on both sides: a tile is a crop of a render
// of a larger area, never an image drawn on its own. The seamless fill compositing runs on the
// whole metatile.
//
// Coordinates: tile (z, x, y) is the XYZ scheme (y = 0 at the north edge, as web maps use);
// MBTiles stores the TMS row (2^z - 1 - y). At zoom z the world is tile_px * 2^z pixels wide:
// Web Mercator x = -20037508.34 m maps to pixel 0.
//
// Sharding: the metatiles of all requested zooms, in order (z, then row, then column), are cut into
// N contiguous runs of equal length; shard I renders run I, so neighbouring metatiles stay together
// and the union of the shards is exactly the unsharded pyramid. Output is deterministic: the same
// input and options give the same bytes whatever the thread count or sharding.
//
// Files: every tile PNG is written atomically (temporary file + rename), so --resume can trust any
// tile it finds; an MBTiles file is built under a temporary name and renamed when complete.
//
// Thread-safety: render_tiles() renders a metatile per thread on up to TileOptions::threads
// threads of the process-wide pool (casteljau/threads.hpp); MapData is only read.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "casteljau/geojson.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/map.hpp"

namespace casteljau {

struct TileOptions {
    int min_zoom = 0, max_zoom = 0;  // 0..limits::kMaxTileZoom
    int tile_px = 256;               // pixels per tile side (tile size x scale)
    int metatile = 8;                // tiles per metatile side (1..64)
    int buffer = 64;                 // pixels rendered around each metatile
    bool skip_empty = false;         // tiles equal to the background everywhere are not written
    int threads = 1;                 // 1..256, at most the pool's size are used
    bool resume = false;             // folder output: skip tiles already there
    int shard = 0, shards = 1;       // render only share `shard` of `shards`
    bool seamless = true;
    double tolerance = kDefaultTolerance;
    // See MapOptions::simplify: each zoom level that needs it is simplified once, for all of its
    // metatiles.
    double simplify = kDefaultMapSimplify;
    bool exact_overlaps = true;   // see MapOptions::exact_overlaps
    bool sampled_strokes = true;  // see MapOptions::sampled_strokes
};

struct TileStats {
    std::uint64_t metatiles = 0, written = 0, skipped_empty = 0, skipped_existing = 0;
};

// Receives each finished tile (PNG bytes). Called from one thread at a time, in any order.
using TileSink = std::function<void(int z, int x, int y, const std::vector<std::uint8_t>& png)>;
// Asked before a metatile is rendered (resume): true when tile (z, x, y) already exists.
using TileExists = std::function<bool(int z, int x, int y)>;

// Renders the share of the pyramid selected by opts.shard / opts.shards. `progress` (optional) is
// called after each metatile with (done, total) for this shard. Throws Error(InvalidArgument) for
// options outside their ranges; errors of the sink propagate (other workers stop first).
TileStats render_tiles(const MapData& data, const MapStyle& style, const TileOptions& opts, const TileSink& sink,
                       const TileExists& exists = {},
                       const std::function<void(std::uint64_t, std::uint64_t)>& progress = {});

// The metatiles of zooms min..max in render order, as (z, first tile x, first tile y).
struct Metatile {
    int z, x0, y0, n;  // n: tiles per side in this metatile (fewer at zooms below log2(metatile))
};
std::vector<Metatile> list_metatiles(int min_zoom, int max_zoom, int metatile);
// The contiguous run of `list` that shard `shard` of `shards` renders: [begin, end).
std::pair<std::size_t, std::size_t> shard_range(std::size_t count, int shard, int shards);

// Writes tiles into DIR/z/x/y.png (folders created as needed, each file atomically).
class TileFolderWriter {
public:
    explicit TileFolderWriter(std::string dir);
    void write(int z, int x, int y, const std::vector<std::uint8_t>& png);
    bool exists(int z, int x, int y) const;
    std::string tile_path(int z, int x, int y) const;
    // Removes the temporary files that writes interrupted by a kill or a crash left in the tile
    // folders (is_atomic_write_temporary); returns how many. For --resume.
    std::size_t remove_interrupted_writes() const;

private:
    std::string dir_;
};

// MBTiles 1.3: tables `metadata(name, value)` and `tiles(zoom_level, tile_column, tile_row,
// tile_data)` with TMS rows. Built in PATH.tmp-PID and renamed over PATH by finish(); destroyed
// without finish() (an error), the temporary file is removed and PATH is untouched. SQLite
// (libsqlite3.so.0) is opened when the first MBTiles file is written or read, not at start-up;
// when it cannot be, these calls throw Error(Io) naming it.
class MbtilesWriter {
public:
    // Throws Error(Io) naming the path when the database cannot be created.
    MbtilesWriter(std::string path, const std::string& name, int min_zoom, int max_zoom, const Rect& bounds_deg);
    ~MbtilesWriter();
    MbtilesWriter(const MbtilesWriter&) = delete;
    MbtilesWriter& operator=(const MbtilesWriter&) = delete;
    void write(int z, int x, int y, const std::vector<std::uint8_t>& png);
    void finish();

private:
    struct Impl;
    Impl* impl_;
};

// Renders the pyramid (render_tiles) into `output`: an MBTiles file when the name ends in
// ".mbtiles" (`name` in its metadata, the Web Mercator world as its bounds), else a folder tree
// DIR/z/x/y.png, where opts.resume first removes the temporary files of interrupted writes and then
// skips the tiles already there. Throws Error(InvalidArgument) for opts.resume with an MBTiles
// output (written whole), and as render_tiles and the writers do.
TileStats write_tiles(const MapData& data, const MapStyle& style, const TileOptions& opts, const std::string& output,
                      const std::string& name, const std::function<void(std::uint64_t, std::uint64_t)>& progress = {});

// Joins MBTiles files (for example one per shard) into `output` (atomically, as above): every
// tile of every input, metadata from the first input with minzoom/maxzoom/bounds widened to all.
void merge_mbtiles(const std::vector<std::string>& inputs, const std::string& output);

}  // namespace casteljau
