// bench/png_encode.cpp: PNG encoding time and size for each zlib level and row filter, with and
// without the smallest-colour-type reduction, on pictures casteljau renders.
//
// Inputs: pictures made in the process (a 300-character line of DejaVu Sans at 48 px, black on
// white and red on transparent) and any PNG files named on the command line (for instance the
// demo's out/*.png). Each configuration encodes every picture; the time is the best of --runs
// rounds (thread CPU time, timer.hpp), the size the total bytes. Every encoding is decoded again
// and compared with the pixmap, so no configuration is timed on a broken file.
//
// Usage: png_encode [--quick] [--runs R] [FILE.png ...]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/font.hpp"
#include "casteljau/png.hpp"
#include "casteljau/text.hpp"
#include "timer.hpp"

using namespace casteljau;

namespace {

Pixmap text_line(Color ink, Color background) {
    const Font font = Font::load(CASTELJAU_BENCH_FONT);
    std::string text;
    while (text.size() < 300) text += "The quick brown fox jumps over the lazy dog. ";
    text.resize(300);
    TextStyle style;
    style.size = 48;
    const TextLayout layout = layout_text(text, font, style);
    const Rect b = layout.bounds();
    Pixmap pm(static_cast<int>(b.x1 - b.x0) + 20, static_cast<int>(b.y1 - b.y0) + 20);
    pm.fill(background);
    Canvas canvas(pm);
    draw_text(canvas, layout, {10 - b.x0, 10 - b.y0}, Paint::solid(ink));
    return pm;
}

const char* filter_name(PngFilter f) {
    switch (f) {
        case PngFilter::Auto: return "auto";
        case PngFilter::None: return "none";
        case PngFilter::Sub: return "sub";
        case PngFilter::Up: return "up";
        case PngFilter::Average: return "average";
        case PngFilter::Paeth: return "paeth";
        case PngFilter::Adaptive: return "adaptive";
    }
    return "?";
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 5;
    bool quick = false;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0)
            quick = true;
        else if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else
            files.emplace_back(argv[i]);
    }
    if (quick) runs = 1;
    struct Picture {
        std::string name;
        Pixmap pixmap;
    };
    std::vector<Picture> pictures;
    pictures.push_back({"text black on white", text_line(Color::black(), Color::white())});
    pictures.push_back({"text red on transparent", text_line(Color::rgba(200, 30, 30), Color::transparent())});
    for (const std::string& f : files) pictures.push_back({f, read_png(f)});
    long long pixels = 0;
    for (const Picture& p : pictures) pixels += static_cast<long long>(p.pixmap.width()) * p.pixmap.height();
    std::printf("%zu pictures, %.2f Mpixels; best of %d rounds, thread CPU time\n\n", pictures.size(), pixels / 1e6,
                runs);

    struct Config {
        int level;
        PngFilter filter;
        bool reduce;
    };
    std::vector<Config> configs;
    configs.push_back({6, PngFilter::Adaptive, false});  // libpng's defaults, RGBA: the reference row
    for (bool reduce : {true, false})
        for (int level : {1, 2, 3, 4, 6, 9})
            for (PngFilter f : {PngFilter::Auto, PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Paeth,
                                PngFilter::Adaptive}) {
                if (quick && level != 4) continue;
                configs.push_back({level, f, reduce});
            }
    const PngEncodeOptions defaults;
    std::printf("%-6s %-9s %-7s %12s %10s %9s %9s\n", "level", "filter", "reduce", "bytes", "ms", "size/ref",
                "time/ref");
    double ref_ms = 0, ref_bytes = 0;
    for (const Config& c : configs) {
        PngEncodeOptions o;
        o.compression_level = c.level;
        o.filter = c.filter;
        o.smallest_colour_type = c.reduce;
        std::size_t bytes = 0;
        for (const Picture& p : pictures) {
            const auto png = encode_png(p.pixmap, o);
            bytes += png.size();
            const Pixmap back = decode_png(png);
            if (std::memcmp(back.data(), p.pixmap.data(),
                            p.pixmap.stride() * static_cast<std::size_t>(p.pixmap.height())) != 0) {
                std::fprintf(stderr, "png_encode: %s does not round-trip with level %d filter %s\n", p.name.c_str(),
                             c.level, filter_name(c.filter));
                return 1;
            }
        }
        double best = 1e30;
        for (int r = 0; r < runs; ++r) {
            const double t0 = bench::thread_cpu_seconds();
            for (const Picture& p : pictures) (void)encode_png(p.pixmap, o);
            best = std::min(best, bench::thread_cpu_seconds() - t0);
        }
        const double ms = best * 1e3;
        if (ref_ms == 0) {
            ref_ms = ms;
            ref_bytes = static_cast<double>(bytes);
        }
        const bool is_default = c.level == defaults.compression_level && c.filter == defaults.filter &&
                                c.reduce == defaults.smallest_colour_type;
        std::printf("%-6d %-9s %-7s %12zu %10.2f %9.3f %9.3f%s\n", c.level, filter_name(c.filter),
                    c.reduce ? "yes" : "no", bytes, ms, bytes / ref_bytes, ms / ref_ms,
                    is_default ? "   <- default" : "");
    }
    return 0;
}
