// The command-line front end: shared declarations for the subcommand files.
//
// Each subcommand lives in its own file src/cli/cmd_NAME.cpp and exposes one registration
// function, declared here and called from run.cpp, that adds a CLI11 subcommand and its callback.
// Callbacks report bad data by throwing casteljau::Error (exit 1) and bad usage by throwing
// cli::UsageError (exit 2); run.cpp prints the one-line "casteljau: error: ..." message.
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

#include "casteljau/flatten.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/map.hpp"
#include "casteljau/paint.hpp"
#include "cli/run.hpp"

namespace casteljau::cli {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parsing helpers shared by commands; each throws UsageError with the option's name.
Color parse_color_option(const std::string& option, const std::string& text);
// "WxH" -> width, height (positive integers within the canvas limits).
void parse_size_option(const std::string& option, const std::string& text, int& width, int& height);
// "a b c d e f" (spaces or commas) -> Affine.
Affine parse_affine_option(const std::string& option, const std::string& text);
// Reads a whole input file ("-" reads standard input) as text; throws Error(Io).
std::string read_text_input(const std::string& path);

// Options shared by `map` and `tiles` (cmd_map.cpp).
struct MapCliStyle {
    std::string fill = "black", stroke, join = "round", cap = "round", background = "transparent";
    std::string fill_by, ramp, style_file, projection = "equirectangular", layer;
    double stroke_width = 1, point_radius = 3, opacity = 1, tolerance = kDefaultTolerance;
    double simplify = kDefaultMapSimplify;
    bool separate = false, no_exact = false, exact_strokes = false;
};
void add_map_style_options(CLI::App* cmd, MapCliStyle& o);
MapStyle build_map_style(const MapCliStyle& o);
// Reads a map file by its extension (.geojsonl/.ndjson: GeoJSON lines, .topojson) or content.
MapData read_map_input(const std::string& path, const std::string& layer);

void register_path(CLI::App& app);
void register_svg(CLI::App& app);
void register_bezier(CLI::App& app);
void register_spline(CLI::App& app);
void register_surface(CLI::App& app);
void register_text(CLI::App& app);
void register_map(CLI::App& app);
void register_tiles(CLI::App& app);

}  // namespace casteljau::cli
