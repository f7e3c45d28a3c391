// Text benchmark: a 10,000-glyph paragraph at 16 px, shaped, rasterized and composited onto a
// Pixmap, side by side in one process:
//   casteljau/warm  layout_text + draw_text with a GlyphCache that already holds the glyphs
//   casteljau/cold  the same with a new, empty GlyphCache every iteration (every distinct glyph and
//                   subpixel offset is rasterized once per iteration, then reused)
//   freetype        HarfBuzz (hb-ft) shaping of the same lines + per glyph FT_Load_Glyph
//                   (FT_LOAD_NO_HINTING), the outline moved to the same quarter-pixel offset,
//                   FT_Render_Glyph, composited with the same composite_span
// Each reports glyphs/s; the end prints the ratios casteljau / FreeType. Shaping is included in
// every case. Build: an executable linking casteljau, Freetype::Freetype, PkgConfig::HB (HarfBuzz)
// and benchmark::benchmark, with CASTELJAU_SOURCE_DIR defined as the source tree (for the font).
#include <benchmark/benchmark.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include <hb-ft.h>
#include <hb.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/font.hpp"
#include "casteljau/text.hpp"

#ifndef CASTELJAU_SOURCE_DIR
#define CASTELJAU_SOURCE_DIR "."
#endif

namespace {

using namespace casteljau;

constexpr double kSize = 16;
constexpr int kSteps = 4;  // quarter-pixel positioning in both renderers
const std::string kFontPath = std::string(CASTELJAU_SOURCE_DIR) + "/fonts/DejaVuSans.ttf";

// Deterministic English-like text, lines of about 72 characters, ~10,000 glyphs in all.
std::string make_paragraph() {
    static const char* words[] = {"the",        "quick", "brown",  "fox",    "jumps",   "over",  "lazy",
                                  "dog",        "while", "five",   "boxing", "wizards", "jump",  "quickly",
                                  "Sphinx",     "of",    "black",  "quartz", "judge",   "my",    "vow",
                                  "pack",       "box",   "with",   "dozen",  "liquor",  "jugs",  "AVATAR",
                                  "Toyota",     "Wales", "office", "fluffy", "waffle",  "1234,", "(parenthesis)",
                                  "\"quoted\"", "and",   "a",      "to",     "in",      "is",    "it"};
    std::uint32_t seed = 20240611;
    std::string out, line;
    std::size_t glyphs = 0;
    while (glyphs < 10360) {  // ~10,000 glyphs after shaping (ligatures, line ends)
        seed = seed * 1664525u + 1013904223u;
        const std::string w = words[(seed >> 8) % (sizeof words / sizeof *words)];
        if (line.size() + w.size() + 1 > 72) {
            out += line + "\n";
            line.clear();
        }
        if (!line.empty()) {
            line += ' ';
            ++glyphs;
        }
        line += w;
        glyphs += w.size();
    }
    return out + line;
}

struct Setup {
    std::string text = make_paragraph();
    Font font = Font::load(kFontPath);
    TextStyle style;
    std::size_t glyphs = 0;
    int width = 0, height = 0;
    Setup() {
        style.size = kSize;
        const TextLayout l = layout_text(text, font, style);
        glyphs = l.glyphs.size();
        width = static_cast<int>(std::ceil(l.bounds().x1)) + 8;
        height = static_cast<int>(std::ceil(l.bounds().y1)) + 8;
    }
};

Setup& setup() {
    static Setup s;
    return s;
}

void BM_casteljau_warm(benchmark::State& state) {
    Setup& s = setup();
    Pixmap pm(s.width, s.height);
    GlyphCache cache;
    {
        Canvas c(pm);
        draw_text(c, layout_text(s.text, s.font, s.style), {4, 4}, Paint::solid(Color::black()), &cache);
    }
    for (auto _ : state) {
        pm.fill(Color::white());
        Canvas c(pm);
        const TextLayout l = layout_text(s.text, s.font, s.style);
        draw_text(c, l, {4, 4}, Paint::solid(Color::black()), &cache);
        benchmark::DoNotOptimize(pm.data());
    }
    state.counters["glyphs/s"] =
        benchmark::Counter(static_cast<double>(s.glyphs), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["cache_misses"] = static_cast<double>(cache.stats().misses);
}

void BM_casteljau_cold(benchmark::State& state) {
    Setup& s = setup();
    Pixmap pm(s.width, s.height);
    std::size_t misses = 0;
    for (auto _ : state) {
        pm.fill(Color::white());
        Canvas c(pm);
        GlyphCache cache;
        const TextLayout l = layout_text(s.text, s.font, s.style);
        draw_text(c, l, {4, 4}, Paint::solid(Color::black()), &cache);
        misses = cache.stats().misses;
        benchmark::DoNotOptimize(pm.data());
    }
    state.counters["glyphs/s"] =
        benchmark::Counter(static_cast<double>(s.glyphs), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["masks_made"] = static_cast<double>(misses);
}

// The baseline: HarfBuzz + FreeType's own rendering, no glyph cache.
class FreeTypeRenderer {
public:
    FreeTypeRenderer() {
        FT_Init_FreeType(&lib_);
        FT_New_Face(lib_, kFontPath.c_str(), 0, &face_);
        FT_Set_Char_Size(face_, static_cast<FT_F26Dot6>(kSize * 64), static_cast<FT_F26Dot6>(kSize * 64), 72, 72);
        hb_ = hb_ft_font_create_referenced(face_);
        hb_ft_font_set_load_flags(hb_, FT_LOAD_NO_HINTING);
        buf_ = hb_buffer_create();
        line_advance_ =
            kSize * (face_->ascender - face_->descender + 0.0) / face_->units_per_EM;  // DejaVu: no line gap
        ascender_ = kSize * face_->ascender / face_->units_per_EM;
    }
    ~FreeTypeRenderer() {
        hb_buffer_destroy(buf_);
        hb_font_destroy(hb_);
        FT_Done_Face(face_);
        FT_Done_FreeType(lib_);
    }

    std::size_t draw(const std::string& text, Pixmap& pm, double ox, double oy, const Paint& paint) {
        std::size_t glyphs = 0;
        std::size_t start = 0;
        int line = 0;
        while (start <= text.size()) {
            std::size_t end = text.find('\n', start);
            if (end == std::string::npos) end = text.size();
            hb_buffer_clear_contents(buf_);
            hb_buffer_add_utf8(buf_, text.data() + start, static_cast<int>(end - start), 0, -1);
            hb_buffer_guess_segment_properties(buf_);
            hb_shape(hb_, buf_, nullptr, 0);
            unsigned n = 0;
            const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf_, &n);
            const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf_, &n);
            double pen = 0;
            const double baseline = oy + ascender_ + line * line_advance_;
            for (unsigned i = 0; i < n; ++i) {
                const double x = ox + pen + pos[i].x_offset / 64.0, y = baseline - pos[i].y_offset / 64.0;
                pen += pos[i].x_advance / 64.0;
                const long qx = std::lround(x * kSteps), qy = std::lround(y * kSteps);
                const long ix = qx >= 0 ? qx / kSteps : -((-qx + kSteps - 1) / kSteps);
                const long iy = qy >= 0 ? qy / kSteps : -((-qy + kSteps - 1) / kSteps);
                if (FT_Load_Glyph(face_, info[i].codepoint, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) continue;
                FT_Outline_Translate(&face_->glyph->outline, (qx - ix * kSteps) * (64 / kSteps),
                                     -(qy - iy * kSteps) * (64 / kSteps));
                if (FT_Render_Glyph(face_->glyph, FT_RENDER_MODE_NORMAL)) continue;
                const FT_Bitmap& bm = face_->glyph->bitmap;
                const long left = ix + face_->glyph->bitmap_left, top = iy - face_->glyph->bitmap_top;
                for (unsigned r = 0; r < bm.rows; ++r) {
                    const long py = top + r;
                    if (py < 0 || py >= pm.height()) continue;
                    long x0 = left, x1 = left + bm.width;
                    const long skip = x0 < 0 ? -x0 : 0;
                    x0 = std::max(x0, 0L);
                    x1 = std::min(x1, static_cast<long>(pm.width()));
                    if (x0 >= x1) continue;
                    composite_span(pm.row(static_cast<int>(py)) + 4 * x0, static_cast<int>(x1 - x0),
                                   bm.buffer + static_cast<long>(r) * bm.pitch + skip, paint);
                }
                ++glyphs;
            }
            ++line;
            start = end + 1;
        }
        return glyphs;
    }

private:
    FT_Library lib_ = nullptr;
    FT_Face face_ = nullptr;
    hb_font_t* hb_ = nullptr;
    hb_buffer_t* buf_ = nullptr;
    double line_advance_ = 0, ascender_ = 0;
};

void BM_freetype(benchmark::State& state) {
    Setup& s = setup();
    Pixmap pm(s.width, s.height);
    FreeTypeRenderer ft;
    std::size_t glyphs = 0;
    for (auto _ : state) {
        pm.fill(Color::white());
        glyphs = ft.draw(s.text, pm, 4, 4, Paint::solid(Color::black()));
        benchmark::DoNotOptimize(pm.data());
    }
    state.counters["glyphs/s"] =
        benchmark::Counter(static_cast<double>(glyphs), benchmark::Counter::kIsIterationInvariantRate);
}

// Console output plus a record of glyphs/s per benchmark, for the ratios at the end.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    RatioReporter() : ConsoleReporter(OO_Tabular) {}
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            auto it = r.counters.find("glyphs/s");
            if (it != r.counters.end() && r.run_type == Run::RT_Iteration)
                rates[r.run_name.function_name] = it->second.value;
        }
    }
    std::map<std::string, double> rates;
};

}  // namespace

BENCHMARK(BM_casteljau_warm)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_casteljau_cold)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_freetype)->Unit(benchmark::kMillisecond)->MinTime(1.0);

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::printf("paragraph: %zu glyphs, DejaVu Sans %g px, %dx%d pixmap; FreeType %d.%d.%d, HarfBuzz %s\n",
                setup().glyphs, kSize, setup().width, setup().height, FREETYPE_MAJOR, FREETYPE_MINOR, FREETYPE_PATCH,
                hb_version_string());
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const double ft = reporter.rates["BM_freetype"];
    if (ft > 0) {
        for (const char* name : {"BM_casteljau_warm", "BM_casteljau_cold"}) {
            const double r = reporter.rates[name];
            if (r > 0)
                std::printf("%-20s %12.0f glyphs/s   %.2fx FreeType+HarfBuzz (%.0f glyphs/s)\n", name, r, r / ft, ft);
        }
    }
    benchmark::Shutdown();
    return 0;
}
