// `casteljau svg`: render an SVG file to PNG.
#include <cmath>
#include <iostream>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

void register_svg(CLI::App& app) {
    struct Opts {
        std::string input, output, background = "transparent", resources;
        double zoom = 1;
        int width = 0, height = 0;
        double tolerance = kDefaultTolerance;
        bool quiet = false;
        SvgOptions svg;
        bool skip_system_fonts = false;
    };
    auto o = std::make_shared<Opts>();
    CLI::App* cmd = app.add_subcommand("svg", "Render an SVG file to PNG");
    cmd->add_option("INPUT", o->input, "SVG file (- for standard input)")->required();
    cmd->add_option("-o,--output", o->output, "Output PNG file")->required();
    auto* zoom = cmd->add_option("-z,--zoom,--scale", o->zoom, "Zoom factor applied to the document size")
                     ->check(CLI::Range(1e-3, 1e3))
                     ->capture_default_str();
    auto* width =
        cmd->add_option("-w,--width", o->width, "Output width in pixels (the height follows the aspect ratio)")
            ->check(CLI::Range(1, limits::kMaxCanvasDimension))
            ->excludes(zoom);
    cmd->add_option("--height", o->height,
                    "Output height in pixels (the width follows the aspect ratio unless -w is given)")
        ->check(CLI::Range(1, limits::kMaxCanvasDimension))
        ->excludes(zoom);
    (void)width;
    cmd->add_option("-b,--background", o->background, "Background colour (CSS syntax)")->capture_default_str();
    cmd->add_option("--tolerance", o->tolerance, "Flattening tolerance in pixels")
        ->check(CLI::Range(1e-4, 10.0))
        ->capture_default_str();
    cmd->add_option(
        "--resources", o->resources,
        "Folder that <image> files may be read from (default: the input's own folder; nothing for standard input)");
    cmd->add_option("--font-dir", o->svg.font_dirs,
                    "Folder of fonts for text (repeatable); the system's fonts are used too");
    cmd->add_option("--font-file", o->svg.font_files, "A font file for text (repeatable)");
    cmd->add_flag("--no-system-fonts,--skip-system-fonts", o->skip_system_fonts,
                  "Do not use the system's fonts (fontconfig) for text: neither by family name nor for characters the "
                  "other fonts lack (which otherwise come from them as in the text command), so the output depends on "
                  "--font-dir and --font-file alone");
    cmd->add_option("--font-family", o->svg.font_family, "Default font family")->capture_default_str();
    cmd->add_option("--serif-family", o->svg.serif_family, "Font family for 'serif'")->capture_default_str();
    cmd->add_option("--sans-serif-family", o->svg.sans_serif_family, "Font family for 'sans-serif'")
        ->capture_default_str();
    cmd->add_option("--cursive-family", o->svg.cursive_family, "Font family for 'cursive'")->capture_default_str();
    cmd->add_option("--fantasy-family", o->svg.fantasy_family, "Font family for 'fantasy'")->capture_default_str();
    cmd->add_option("--monospace-family", o->svg.monospace_family, "Font family for 'monospace'")
        ->capture_default_str();
    cmd->add_flag("-q,--quiet", o->quiet, "Do not print warnings about unsupported SVG features");
    cmd->callback([o] {
        const Color bg = parse_color_option("--background", o->background);
        // A file resolves relative <image> hrefs against its folder; standard input has none.
        SvgOptions so = o->svg;
        so.system_fonts = !o->skip_system_fonts;
        so.system_fallback = !o->skip_system_fonts;
        so.resource_root = o->resources;
        // The font folders and files must exist whether or not the document has text; the font
        // database itself is built by the SVG reader when the first text needs it (scanning the
        // system fonts costs more than drawing an icon), once for the document and its images.
        FontDatabaseOptions fo;
        fo.font_dirs = so.font_dirs;
        fo.font_files = so.font_files;
        check_font_sources(fo);
        const SvgDocument doc =
            o->input == "-" ? SvgDocument::parse(read_text_input(o->input), so) : SvgDocument::load(o->input, so);
        if (!o->quiet)
            for (const std::string& w : doc.warnings()) std::cerr << "casteljau: warning: " << w << "\n";
        // Output size as resvg and rsvg-convert choose it (svg.hpp): from the rounded intrinsic
        // size; the document is then scaled to fill the output exactly.
        std::pair<int, int> size;
        if (o->width > 0 && o->height > 0)
            size = {o->width, o->height};
        else if (o->width > 0)
            size = doc.output_size_for_width(o->width);
        else if (o->height > 0)
            size = doc.output_size_for_height(o->height);
        else
            size = doc.output_size_for_zoom(o->zoom);
        check_canvas_size(size.first, size.second);
        Pixmap pm(size.first, size.second);
        pm.fill(bg);
        Canvas canvas(pm);
        canvas.fill_options().tolerance = o->tolerance;
        doc.render(canvas, Affine::scale(size.first / doc.intrinsic_width(), size.second / doc.intrinsic_height()));
        write_png(pm, o->output);
    });
}

}  // namespace casteljau::cli
