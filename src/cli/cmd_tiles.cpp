// `casteljau tiles`: render an XYZ tile pyramid (folder or MBTiles), optionally one shard of it;
// `casteljau tiles-merge`: join MBTiles files.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/map.hpp"
#include "casteljau/threads.hpp"
#include "casteljau/tiles.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

namespace {

int parse_int(const std::string& option, const std::string& s) {
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError(option + ": expected a number, got '" + s + "'");
    return std::atoi(s.c_str());
}

void parse_zoom(const std::string& text, int& lo, int& hi) {
    const auto dash = text.find('-');
    lo = parse_int("--zoom", dash == std::string::npos ? text : text.substr(0, dash));
    hi = dash == std::string::npos ? lo : parse_int("--zoom", text.substr(dash + 1));
    if (hi > limits::kMaxTileZoom)
        throw UsageError("--zoom: at most " + std::to_string(limits::kMaxTileZoom) + ", got '" + text + "'");
    if (lo > hi) throw UsageError("--zoom: expected MIN-MAX with MIN <= MAX, got '" + text + "'");
}

// Shard from --shard I/N, else from the batch engine's environment.
void parse_shard(const std::string& text, int shards_opt, int& shard, int& shards) {
    if (!text.empty()) {
        const auto slash = text.find('/');
        if (slash == std::string::npos) throw UsageError("--shard: expected I/N, got '" + text + "'");
        shard = parse_int("--shard", text.substr(0, slash));
        shards = parse_int("--shard", text.substr(slash + 1));
    } else {
        auto env = [](const char* n) -> const char* {
            const char* v = std::getenv(n);
            return v && *v ? v : nullptr;
        };
        if (const char* k = env("JOB_COMPLETION_INDEX")) {  // Kubernetes Indexed Job
            if (shards_opt < 1)
                throw UsageError("JOB_COMPLETION_INDEX is set: pass --shards N (the Job's completions)");
            shard = parse_int("JOB_COMPLETION_INDEX", k);
            shards = shards_opt;
        } else if (const char* s = env("SLURM_ARRAY_TASK_ID")) {
            const char* n = env("SLURM_ARRAY_TASK_COUNT");
            if (!n && shards_opt < 1)
                throw UsageError("SLURM_ARRAY_TASK_ID is set without SLURM_ARRAY_TASK_COUNT: pass --shards N");
            shard = parse_int("SLURM_ARRAY_TASK_ID", s);
            shards = n ? parse_int("SLURM_ARRAY_TASK_COUNT", n) : shards_opt;
        } else if (const char* a = env("AWS_BATCH_JOB_ARRAY_INDEX")) {
            const char* n = env("AWS_BATCH_JOB_ARRAY_SIZE");
            if (!n && shards_opt < 1)
                throw UsageError("AWS_BATCH_JOB_ARRAY_INDEX is set without AWS_BATCH_JOB_ARRAY_SIZE: pass --shards N");
            shard = parse_int("AWS_BATCH_JOB_ARRAY_INDEX", a);
            shards = n ? parse_int("AWS_BATCH_JOB_ARRAY_SIZE", n) : shards_opt;
        } else {
            shard = 0;
            shards = 1;
        }
    }
    if (shards < 1 || shard >= shards)
        throw UsageError("shard " + std::to_string(shard) + " of " + std::to_string(shards) + " is out of range");
}

struct TilesOpts {
    std::string input, output, zoom, shard, name = "casteljau";
    int tile_size = 256, scale = 1, metatile = 8, buffer = 64, threads = 0, shards = 0;
    bool skip_empty = false, resume = false, quiet = false;
    MapCliStyle style;
};

// The pyramid's options from the command line (usage errors first); --threads sizes the pool the
// metatiles are rendered on (casteljau/threads.hpp).
TileOptions tile_options(const TilesOpts& o) {
    TileOptions to;
    parse_zoom(o.zoom, to.min_zoom, to.max_zoom);
    parse_shard(o.shard, o.shards, to.shard, to.shards);
    to.tile_px = o.tile_size * o.scale;
    to.metatile = o.metatile;
    to.buffer = o.buffer * o.scale;
    to.skip_empty = o.skip_empty;
    to.resume = o.resume;
    if (o.threads > 0) set_thread_count(o.threads);
    to.threads = map_threads(0);
    to.seamless = !o.style.separate;
    to.tolerance = o.style.tolerance;
    to.simplify = o.style.simplify;
    to.exact_overlaps = !o.style.no_exact;
    to.sampled_strokes = !o.style.exact_strokes;
    return to;
}

// The style at --scale: stroke widths and point radii grow with the pixel ratio.
MapStyle tile_style(const TilesOpts& o) {
    if (o.style.projection != "equirectangular" && o.style.projection != "mercator")
        throw UsageError("--projection: tiles are always Web Mercator");
    MapStyle style = build_map_style(o.style);
    for (MapLayerStyle& l : style.layers) l.stroke_width *= o.scale;
    style.point_radius *= o.scale;
    return style;
}

// Progress on a terminal's stderr (metatiles done, rate, time left), and the summary at the end.
class TilesReport {
public:
    explicit TilesReport(bool quiet) : quiet_(quiet), tty_(!quiet && ::isatty(2)) {}

    void progress(std::uint64_t done, std::uint64_t total) const {
        if (!tty_) return;
        const double s = seconds();
        const double rate = s > 0 ? done / s : 0;
        const double eta = rate > 0 ? (total - done) / rate : 0;
        std::fprintf(stderr, "\r  %llu/%llu metatiles  %.1f metatiles/s  ETA %.0f s   ",
                     static_cast<unsigned long long>(done), static_cast<unsigned long long>(total), rate, eta);
    }

    void summary(const TileOptions& to, const TileStats& st) const {
        if (quiet_) return;
        const double s = seconds();
        if (tty_) std::fprintf(stderr, "\n");
        std::fprintf(stderr,
                     "casteljau: tiles: shard %d/%d, %llu metatiles, %llu tiles written, %llu empty skipped, "
                     "%llu already there, %.2f s (%.1f tiles/s)\n",
                     to.shard, to.shards, static_cast<unsigned long long>(st.metatiles),
                     static_cast<unsigned long long>(st.written), static_cast<unsigned long long>(st.skipped_empty),
                     static_cast<unsigned long long>(st.skipped_existing), s, s > 0 ? st.written / s : 0.0);
    }

private:
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }
    bool quiet_, tty_;
    std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

void run_tiles(const TilesOpts& o) {
    const TileOptions to = tile_options(o);
    const MapStyle style = tile_style(o);
    if (o.output.ends_with(".mbtiles") && o.resume)
        throw UsageError("--resume works with a folder output (an .mbtiles file is written whole)");
    const MapData data = read_map_input(o.input, o.style.layer);
    const TilesReport report(o.quiet);
    const TileStats st = write_tiles(data, style, to, o.output, o.name,
                                     [&](std::uint64_t done, std::uint64_t total) { report.progress(done, total); });
    report.summary(to, st);
}

// The pyramid's shape and share: tile size and scale, metatiles, buffer, what is skipped, threads,
// shards.
void add_pyramid_options(CLI::App* cmd, TilesOpts& o) {
    cmd->add_option("--tile-size", o.tile_size, "Tile size in pixels before --scale")
        ->check(CLI::IsMember({256, 512}))
        ->capture_default_str();
    cmd->add_option("--scale", o.scale, "Pixel ratio (2 for retina tiles; strokes and points scale too)")
        ->check(CLI::Range(1, 4))
        ->capture_default_str();
    cmd->add_option("--metatile", o.metatile, "Tiles per metatile side")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    cmd->add_option("--buffer", o.buffer, "Pixels rendered around each metatile")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_flag("--skip-empty", o.skip_empty, "Do not write tiles that show only the background");
    cmd->add_option("--threads", o.threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 256));
    cmd->add_flag("--resume", o.resume, "Skip tiles already written (folder output)");
    cmd->add_option("--shard", o.shard,
                    "Render share I of N (I/N, 0-based); default from JOB_COMPLETION_INDEX, "
                    "SLURM_ARRAY_TASK_ID or AWS_BATCH_JOB_ARRAY_INDEX");
    cmd->add_option("--shards", o.shards, "Number of shards when the index comes from JOB_COMPLETION_INDEX")
        ->check(CLI::Range(1, 1000000));
}

}  // namespace

void register_tiles(CLI::App& app) {
    auto o = std::make_shared<TilesOpts>();
    CLI::App* cmd =
        app.add_subcommand("tiles", "Render an XYZ tile pyramid (Web Mercator) to a folder or an .mbtiles file");
    cmd->add_option("INPUT", o->input, "Map file: .geojson, .json, .topojson, .geojsonl (- for standard input)")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output folder (DIR/z/x/y.png) or FILE.mbtiles")->required();
    cmd->add_option("--zoom", o->zoom, "Zoom levels MIN-MAX (or one level), 0 to 24")->required();
    add_pyramid_options(cmd, *o);
    cmd->add_option("--name", o->name, "MBTiles metadata name")->capture_default_str();
    cmd->add_flag("-q,--quiet", o->quiet, "No progress or summary on stderr");
    add_map_style_options(cmd, o->style);
    cmd->callback([o] { run_tiles(*o); });

    auto m = std::make_shared<std::pair<std::vector<std::string>, std::string>>();
    CLI::App* merge = app.add_subcommand("tiles-merge", "Join MBTiles files (for example one per shard) into one");
    merge->add_option("INPUTS", m->first, "MBTiles files")->required();
    merge->add_option("-o,--output", m->second, "Output .mbtiles file")->required();
    merge->callback([m] { merge_mbtiles(m->first, m->second); });
}

}  // namespace casteljau::cli
