// libFuzzer target: the C API (include/casteljau/casteljau.h and the SVG, map and text headers it
// includes) driven by random call sequences.
// The input is a program: each byte picks a call, the bytes after it its arguments, read as
// doubles from a table of awkward values (0, -0, NaN, +/-inf, 1e300, 1e-300, 32769, ...) or as raw
// 8-byte doubles, texts (SVG, GeoJSON, style JSON, UTF-8, projections, features) of up to 4 KiB,
// and handles from small pools of live objects (NULL when the pool is empty).
// Image sizes above 256 are kept only when they exceed the canvas limit (so the limit error is
// exercised without gigabyte allocations); new images from SVG documents and text layouts are made
// only when their size is at most 512 x 512, maps at most 128 x 128, and tile pyramids are cut to
// zoom 0-1 with small metatiles (invalid values are passed to the setters first, then a bounded
// valid one). SVG documents never use the system's fonts (scanning them would dominate the run).
// One call sets the process-wide limits from random bytes and a random struct size; they are reset
// after each input. Every object is destroyed at the end, so the leak checker sees anything the API
// forgets.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/casteljau.h"
#include "casteljau/casteljau_map.h"
#include "casteljau/casteljau_svg.h"
#include "casteljau/casteljau_text.h"

namespace {

class Reader {
public:
    Reader(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
    bool done() const { return i_ >= n_; }
    std::uint8_t byte() { return i_ < n_ ? d_[i_++] : 0; }
    double number() {
        static const double kTable[] = {0.0,
                                        -0.0,
                                        1.0,
                                        -1.0,
                                        0.5,
                                        2.0,
                                        10.0,
                                        100.0,
                                        255.0,
                                        32769.0,
                                        1e6,
                                        -1e6,
                                        1e300,
                                        -1e300,
                                        1e-300,
                                        std::numeric_limits<double>::quiet_NaN(),
                                        std::numeric_limits<double>::infinity(),
                                        -std::numeric_limits<double>::infinity(),
                                        3.7,
                                        0.25,
                                        64.0,
                                        -5.5,
                                        1e15,
                                        4e15};
        const std::uint8_t b = byte();
        if (b < 200) return kTable[b % (sizeof kTable / sizeof kTable[0])];
        double v = 0;
        std::uint8_t raw[8] = {};
        for (std::uint8_t& r : raw) r = byte();
        std::memcpy(&v, raw, 8);
        return v;
    }
    int small_int() { return static_cast<int>(byte()) - 16; }
    std::string text() {
        const std::size_t len = byte();
        std::string s;
        while (s.size() < len && !done()) s.push_back(static_cast<char>(byte()));
        return s;
    }
    // A text of up to 4095 bytes (a 12-bit length).
    std::string long_text() {
        const std::size_t len = ((static_cast<std::size_t>(byte()) << 8) | byte()) & 0xFFF;
        std::string s;
        while (s.size() < len && !done()) s.push_back(static_cast<char>(byte()));
        return s;
    }
    // One of `n` fixed texts, or (past them) a random one; nullptr for one index.
    const char* choose(const char* const* table, std::size_t n, std::string& scratch) {
        const std::size_t i = byte() % (n + 2);
        if (i < n) return table[i];
        if (i == n) return nullptr;
        scratch = text();
        return scratch.c_str();
    }

private:
    const std::uint8_t* d_;
    std::size_t n_, i_ = 0;
};

// An enum value from any int, as a C caller may pass it (casteljau.h gives the enumerations int as
// their underlying type in C++, so every int is a value of them).
template <class E>
E as_enum(int v) {
    return static_cast<E>(v);
}

template <class T>
T* pick(std::vector<T*>& pool, Reader& r) {
    if (pool.empty()) return nullptr;
    return pool[r.byte() % pool.size()];
}

casteljau_color color(Reader& r) { return {r.byte(), r.byte(), r.byte(), r.byte()}; }

casteljau_matrix matrix(Reader& r) { return {r.number(), r.number(), r.number(), r.number(), r.number(), r.number()}; }

int image_side(Reader& r) {
    const double v = r.number();
    if (!(v == v)) return 0;
    if (v > 32768) return 40000;  // past the limit: an error, no allocation
    if (v > 256) return 256;
    return static_cast<int>(std::max(-2.0, v));
}

// A folder for the tile pyramids of this process, made once, reused by every input and removed
// when the process exits.
const std::string& tile_folder() {
    struct Folder {
        std::string path;
        Folder() {
            char name[] = "/tmp/casteljau-fuzz-capi.XXXXXX";
            if (const char* made = mkdtemp(name)) path = made;
        }
        ~Folder() {
            std::error_code ec;
            if (!path.empty()) std::filesystem::remove_all(path, ec);
        }
    };
    static const Folder folder;
    return folder.path;
}

// Called after each metatile; asks to stop once `*user` calls have been made (0: never).
int stop_after(std::uint64_t, std::uint64_t, void* user) {
    int& left = *static_cast<int*>(user);
    return left > 0 && --left == 0;
}

// The SVG, map, tile and text calls: their handles, and one step of the program per call.
class Documents {
public:
    Documents(std::vector<casteljau_canvas*>& canvases, std::vector<casteljau_paint*>& paints,
              std::vector<casteljau_image*>& images)
        : canvases_(canvases), paints_(paints), images_(images) {}
    Documents(const Documents&) = delete;
    Documents& operator=(const Documents&) = delete;
    ~Documents() {
        for (casteljau_svg* d : svgs_) casteljau_svg_destroy(d);
        for (casteljau_svg_options* o : svg_options_) casteljau_svg_options_destroy(o);
        for (casteljau_map* m : maps_) casteljau_map_destroy(m);
        for (casteljau_map_style* st : styles_) casteljau_map_style_destroy(st);
        for (casteljau_map_options* o : map_options_) casteljau_map_options_destroy(o);
        for (casteljau_tile_options* o : tile_options_) casteljau_tile_options_destroy(o);
        for (casteljau_text_layout* l : layouts_) casteljau_text_layout_destroy(l);
        for (casteljau_text_style* st : text_styles_) casteljau_text_style_destroy(st);
        for (casteljau_font* f : fonts_) casteljau_font_destroy(f);
    }

    static constexpr int kSteps = 19;
    casteljau_status step(int op, Reader& r) {
        switch (op) {
            case 0: return svg_options(r);
            case 1: return svg_read(r);
            case 2: return svg_query(r);
            case 3: return svg_draw(r);
            case 4: return map_read(r);
            case 5: return map_style(r);
            case 6: return map_options(r);
            case 7: return map_draw(r);
            case 8: return tiles(r);
            case 9: return font(r);
            case 10: return text_style(r);
            case 11: return text_layout(r);
            case 12: return text_query(r);
            case 13: return text_draw(r);
            case 14: return core(r);
            case 15: return svg_read(r);
            case 16: return map_read(r);
            case 17: return text_layout(r);
            default: return map_draw(r);
        }
    }

private:
    template <class T>
    static void keep(std::vector<T*>& pool, T* p, void (*destroy)(T*)) {
        if (!p) return;
        if (pool.size() < 4)
            pool.push_back(p);
        else
            destroy(p);
    }

    casteljau_svg_options* options_for_svg(Reader& r) {
        casteljau_svg_options* o = pick(svg_options_, r);
        if (o) return o;
        o = casteljau_svg_options_create();
        casteljau_svg_options_set_system_fonts(o, 0);
        svg_options_.push_back(o);
        return o;
    }

    casteljau_status svg_options(Reader& r) {
        static const char* const kFolders[] = {CASTELJAU_FONT_DIR, CASTELJAU_SOURCE_DIR "/examples/data",
                                               "/nonexistent"};
        static const char* const kFiles[] = {CASTELJAU_FONT_DIR "/DejaVuSans.ttf",
                                             CASTELJAU_FONT_DIR "/LinLibertine_R.otf", "/nonexistent.ttf"};
        static const char* const kFamilies[] = {"DejaVu Sans", "Linux Libertine", "serif", ""};
        static const char* const kIds[] = {"#a", "badge", "", "nope"};
        std::string scratch;
        casteljau_svg_options* o = options_for_svg(r);
        switch (r.byte() % 7) {
            case 0: return casteljau_svg_options_set_resources(o, r.choose(kFolders, 3, scratch));
            case 1: return casteljau_svg_options_add_font_dir(o, r.choose(kFolders, 3, scratch));
            case 2: return casteljau_svg_options_add_font_file(o, r.choose(kFiles, 3, scratch));
            case 3:
                return casteljau_svg_options_set_font_family(o, as_enum<casteljau_font_generic>(r.small_int()),
                                                             r.choose(kFamilies, 4, scratch));
            case 4: return casteljau_svg_options_set_dpi(o, r.number());
            case 5: return casteljau_svg_options_set_export_id(o, r.choose(kIds, 4, scratch));
            default: return casteljau_svg_options_set_system_fonts(nullptr, 0);
        }
    }

    casteljau_status svg_read(Reader& r) {
        static const char* const kFiles[] = {CASTELJAU_SOURCE_DIR "/examples/data/badge.svg",
                                             CASTELJAU_SOURCE_DIR "/examples/data/shapes.svg", "/nonexistent.svg"};
        casteljau_svg_options* o = options_for_svg(r);
        casteljau_svg* d = nullptr;
        casteljau_status s;
        if (r.byte() & 1) {
            std::string scratch;
            s = casteljau_svg_load(r.choose(kFiles, 3, scratch), o, &d);
        } else {
            const std::string text = r.long_text();
            s = casteljau_svg_parse(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), o, &d);
        }
        if ((s == CASTELJAU_OK) != (d != nullptr)) __builtin_trap();
        keep(svgs_, d, casteljau_svg_destroy);
        return s;
    }

    casteljau_status svg_query(Reader& r) {
        casteljau_svg* d = pick(svgs_, r);
        double w = 0, h = 0;
        int ow = 0, oh = 0;
        casteljau_status s = casteljau_svg_intrinsic_size(d, &w, &h);
        if (s == CASTELJAU_OK && !(w > 0 && h > 0)) __builtin_trap();
        const char* warning = casteljau_svg_warning(d, r.byte() % 4);
        if (warning && std::strlen(warning) > 100000) __builtin_trap();
        (void)casteljau_svg_warning_count(d);
        const int width = r.small_int() * 8, height = r.small_int() * 8;
        s = casteljau_svg_output_size(d, width, height, r.number(), &ow, &oh);
        if (s == CASTELJAU_OK && (ow < 1 || oh < 1)) __builtin_trap();
        return s;
    }

    casteljau_status svg_draw(Reader& r) {
        casteljau_svg* d = pick(svgs_, r);
        if (r.byte() & 1) return casteljau_svg_render(d, pick(canvases_, r));
        const int width = r.small_int() * 4, height = r.small_int() * 4;
        const double zoom = r.number();
        int ow = 0, oh = 0;
        const casteljau_status s = casteljau_svg_output_size(d, width, height, zoom, &ow, &oh);
        if (s != CASTELJAU_OK || std::int64_t{ow} * oh > 512 * 512) return s;
        casteljau_image* im = nullptr;
        const casteljau_status drawn = casteljau_svg_render_image(d, width, height, zoom, color(r), &im);
        if (drawn == CASTELJAU_OK && (casteljau_image_width(im) != ow || casteljau_image_height(im) != oh))
            __builtin_trap();
        keep(images_, im, casteljau_image_destroy);
        return drawn;
    }

    casteljau_status map_read(Reader& r) {
        static const char* const kFiles[] = {CASTELJAU_SOURCE_DIR "/tests/data/maps/countries-110m.json",
                                             CASTELJAU_SOURCE_DIR "/tests/data/maps/sample.geojson",
                                             CASTELJAU_SOURCE_DIR "/fuzz/corpus/map_data/lines.geojsonl",
                                             "/nonexistent.topojson"};
        static const char* const kLayers[] = {"countries", "land", ""};
        std::string scratch, layer_scratch;
        casteljau_map* m = nullptr;
        casteljau_status s;
        if (r.byte() & 1) {
            const char* path = r.choose(kFiles, 4, scratch);
            s = casteljau_map_load(path, r.choose(kLayers, 3, layer_scratch), &m);
        } else {
            const std::string text = r.long_text();
            s = casteljau_map_parse(text.data(), text.size(), r.choose(kLayers, 3, layer_scratch), &m);
        }
        if ((s == CASTELJAU_OK) != (m != nullptr)) __builtin_trap();
        keep(maps_, m, casteljau_map_destroy);
        return s;
    }

    casteljau_status map_style(Reader& r) {
        casteljau_map_style* st = pick(styles_, r);
        const casteljau_color c = color(r), c2 = color(r);
        switch (r.byte() % 13) {
            case 0: keep(styles_, casteljau_map_style_create(), casteljau_map_style_destroy); return CASTELJAU_OK;
            case 1: {
                casteljau_map_style* parsed = nullptr;
                const casteljau_status s = casteljau_map_style_parse(r.long_text().c_str(), &parsed);
                keep(styles_, parsed, casteljau_map_style_destroy);
                return s;
            }
            case 2: return casteljau_map_style_set_fill(st, (r.byte() & 1) ? &c : nullptr);
            case 3: return casteljau_map_style_set_stroke(st, (r.byte() & 1) ? &c : nullptr);
            case 4: return casteljau_map_style_set_stroke_width(st, r.number());
            case 5: return casteljau_map_style_set_opacity(st, r.number());
            case 6: {
                static const char* const kProperties[] = {"name", "kind", "v"};
                std::string scratch;
                return casteljau_map_style_set_fill_by(st, r.choose(kProperties, 3, scratch));
            }
            case 7: {
                const double lo = r.number(), hi = r.number();
                return casteljau_map_style_set_ramp(st, lo, c, hi, c2);
            }
            case 8: return casteljau_map_style_set_background(st, c);
            case 9: return casteljau_map_style_set_line_join(st, as_enum<casteljau_line_join>(r.small_int()));
            case 10: return casteljau_map_style_set_line_cap(st, as_enum<casteljau_line_cap>(r.small_int()));
            case 11: return casteljau_map_style_set_point_radius(st, r.number());
            default: {
                casteljau_map_style* loaded = nullptr;
                const casteljau_status s = casteljau_map_style_load("/nonexistent-style.json", &loaded);
                keep(styles_, loaded, casteljau_map_style_destroy);
                return s;
            }
        }
    }

    // A projection: built in (NULL and "" are errors), or one time in 16 through PROJ, whose
    // context costs about half a second under ASan when it is made and again for each thread.
    static const char* projection(Reader& r, std::string& scratch) {
        static const char* const kBuiltIn[] = {"equirectangular", "mercator", "EPSG:3857", ""};
        static const char* const kProj[] = {"+proj=robin", "EPSG:3035", "+proj=ortho +lat_0=40", "+proj=nonsense"};
        if (r.byte() % 16 == 0) return r.choose(kProj, 4, scratch);
        const std::uint8_t b = r.byte() % 5;
        return b < 4 ? kBuiltIn[b] : nullptr;
    }

    casteljau_status map_options(Reader& r) {
        casteljau_map_options* o = pick(map_options_, r);
        switch (r.byte() % 9) {
            case 0:
                keep(map_options_, casteljau_map_options_create(), casteljau_map_options_destroy);
                return CASTELJAU_OK;
            case 1: {
                // Out of range first (refused), then at most 128 x 128.
                const int wide = r.small_int() * 1000, high = r.small_int() * 1000;
                const casteljau_status s = casteljau_map_options_set_size(o, wide, high);
                const int width = 1 + r.byte() % 128, height = r.byte() % 129;
                casteljau_map_options_set_size(o, width, height);
                return s;
            }
            case 2: {
                std::string scratch;
                return casteljau_map_options_set_projection(o, projection(r, scratch));
            }
            case 3: {
                const double west = r.number(), south = r.number(), east = r.number(), north = r.number();
                return casteljau_map_options_set_bbox(o, west, south, east, north);
            }
            case 4: return casteljau_map_options_set_padding(o, r.number());
            case 5: return casteljau_map_options_set_separate(o, r.small_int());
            case 6: return casteljau_map_options_set_exact_overlaps(o, r.small_int());
            case 7: return casteljau_map_options_set_tolerance(o, r.number());
            default: return casteljau_map_options_set_size(o, 1 + r.byte() % 64, 0);
        }
    }

    casteljau_status map_draw(Reader& r) {
        casteljau_map* m = pick(maps_, r);
        casteljau_map_style* st = (r.byte() & 1) ? pick(styles_, r) : nullptr;
        casteljau_map_options* o = pick(map_options_, r);
        if (r.byte() & 1) return casteljau_map_render(m, st, o, pick(canvases_, r));
        casteljau_image* im = nullptr;
        const casteljau_status s = casteljau_map_render_image(m, st, o, &im);
        keep(images_, im, casteljau_image_destroy);
        return s;
    }

    casteljau_status tiles(Reader& r) {
        if (tile_options_.empty() || r.byte() % 4 == 0)
            keep(tile_options_, casteljau_tile_options_create(), casteljau_tile_options_destroy);
        casteljau_tile_options* o = pick(tile_options_, r);
        // Each setter gets a value from a wide range first (refused when out of range, applied when
        // not), then one that keeps the pyramid small: zoom 0-1, metatiles of at most 2 x 2 tiles.
        const int lo = r.small_int(), hi = r.small_int();
        casteljau_tile_options_set_zoom(o, lo, hi);
        casteljau_tile_options_set_zoom(o, 0, r.byte() % 2);
        const int size = r.small_int() * 32, scale = r.small_int();
        casteljau_tile_options_set_tile_size(o, size, scale);
        casteljau_tile_options_set_tile_size(o, 256, 1 + r.byte() % 2);
        casteljau_tile_options_set_metatile(o, r.small_int() * 8);
        casteljau_tile_options_set_metatile(o, 1 + r.byte() % 2);
        casteljau_tile_options_set_buffer(o, r.small_int() * 64);
        casteljau_tile_options_set_buffer(o, r.byte() % 65);
        casteljau_tile_options_set_skip_empty(o, r.small_int());
        casteljau_tile_options_set_resume(o, r.small_int());
        const int shard = r.small_int(), shards = r.small_int();
        casteljau_tile_options_set_shard(o, shard, shards);
        casteljau_tile_options_set_separate(o, r.small_int());
        casteljau_tile_options_set_exact_overlaps(o, r.small_int());
        casteljau_tile_options_set_tolerance(o, r.number());
        casteljau_tile_options_set_name(o, (r.byte() & 1) ? r.text().c_str() : nullptr);
        const std::string& dir = tile_folder();  // empty when it could not be made: an error below
        const std::string output = dir.empty() ? dir : dir + ((r.byte() & 1) ? "/tiles.mbtiles" : "/tiles");
        int left = r.byte() % 4;
        casteljau_tile_stats stats;
        casteljau_map* m = pick(maps_, r);
        casteljau_map_style* st = (r.byte() & 1) ? pick(styles_, r) : nullptr;
        const casteljau_status s = casteljau_map_render_tiles(m, st, o, output.c_str(), stop_after, &left, &stats);
        if (s == CASTELJAU_OK && stats.written + stats.skipped_empty + stats.skipped_existing > 5) __builtin_trap();
        return s;
    }

    casteljau_status font(Reader& r) {
        static const char* const kFiles[] = {CASTELJAU_FONT_DIR "/DejaVuSans.ttf",
                                             CASTELJAU_FONT_DIR "/NotoSansArabic-Regular.ttf",
                                             CASTELJAU_SOURCE_DIR "/tests/data/Inter-roman.var.ttf",
                                             CASTELJAU_FONT_DIR "/LinLibertine_R.otf", "/nonexistent.ttf"};
        std::string scratch;
        const char* path = r.choose(kFiles, 5, scratch);
        casteljau_font* f = nullptr;
        const casteljau_status s = casteljau_font_load_face(path, (r.byte() & 1) ? r.small_int() : 0, &f);
        keep(fonts_, f, casteljau_font_destroy);
        return s;
    }

    casteljau_status text_style(Reader& r) {
        static const char* const kScripts[] = {"Latn", "Arab", "Zzzz", "latin"};
        static const char* const kLanguages[] = {"en", "ar", "tr"};
        static const char* const kFeatures[] = {"kern=0", "liga=0", "smcp", "+++", "-kern[3:5]"};
        static const char* const kVariations[] = {"wght=700", "wdth=50", "opsz=1e300", "wght"};
        casteljau_text_style* st = pick(text_styles_, r);
        std::string scratch;
        switch (r.byte() % 11) {
            case 0:
                keep(text_styles_, casteljau_text_style_create(), casteljau_text_style_destroy);
                return CASTELJAU_OK;
            case 1: return casteljau_text_style_set_size(st, r.number());
            case 2: return casteljau_text_style_set_line_height(st, r.number());
            case 3: return casteljau_text_style_set_width(st, r.number());
            case 4: return casteljau_text_style_set_align(st, as_enum<casteljau_text_align>(r.small_int()));
            case 5: return casteljau_text_style_set_direction(st, as_enum<casteljau_text_direction>(r.small_int()));
            case 6: return casteljau_text_style_set_script(st, r.choose(kScripts, 4, scratch));
            case 7: return casteljau_text_style_set_language(st, r.choose(kLanguages, 3, scratch));
            case 8: return casteljau_text_style_add_feature(st, r.choose(kFeatures, 5, scratch));
            case 9: return casteljau_text_style_set_palette(st, r.small_int());
            default: return casteljau_text_style_add_variation(st, r.choose(kVariations, 4, scratch));
        }
    }

    casteljau_status text_layout(Reader& r) {
        const casteljau_font* chain[4];
        const std::size_t count = r.byte() % 5;
        for (std::size_t i = 0; i < count && i < 4; ++i) chain[i] = pick(fonts_, r);
        const std::string text = r.long_text();
        casteljau_text_layout* l = nullptr;
        const char* utf8 = (r.byte() == 255) ? nullptr : text.c_str();
        casteljau_text_style* st = (r.byte() & 1) ? pick(text_styles_, r) : nullptr;
        const casteljau_status s = casteljau_text_layout_create(utf8, count > 0 ? chain : nullptr, count, st, &l);
        if ((s == CASTELJAU_OK) != (l != nullptr)) __builtin_trap();
        keep(layouts_, l, casteljau_text_layout_destroy);
        return s;
    }

    casteljau_status text_query(Reader& r) {
        casteljau_text_layout* l = pick(layouts_, r);
        double w = 0, h = 0, x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        casteljau_status s = casteljau_text_layout_size(l, &w, &h);
        s = casteljau_text_layout_bounds(l, &x0, &y0, &x1, &y1);
        const std::size_t lines = casteljau_text_layout_line_count(l);
        casteljau_text_line line;
        s = casteljau_text_layout_line(l, r.byte() % (lines + 2), &line);
        if (s == CASTELJAU_OK && (line.text == nullptr || std::strlen(line.text) != line.length)) __builtin_trap();
        return s;
    }

    casteljau_status text_draw(Reader& r) {
        casteljau_text_layout* l = pick(layouts_, r);
        if (r.byte() & 1) {
            casteljau_canvas* c = pick(canvases_, r);
            const double x = r.number(), y = r.number();
            return casteljau_text_layout_draw(l, c, x, y, pick(paints_, r));
        }
        double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        const casteljau_status s = casteljau_text_layout_bounds(l, &x0, &y0, &x1, &y1);
        const int padding = r.small_int();
        if (s != CASTELJAU_OK || !(x1 - x0 + 2 * padding < 512 && y1 - y0 + 2 * padding < 512)) return s;
        casteljau_image* im = nullptr;
        const casteljau_status drawn = casteljau_text_layout_render_image(l, pick(paints_, r), color(r), padding, &im);
        keep(images_, im, casteljau_image_destroy);
        return drawn;
    }

    casteljau_status core(Reader& r) {
        casteljau_color c;
        switch (r.byte() % 3) {
            case 0: return casteljau_color_parse((r.byte() & 1) ? r.text().c_str() : nullptr, &c);
            case 1: {
                std::uint8_t* png = nullptr;
                std::size_t size = 0;
                const casteljau_status s = casteljau_image_encode_png(pick(images_, r), &png, &size);
                if ((s == CASTELJAU_OK) != (png != nullptr)) __builtin_trap();
                casteljau_free(png);
                return s;
            }
            default: {
                casteljau_paint* p = pick(paints_, r);
                return casteljau_paint_set_linear_blend(p, r.small_int());
            }
        }
    }

    std::vector<casteljau_canvas*>& canvases_;
    std::vector<casteljau_paint*>& paints_;
    std::vector<casteljau_image*>& images_;
    std::vector<casteljau_svg_options*> svg_options_;
    std::vector<casteljau_svg*> svgs_;
    std::vector<casteljau_map*> maps_;
    std::vector<casteljau_map_style*> styles_;
    std::vector<casteljau_map_options*> map_options_;
    std::vector<casteljau_tile_options*> tile_options_;
    std::vector<casteljau_font*> fonts_;
    std::vector<casteljau_text_style*> text_styles_;
    std::vector<casteljau_text_layout*> layouts_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Reader r(data, size);
    std::vector<casteljau_path*> paths;
    std::vector<casteljau_paint*> paints;
    std::vector<casteljau_image*> images;
    std::vector<casteljau_canvas*> canvases;
    std::vector<casteljau_stroke*> strokes;
    int steps = 0;
    // Destroyed before the canvases and images below: it draws onto them and adds images.
    auto documents = std::make_unique<Documents>(canvases, paints, images);
    while (!r.done() && ++steps < 400) {
        const std::uint8_t op = r.byte() % (33 + Documents::kSteps);
        casteljau_status s = CASTELJAU_OK;
        switch (op) {
            case 0:
                if (paths.size() < 8) paths.push_back(casteljau_path_create());
                break;
            case 1: {
                casteljau_path* p = nullptr;
                s = casteljau_path_from_svg(r.text().c_str(), &p);
                if (p) paths.push_back(p);
                break;
            }
            case 2: s = casteljau_path_move_to(pick(paths, r), r.number(), r.number()); break;
            case 3: s = casteljau_path_line_to(pick(paths, r), r.number(), r.number()); break;
            case 4:
                s = casteljau_path_cubic_to(pick(paths, r), r.number(), r.number(), r.number(), r.number(), r.number(),
                                            r.number());
                break;
            case 5:
                s = casteljau_path_add_ellipse(pick(paths, r), r.number(), r.number(), r.number(), r.number());
                break;
            case 6: s = casteljau_path_close(pick(paths, r)); break;
            case 7: {
                const casteljau_matrix m = matrix(r);
                s = casteljau_path_transform(pick(paths, r), &m);
                break;
            }
            case 8: {
                casteljau_paint* p = nullptr;
                s = casteljau_paint_create_solid(color(r), &p);
                if (p) paints.push_back(p);
                break;
            }
            case 9: {
                casteljau_gradient_stop stops[3] = {
                    {r.number(), color(r)}, {r.number(), color(r)}, {r.number(), color(r)}};
                casteljau_paint* p = nullptr;
                const casteljau_matrix m = matrix(r);
                const bool radial = r.byte() & 1;
                const auto spread = as_enum<casteljau_spread>(r.small_int());
                if (radial)
                    s = casteljau_paint_create_radial(r.number(), r.number(), r.number(), r.number(), r.number(),
                                                      r.number(), stops, r.byte() % 4, spread,
                                                      (r.byte() & 1) ? &m : nullptr, &p);
                else
                    s = casteljau_paint_create_linear(r.number(), r.number(), r.number(), r.number(), stops,
                                                      r.byte() % 4, spread, (r.byte() & 1) ? &m : nullptr, &p);
                if (p) paints.push_back(p);
                break;
            }
            case 10: {
                casteljau_paint* p = nullptr;
                const casteljau_matrix m = matrix(r);
                s = casteljau_paint_create_image(pick(images, r), as_enum<casteljau_sampling>(r.small_int()), &m,
                                                 r.byte() & 1, &p);
                if (p) paints.push_back(p);
                break;
            }
            case 11: s = casteljau_paint_set_opacity(pick(paints, r), r.number()); break;
            case 12:
                s = casteljau_paint_set_blend_mode(pick(paints, r), as_enum<casteljau_blend_mode>(r.small_int()));
                break;
            case 13: {
                if (images.size() >= 4) break;
                casteljau_image* im = nullptr;
                s = casteljau_image_create(image_side(r), image_side(r), &im);
                if (im) images.push_back(im);
                break;
            }
            case 14: {
                casteljau_image* im = pick(images, r);
                if (!im || canvases.size() >= 4) break;
                casteljau_canvas* c = nullptr;
                s = casteljau_canvas_create(im, &c);
                if (c) canvases.push_back(c);
                break;
            }
            case 15: {
                if (strokes.size() < 4) strokes.push_back(casteljau_stroke_create());
                casteljau_stroke* st = pick(strokes, r);
                s = casteljau_stroke_set_width(st, r.number());
                casteljau_stroke_set_cap(st, as_enum<casteljau_line_cap>(r.small_int()));
                casteljau_stroke_set_join(st, as_enum<casteljau_line_join>(r.small_int()), r.number());
                const double d[3] = {r.number(), r.number(), r.number()};
                casteljau_stroke_set_dashes(st, d, r.byte() % 4, r.number());
                break;
            }
            case 16: s = casteljau_canvas_save(pick(canvases, r)); break;
            case 17: s = casteljau_canvas_restore(pick(canvases, r)); break;
            case 18: s = casteljau_canvas_translate(pick(canvases, r), r.number(), r.number()); break;
            case 19: s = casteljau_canvas_scale(pick(canvases, r), r.number(), r.number()); break;
            case 20: s = casteljau_canvas_rotate(pick(canvases, r), r.number()); break;
            case 21: {
                const casteljau_matrix m = matrix(r);
                s = casteljau_canvas_concat(pick(canvases, r), &m);
                break;
            }
            case 22:
                s = casteljau_canvas_clip_rect(pick(canvases, r), r.number(), r.number(), r.number(), r.number());
                break;
            case 23:
                s = casteljau_canvas_clip_path(pick(canvases, r), pick(paths, r),
                                               as_enum<casteljau_fill_rule>(r.small_int()));
                break;
            case 24: s = casteljau_canvas_set_opacity(pick(canvases, r), r.number()); break;
            case 25:
                s = casteljau_canvas_set_blend_mode(pick(canvases, r), as_enum<casteljau_blend_mode>(r.small_int()));
                break;
            case 26: s = casteljau_canvas_clear(pick(canvases, r), color(r)); break;
            case 27:
                s = casteljau_canvas_fill_path(pick(canvases, r), pick(paths, r), pick(paints, r),
                                               as_enum<casteljau_fill_rule>(r.byte() % 3));
                break;
            case 28:
                s = casteljau_canvas_stroke_path(pick(canvases, r), pick(paths, r), pick(strokes, r), pick(paints, r));
                break;
            case 29: {
                const casteljau_matrix m = matrix(r);
                s = casteljau_canvas_draw_image(pick(canvases, r), pick(images, r), (r.byte() & 1) ? &m : nullptr,
                                                as_enum<casteljau_sampling>(r.small_int()), r.number());
                break;
            }
            case 30:
                s = casteljau_canvas_begin_layer(pick(canvases, r), r.number(),
                                                 as_enum<casteljau_blend_mode>(r.small_int()));
                break;
            case 31: {
                s = casteljau_canvas_end_layer(pick(canvases, r));
                casteljau_image* im = pick(images, r);
                if (im && r.byte() == 7) {
                    casteljau_canvas* c = nullptr;
                    const int w = casteljau_image_width(im), h = casteljau_image_height(im);
                    s = casteljau_canvas_create_for_pixels(casteljau_image_data(im), w, h, casteljau_image_stride(im),
                                                           &c);
                    casteljau_canvas_fill_rect(c, r.number(), r.number(), r.number(), r.number(), pick(paints, r));
                    casteljau_canvas_destroy(c);
                }
                break;
            }
            case 32: {
                // Random bytes over the limits in force, applied with a random size: refused
                // whole or applied whole, and every later call checks against them.
                casteljau_limits l;
                s = casteljau_limits_get(&l, sizeof l);
                auto* raw = reinterpret_cast<std::uint8_t*>(&l);
                for (int n = r.byte() % 8; n > 0; --n) raw[r.byte() % sizeof l] = r.byte();
                const std::size_t size = (r.byte() & 1) ? sizeof l : r.byte() % (sizeof l + 2);
                s = casteljau_limits_set(&l, size);
                break;
            }
            default: s = documents->step(op - 33, r); break;
        }
        // Every failure leaves a message.
        if (s != CASTELJAU_OK && casteljau_last_error()[0] == '\0') __builtin_trap();
    }
    documents.reset();
    // Canvases borrow images: destroy them first.
    for (casteljau_canvas* c : canvases) casteljau_canvas_destroy(c);
    for (casteljau_image* i : images) casteljau_image_destroy(i);
    for (casteljau_path* p : paths) casteljau_path_destroy(p);
    for (casteljau_paint* p : paints) casteljau_paint_destroy(p);
    for (casteljau_stroke* st : strokes) casteljau_stroke_destroy(st);
    casteljau_limits_reset();
    return 0;
}
