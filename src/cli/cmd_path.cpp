// `casteljau path`: fill SVG path data onto a canvas and write a PNG.
#include <cmath>
#include <iostream>
#include <sstream>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg_path.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

namespace {

struct PathOpts {
    std::string data, output, size, fill = "black", rule = "nonzero", background = "transparent", transform;
    double tolerance = kDefaultTolerance;
    bool no_exact = false;
    std::string stroke, cap = "butt", join = "miter", dashes;
    double stroke_width = 1, miter_limit = 4;
};

// --dash "on off ...": lengths separated by spaces or commas, each a non-negative number.
std::vector<double> parse_dash_option(const std::string& text) {
    std::string list = text;
    for (char& c : list)
        if (c == ',') c = ' ';
    std::istringstream in(list);
    std::vector<double> dashes;
    double v;
    while (in >> v) {
        if (!(v >= 0) || !std::isfinite(v)) throw UsageError("--dash: lengths must be non-negative numbers");
        dashes.push_back(v);
    }
    if (!in.eof()) throw UsageError("--dash: expected numbers, got '" + text + "'");
    return dashes;
}

StrokeStyle stroke_style(const PathOpts& o) {
    StrokeStyle style;
    style.width = o.stroke_width;
    parse_line_cap(o.cap, style.cap);  // the option checks only admit valid names
    parse_line_join(o.join, style.join);
    style.miter_limit = o.miter_limit;
    if (!o.dashes.empty()) style.dashes = parse_dash_option(o.dashes);
    return style;
}

// The path data argument: the data itself, @FILE, or - for standard input.
std::string path_data(const std::string& arg) {
    if (arg == "-") return read_text_input("-");
    if (!arg.empty() && arg[0] == '@') return read_text_input(arg.substr(1));
    return arg;
}

void run_path(const PathOpts& o) {
    int w = 0, h = 0;
    parse_size_option("--size", o.size, w, h);
    const Color fill = parse_color_option("--fill", o.fill);
    const Color bg = parse_color_option("--background", o.background);
    const Affine m = o.transform.empty() ? Affine{} : parse_affine_option("--transform", o.transform);
    const Path path = parse_svg_path(path_data(o.data));
    Pixmap pm(w, h);
    pm.fill(bg);
    Canvas canvas(pm);
    canvas.fill_options().tolerance = o.tolerance;
    canvas.fill_options().exact_overlaps = !o.no_exact;
    canvas.set_transform(m);
    canvas.fill_path(path, Paint::solid(fill), o.rule == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero);
    if (!o.stroke.empty()) {
        const StrokeStyle style = stroke_style(o);
        canvas.stroke_path(path, style, Paint::solid(parse_color_option("--stroke", o.stroke)));
    }
    write_png(pm, o.output);
}

// The stroke drawn over the fill: colour, width, caps, joins, miter limit, dashes.
void add_stroke_options(CLI::App* cmd, PathOpts& o) {
    cmd->add_option("--stroke", o.stroke, "Stroke colour (CSS syntax); the stroke is drawn over the fill");
    cmd->add_option("--stroke-width", o.stroke_width, "Stroke width in path units")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    cmd->add_option("--line-cap", o.cap, "butt, round or square")
        ->check(CLI::IsMember({"butt", "round", "square"}))
        ->capture_default_str();
    cmd->add_option("--line-join", o.join, "miter, miter-clip, round or bevel")
        ->check(CLI::IsMember({"miter", "miter-clip", "round", "bevel"}))
        ->capture_default_str();
    cmd->add_option("--miter-limit", o.miter_limit, "Miter limit (ratio to the width)")
        ->check(CLI::Range(1.0, 1e6))
        ->capture_default_str();
    cmd->add_option("--dash", o.dashes, "Dash pattern \"on off ...\" in path units");
}

}  // namespace

void register_path(CLI::App& app) {
    auto o = std::make_shared<PathOpts>();
    CLI::App* cmd = app.add_subcommand("path", "Fill SVG path data and write a PNG");
    cmd->add_option("DATA", o->data,
                    "SVG path data, e.g. \"M10 10 L90 10 L50 90 Z\"; @FILE reads it from a file, - from standard input")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output PNG file")->required();
    cmd->add_option("--size", o->size, "Canvas size WIDTHxHEIGHT in pixels")->required();
    cmd->add_option("--fill", o->fill, "Fill colour (CSS syntax)")->capture_default_str();
    cmd->add_option("--fill-rule", o->rule, "nonzero or evenodd")
        ->check(CLI::IsMember({"nonzero", "evenodd"}))
        ->capture_default_str();
    cmd->add_option("--background", o->background, "Background colour (CSS syntax)")->capture_default_str();
    cmd->add_option("--transform", o->transform,
                    "Affine transform \"a b c d e f\" (x' = a x + c y + e, y' = b x + d y + f)");
    cmd->add_option("--tolerance", o->tolerance, "Flattening tolerance in pixels")
        ->check(CLI::Range(1e-4, 10.0))
        ->capture_default_str();
    add_stroke_options(cmd, *o);
    cmd->add_flag("--no-exact-overlaps", o->no_exact, "Plain accumulation where edges overlap (faster, less exact)");
    cmd->callback([o] { run_path(*o); });
}

}  // namespace casteljau::cli
