// `casteljau svg`: render SVG files to PNG, one or many (into a folder, on several threads).
#include <atomic>
#include <filesystem>
#include <functional>
#include <iostream>
#include <mutex>
#include <set>
#include <thread>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

namespace {

namespace fs = std::filesystem;

struct SvgOpts {
    std::vector<std::string> inputs;
    std::string output, background = "transparent", resources;
    double zoom = 1;
    int width = 0, height = 0;
    double tolerance = kDefaultTolerance;
    bool quiet = false;
    SvgOptions svg;
    bool skip_system_fonts = false;
    int jobs = 1;
};

// Renders one document to one PNG file; warnings go to `warn`.
void render_file(const SvgOpts& o, const SvgOptions& so, Color bg, const std::string& input, const std::string& output,
                 const std::function<void(const std::string&)>& warn) {
    const SvgDocument doc =
        input == "-" ? SvgDocument::parse(read_text_input(input), so) : SvgDocument::load(input, so);
    if (!o.quiet)
        for (const std::string& w : doc.warnings()) warn(w);
    // Output size as resvg and rsvg-convert choose it (svg.hpp): from the rounded intrinsic
    // size; the document is then scaled to fill the output exactly.
    std::pair<int, int> size;
    if (o.width > 0 && o.height > 0)
        size = {o.width, o.height};
    else if (o.width > 0)
        size = doc.output_size_for_width(o.width);
    else if (o.height > 0)
        size = doc.output_size_for_height(o.height);
    else
        size = doc.output_size_for_zoom(o.zoom);
    check_canvas_size(size.first, size.second);
    Pixmap pm(size.first, size.second);
    pm.fill(bg);
    Canvas canvas(pm);
    canvas.fill_options().tolerance = o.tolerance;
    doc.render(canvas, Affine::scale(size.first / doc.intrinsic_width(), size.second / doc.intrinsic_height()));
    write_png(pm, output);
}

// Several inputs, or an existing folder as the output: each input's PNG goes into that folder
// under the input's name with the extension .png. Checked before anything is drawn: no standard
// input, no two inputs with one output name, the folder created when missing.
std::vector<std::string> folder_outputs(const SvgOpts& o) {
    if (fs::exists(o.output) && !fs::is_directory(o.output))
        throw UsageError("-o: with several inputs the output must be a folder, and '" + o.output + "' is a file");
    std::vector<std::string> outs;
    std::set<std::string> seen;
    for (const std::string& in : o.inputs) {
        if (in == "-") throw UsageError("INPUT: standard input (-) cannot be one of several inputs");
        const std::string name = fs::path(in).stem().string() + ".png";
        if (!seen.insert(name).second)
            throw UsageError("INPUT: two inputs would both be written to '" + name + "' in " + o.output);
        outs.push_back((fs::path(o.output) / name).string());
    }
    std::error_code ec;
    fs::create_directories(o.output, ec);
    if (ec) throw Error(ErrorKind::Io, "cannot create the output folder '" + o.output + "': " + ec.message());
    return outs;
}

// Several inputs into a folder, `jobs` at once. Every file is tried; one that fails gets its own
// error line and no output, and the command then exits as the first failure would have alone.
class FolderRun {
public:
    FolderRun(const SvgOpts& o, const SvgOptions& so, Color bg) : o_(o), so_(so), bg_(bg), outs_(folder_outputs(o)) {}

    void run() {
        const std::size_t threads = std::min<std::size_t>(static_cast<std::size_t>(o_.jobs), o_.inputs.size());
        std::vector<std::thread> pool;
        for (std::size_t t = 1; t < threads; ++t) pool.emplace_back([this] { work(); });
        work();
        for (std::thread& t : pool) t.join();
        if (failed_ > 0)
            throw Error(first_kind_, std::to_string(failed_) + " of " + std::to_string(o_.inputs.size()) +
                                         " files were not rendered (their errors are above)");
    }

private:
    void work() {
        for (std::size_t i; (i = next_++) < o_.inputs.size();) {
            const std::string& in = o_.inputs[i];
            try {
                render_file(o_, so_, bg_, in, outs_[i],
                            [&](const std::string& w) { say("casteljau: warning: " + in + ": " + w); });
            } catch (const Error& e) { failure(in, e.what(), e.kind()); } catch (const std::bad_alloc&) {
                failure(in, "out of memory", ErrorKind::Limit);
            } catch (const std::exception& e) {  // nothing may leave a worker thread
                failure(in, e.what(), ErrorKind::InvalidData);
            }
        }
    }

    void say(const std::string& line) {
        const std::lock_guard<std::mutex> g(lock_);
        std::cerr << line << "\n";
    }

    // The line starts with the file's name, so a message that ends by naming it (the library adds
    // " in PATH" where a caller may not know which file failed) loses that ending.
    void failure(const std::string& in, std::string what, ErrorKind kind) {
        const std::string named = " in " + in;
        if (what.size() > named.size() && what.ends_with(named)) what.resize(what.size() - named.size());
        const std::lock_guard<std::mutex> g(lock_);
        std::cerr << "casteljau: error: " << in << ": " << what << "\n";
        if (failed_++ == 0) first_kind_ = kind;
    }

    const SvgOpts& o_;
    const SvgOptions& so_;
    const Color bg_;
    const std::vector<std::string> outs_;
    std::mutex lock_;
    std::atomic<std::size_t> next_{0};
    ErrorKind first_kind_ = ErrorKind::InvalidData;  // the first failure's, once failed_ > 0
    std::size_t failed_ = 0;
};

void run_svg(const SvgOpts& o) {
    const Color bg = parse_color_option("--background", o.background);
    // A file resolves relative <image> hrefs against its folder; standard input has none.
    SvgOptions so = o.svg;
    so.system_fonts = !o.skip_system_fonts;
    so.system_fallback = !o.skip_system_fonts;
    so.resource_root = o.resources;
    // The font folders and files must exist whether or not the document has text; the font
    // database itself is built by the SVG reader when the first text needs it (scanning the system
    // fonts costs more than drawing an icon), once for the document and its images.
    FontDatabaseOptions fo;
    fo.font_dirs = so.font_dirs;
    fo.font_files = so.font_files;
    check_font_sources(fo);
    if (o.inputs.size() > 1 || fs::is_directory(o.output)) return FolderRun(o, so, bg).run();
    render_file(o, so, bg, o.inputs[0], o.output,
                [](const std::string& w) { std::cerr << "casteljau: warning: " << w << "\n"; });
}

// The output's size: zoom, width, height, dpi.
void add_size_options(CLI::App* cmd, SvgOpts& o) {
    auto* zoom = cmd->add_option("-z,--zoom,--scale", o.zoom, "Zoom factor applied to the document size")
                     ->check(CLI::Range(1e-3, 1e3))
                     ->capture_default_str();
    cmd->add_option("-w,--width", o.width, "Output width in pixels (the height follows the aspect ratio)")
        ->check(CLI::Range(1, limits::kMaxCanvasDimension))
        ->excludes(zoom);
    cmd->add_option("--height", o.height,
                    "Output height in pixels (the width follows the aspect ratio unless -w is given)")
        ->check(CLI::Range(1, limits::kMaxCanvasDimension))
        ->excludes(zoom);
    cmd->add_option("-d,--dpi", o.svg.dpi,
                    "Pixels per inch of the physical units (in, cm, mm, pt, pc), the document's width and height "
                    "included: it decides the document's size in pixels, which --zoom, --width and --height then scale")
        ->check(CLI::Range(SvgOptions::kMinDpi, SvgOptions::kMaxDpi))
        ->capture_default_str();
}

// What is drawn and how: one element, the background, the tolerance, where images come from.
void add_drawing_options(CLI::App* cmd, SvgOpts& o) {
    cmd->add_option("-i,--export-id", o.svg.export_id,
                    "Draw only the element with this id (#ID works too) in its place in the document: its ancestors' "
                    "transforms, inherited styles and group effects apply, what it references (gradients, clips, use "
                    "targets) still resolves, and the output keeps the document's size (rsvg-convert 2.54 instead "
                    "crops the output to the element). An id no element has is an error");
    cmd->add_option("-b,--background", o.background, "Background colour (CSS syntax)")->capture_default_str();
    cmd->add_option("--tolerance", o.tolerance, "Flattening tolerance in pixels")
        ->check(CLI::Range(1e-4, 10.0))
        ->capture_default_str();
    cmd->add_option(
        "--resources", o.resources,
        "Folder that <image> files may be read from (default: the input's own folder; nothing for standard input)");
}

// Fonts for text: folders, files, the system's fonts, the generic families.
void add_font_options(CLI::App* cmd, SvgOpts& o) {
    cmd->add_option("--font-dir", o.svg.font_dirs,
                    "Folder of fonts for text (repeatable); the system's fonts are used too");
    cmd->add_option("--font-file", o.svg.font_files, "A font file for text (repeatable)");
    cmd->add_flag("--no-system-fonts,--skip-system-fonts", o.skip_system_fonts,
                  "Do not use the system's fonts (fontconfig) for text: neither by family name nor for characters the "
                  "other fonts lack (which otherwise come from them as in the text command), so the output depends on "
                  "--font-dir and --font-file alone");
    cmd->add_option("--font-family", o.svg.font_family, "Default font family")->capture_default_str();
    cmd->add_option("--serif-family", o.svg.serif_family, "Font family for 'serif'")->capture_default_str();
    cmd->add_option("--sans-serif-family", o.svg.sans_serif_family, "Font family for 'sans-serif'")
        ->capture_default_str();
    cmd->add_option("--cursive-family", o.svg.cursive_family, "Font family for 'cursive'")->capture_default_str();
    cmd->add_option("--fantasy-family", o.svg.fantasy_family, "Font family for 'fantasy'")->capture_default_str();
    cmd->add_option("--monospace-family", o.svg.monospace_family, "Font family for 'monospace'")->capture_default_str();
}

}  // namespace

void register_svg(CLI::App& app) {
    auto o = std::make_shared<SvgOpts>();
    CLI::App* cmd = app.add_subcommand("svg", "Render SVG files to PNG");
    cmd->add_option("INPUT", o->inputs,
                    "SVG files (- for standard input); with several, -o names a folder that receives each as "
                    "NAME.png")
        ->required()
        ->expected(1, -1);
    cmd->add_option("-o,--output", o->output,
                    "Output PNG file, or a folder (several inputs, or an existing folder): NAME.png for each input")
        ->required();
    cmd->add_option("-j,--jobs", o->jobs, "Files rendered at once, on that many threads (several inputs)")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    add_size_options(cmd, *o);
    add_drawing_options(cmd, *o);
    add_font_options(cmd, *o);
    cmd->add_flag("-q,--quiet", o->quiet, "Do not print warnings about unsupported SVG features");
    cmd->callback([o] { run_svg(*o); });
}

}  // namespace casteljau::cli
