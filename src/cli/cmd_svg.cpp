// `casteljau svg`: render an SVG file to PNG.
#include <cmath>
#include <iostream>

#include "casteljau/error.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

void register_svg(CLI::App& app) {
    struct Opts {
        std::string input, output, background = "transparent";
        double scale = 1;
        int width = 0;
        double tolerance = kDefaultTolerance;
        bool quiet = false;
    };
    auto o = std::make_shared<Opts>();
    CLI::App* cmd = app.add_subcommand("svg", "Render an SVG file to PNG");
    cmd->add_option("INPUT", o->input, "SVG file (- for standard input)")->required();
    cmd->add_option("-o,--output", o->output, "Output PNG file")->required();
    auto* scale = cmd->add_option("--scale", o->scale, "Scale factor applied to the document size")
                      ->check(CLI::Range(1e-3, 1e3))
                      ->capture_default_str();
    cmd->add_option("--width", o->width, "Output width in pixels (height follows the aspect ratio)")
        ->check(CLI::Range(1, limits::kMaxCanvasDimension))
        ->excludes(scale);
    cmd->add_option("--background", o->background, "Background colour (CSS syntax)")->capture_default_str();
    cmd->add_option("--tolerance", o->tolerance, "Flattening tolerance in pixels")
        ->check(CLI::Range(1e-4, 10.0))
        ->capture_default_str();
    cmd->add_flag("-q,--quiet", o->quiet, "Do not print warnings about unsupported SVG features");
    cmd->callback([o] {
        const Color bg = parse_color_option("--background", o->background);
        const std::string text = read_text_input(o->input);
        const SvgDocument doc = SvgDocument::parse(text);
        if (!o->quiet)
            for (const std::string& w : doc.warnings()) std::cerr << "casteljau: warning: " << w << "\n";
        double s = o->scale;
        if (o->width > 0) s = static_cast<double>(o->width) / doc.width();
        const double W = o->width > 0 ? o->width : std::ceil(doc.width() * s);
        const double H = std::ceil(doc.height() * s);
        check_canvas_size(W, H);
        Pixmap pm(static_cast<int>(W), static_cast<int>(H));
        pm.fill(bg);
        Canvas canvas(pm);
        canvas.fill_options().tolerance = o->tolerance;
        doc.render(canvas, Affine::scale(s));
        write_png(pm, o->output);
    });
}

}  // namespace casteljau::cli
