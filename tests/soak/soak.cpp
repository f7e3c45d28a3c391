// Soak test: one process renders many items of one kind and checks that memory stays flat and
// that its last item equals what a fresh process makes of that item alone.
//   casteljau_soak svg N     N generated SVG documents (shapes, gradients, groups with opacity,
//                            clip paths, use, dashes), each parsed and rendered at 96 x 96
//   casteljau_soak text N    N generated text lines (Latin, Arabic, mixed) laid out and drawn
//   casteljau_soak tiles Z   the world (tests/data) as a tile pyramid z0..Z, tiles kept in memory
// Options: --only I renders item I alone (for the fresh-process comparison); --out FILE writes the
// last item's PNG. The resident set size (VmRSS) is read before the first item, at the middle
// and after the last; the run fails (exit 1) when it grew from the middle to the end by more than
// 10% + 4 MiB, which a leak or an ever-growing cache would show. Run under LeakSanitizer (the
// sanitizer build) it fails on any leak instead: there AddressSanitizer's quarantine of freed
// memory makes the resident size grow with the churn, so the growth check is not made.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/font.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/text.hpp"
#include "casteljau/tiles.hpp"

using namespace casteljau;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

namespace {

long rss_kib() {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
    return 0;
}

std::string svg_document(int i) {
    std::mt19937 rng(static_cast<unsigned>(i) * 2654435761u);
    auto u = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    std::ostringstream s;
    s << "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' width='96' height='96'>"
      << "<defs><linearGradient id='g' x1='0' x2='1'><stop offset='0' stop-color='#" << std::hex << (rng() & 0xffffff)
      << "'/><stop offset='1' stop-color='#" << (rng() & 0xffffff) << std::dec
      << "' stop-opacity='0.5'/></linearGradient>"
      << "<clipPath id='c'><circle cx='48' cy='48' r='" << 20 + u(28) << "'/></clipPath>"
      << "<path id='p' d='M0 0 L" << 5 + u(20) << " 0 L0 " << 5 + u(20) << " Z'/></defs>";
    s << "<g opacity='0." << 3 + u(7) << "' clip-path='url(#c)'>";
    for (int k = 0, n = 3 + u(12); k < n; ++k) {
        switch (u(4)) {
            case 0:
                s << "<rect x='" << u(80) << "' y='" << u(80) << "' width='" << 1 + u(60) << "' height='" << 1 + u(60)
                  << "' fill='url(#g)'/>";
                break;
            case 1:
                s << "<circle cx='" << u(96) << "' cy='" << u(96) << "' r='" << 1 + u(40) << "' fill='none' stroke='#"
                  << std::hex << (rng() & 0xffffff) << std::dec << "' stroke-width='" << 1 + u(6)
                  << "' stroke-dasharray='" << 1 + u(9) << " " << 1 + u(5) << "'/>";
                break;
            case 2:
                s << "<use xlink:href='#p' x='" << u(90) << "' y='" << u(90) << "' transform='rotate(" << u(360)
                  << " 48 48)'/>";
                break;
            default:
                s << "<path d='M" << u(96) << " " << u(96) << " C" << u(96) << " " << u(96) << " " << u(96) << " "
                  << u(96) << " " << u(96) << " " << u(96) << " Z' fill-rule='evenodd' fill='#" << std::hex
                  << (rng() & 0xffffff) << std::dec << "'/>";
        }
    }
    s << "</g></svg>";
    return s.str();
}

std::string text_line(int i) {
    static const char* kWords[] = {"casteljau", "glyph", "Bézier", "curve", "مرحبا",
                                   "كتاب",      "ﬁnal",  "Ωmega",  "42",    "—"};
    std::mt19937 rng(static_cast<unsigned>(i) * 40503u + 7u);
    std::string s;
    for (int k = 0, n = 2 + static_cast<int>(rng() % 8); k < n; ++k) {
        if (k) s += ' ';
        s += kWords[rng() % (sizeof kWords / sizeof kWords[0])];
    }
    return s;
}

void usage() {
    std::fprintf(stderr, "usage: casteljau_soak svg|text|tiles N [--only I] [--out FILE]\n");
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) usage();
    const std::string kind = argv[1];
    const int n = std::atoi(argv[2]);
    int only = -1;
    std::string out;
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--only")
            only = std::atoi(argv[i + 1]);
        else if (a == "--out")
            out = argv[i + 1];
        else
            usage();
    }
    if (n < 1 || (kind != "svg" && kind != "text" && kind != "tiles")) usage();
    try {
        const std::string source = CASTELJAU_SOURCE_DIR;
        std::vector<std::uint8_t> last;
        long before = 0, middle = 0, after = 0;
        if (kind == "tiles") {
            // One pyramid z0..n, all tiles in one process; the last tile of the run is compared.
            const MapData data = read_map_file(source + "/tests/data/maps/countries-110m.json", "countries");
            MapStyle style;
            style.layers[0].fill_by = "name";
            style.layers[0].stroke = Color::rgba(50, 50, 50);
            style.layers[0].stroke_width = 0.8;
            TileOptions to;
            to.max_zoom = n;
            if (only >= 0) to.min_zoom = n;  // the fresh process renders only the last zoom
            to.metatile = 2;
            std::size_t count = 0, total = 0;
            for (int z = 0; z <= n; ++z) total += std::size_t(1) << (2 * z);
            int lz = -1, lx = -1, ly = -1;
            before = rss_kib();
            (void)render_tiles(data, style, to, [&](int z, int x, int y, const std::vector<std::uint8_t>& png) {
                if (++count == total / 2) middle = rss_kib();
                if (only < 0 || (z == n && x == only && y == only)) {
                    if (z > lz || (z == lz && (x > lx || (x == lx && y > ly)))) {
                        lz = z;
                        lx = x;
                        ly = y;
                        last = png;
                    }
                }
            });
            after = rss_kib();
            std::printf("soak tiles: %zu tiles, last z%d/%d/%d\n", count, lz, lx, ly);
        } else {
            const Font font = Font::load(source + "/fonts/DejaVuSans.ttf");
            const Font arabic = Font::load(source + "/fonts/NotoSansArabic-Regular.ttf");
            const Font* fonts[] = {&font, &arabic};
            GlyphCache cache;
            before = rss_kib();
            for (int i = only >= 0 ? only : 0; i < (only >= 0 ? only + 1 : n); ++i) {
                Pixmap pm(kind == "svg" ? 96 : 480, kind == "svg" ? 96 : 40);
                if (kind == "svg") {
                    pm = SvgDocument::parse(svg_document(i)).render();
                } else {
                    pm.fill(Color::white());
                    Canvas canvas(pm);
                    TextStyle st;
                    st.size = 18 + i % 7;
                    const TextLayout layout = layout_text(text_line(i), fonts, st);
                    draw_text(canvas, layout, Point{4, 4}, Paint::solid(Color::black()), &cache);
                }
                if (i == n / 2) middle = rss_kib();
                if (i == n - 1 || only >= 0) last = encode_png(pm);
            }
            after = rss_kib();
            std::printf("soak %s: %d items\n", kind.c_str(), only >= 0 ? 1 : n);
        }
        if (!out.empty()) write_file_atomic(out, last);
        if (only < 0) {
            std::printf("VmRSS: %ld KiB before, %ld KiB at the middle, %ld KiB after\n", before, middle, after);
            if (kAddressSanitizer) {
                // ASan keeps freed memory in its quarantine (256 MB by default) before reusing it,
                // so the resident size grows with the churn, not with what is still held; leaks are
                // LeakSanitizer's to find at exit. The flat-memory check runs in the normal build.
                std::printf("the growth check is left to the normal build (AddressSanitizer's quarantine)\n");
            } else if (after > middle + middle / 10 + 4096) {
                std::fprintf(stderr, "soak: memory grew from %ld KiB at the middle to %ld KiB at the end\n", middle,
                             after);
                return 1;
            }
        }
    } catch (const Error& e) {
        std::fprintf(stderr, "soak: %s\n", e.what());
        return 1;
    }
    return 0;
}
