// bench/glyph_set.cpp: loads the benchmark glyph set with FreeType (see glyph_set.hpp).
#include "glyph_set.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace bench {

std::vector<std::uint32_t> benchmark_codepoints() {
    std::vector<std::uint32_t> cps;
    for (std::uint32_t c = 0x21; c <= 0x7E; ++c) cps.push_back(c);
    for (std::uint32_t c = 0xA1; c <= 0x17F; ++c) cps.push_back(c);
    return cps;
}

Font::Font(const std::string& path) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open font " + path);
    bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (FT_Init_FreeType(&lib_)) throw std::runtime_error("FT_Init_FreeType failed");
    if (FT_New_Memory_Face(lib_, bytes_.data(), static_cast<FT_Long>(bytes_.size()), 0, &face_)) {
        FT_Done_FreeType(lib_);
        throw std::runtime_error("FreeType cannot open " + path);
    }
}

Font::~Font() {
    FT_Done_Face(face_);
    FT_Done_FreeType(lib_);
}

namespace {

// FT_Outline_Decompose callbacks appending to a casteljau::Path in 26.6 units.
struct Decomposer {
    casteljau::Path* path;
    bool open = false;
    std::size_t curves = 0;
};

casteljau::Point pt(const FT_Vector* v) { return {static_cast<double>(v->x), static_cast<double>(v->y)}; }

int on_move(const FT_Vector* to, void* user) {
    auto* d = static_cast<Decomposer*>(user);
    if (d->open) d->path->close();
    d->path->move_to(pt(to));
    d->open = true;
    return 0;
}
int on_line(const FT_Vector* to, void* user) {
    static_cast<Decomposer*>(user)->path->line_to(pt(to));
    return 0;
}
int on_conic(const FT_Vector* c, const FT_Vector* to, void* user) {
    auto* d = static_cast<Decomposer*>(user);
    d->path->quad_to(pt(c), pt(to));
    ++d->curves;
    return 0;
}
int on_cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto* d = static_cast<Decomposer*>(user);
    d->path->cubic_to(pt(c1), pt(c2), pt(to));
    ++d->curves;
    return 0;
}

}  // namespace

GlyphSet::GlyphSet(const Font& font, int pixel_size) : font_(font), px_(pixel_size) {
    FT_Face face = font.face();
    if (FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixel_size)))
        throw std::runtime_error("FT_Set_Pixel_Sizes failed");
    FT_Outline_Funcs funcs{};
    funcs.move_to = on_move;
    funcs.line_to = on_line;
    funcs.conic_to = on_conic;
    funcs.cubic_to = on_cubic;
    funcs.shift = 0;
    funcs.delta = 0;
    for (std::uint32_t cp : benchmark_codepoints()) {
        const FT_UInt gi = FT_Get_Char_Index(face, cp);
        if (gi == 0) continue;
        if (FT_Load_Glyph(face, gi, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) continue;
        const FT_Outline& src = face->glyph->outline;
        if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE || src.n_points == 0) continue;
        Glyph g;
        g.codepoint = cp;
        g.glyph_index = gi;
        FT_BBox cb;
        FT_Outline_Get_CBox(&src, &cb);
        const long px0 = cb.xMin >> 6, py0 = cb.yMin >> 6;                // floor
        const long px1 = (cb.xMax + 63) >> 6, py1 = (cb.yMax + 63) >> 6;  // ceil
        g.box.x0 = static_cast<int>(px0);
        g.box.y0 = static_cast<int>(-py1);
        g.box.width = static_cast<int>(px1 - px0);
        g.box.height = static_cast<int>(py1 - py0);
        if (g.box.width <= 0 || g.box.height <= 0) continue;

        Decomposer d{&g.path};
        if (FT_Outline_Decompose(const_cast<FT_Outline*>(&src), &funcs, &d))
            throw std::runtime_error("FT_Outline_Decompose failed");
        if (d.open) g.path.close();
        g.curves = d.curves;
        // x' = x / 64 - px0, y' = py1 - y / 64.
        g.to_box = casteljau::Affine{1.0 / 64, 0, 0, -1.0 / 64, -static_cast<double>(px0), static_cast<double>(py1)};

        if (FT_Outline_New(font.library(), static_cast<FT_UInt>(src.n_points), src.n_contours, &g.outline))
            throw std::runtime_error("FT_Outline_New failed");
        FT_Outline_Copy(&src, &g.outline);
        FT_Outline_Translate(&g.outline, -px0 * 64, -py0 * 64);

        max_pixels_ = std::max(max_pixels_, g.box.pixels());
        total_pixels_ += g.box.pixels();
        max_w_ = std::max(max_w_, g.box.width);
        max_h_ = std::max(max_h_, g.box.height);
        glyphs_.push_back(std::move(g));
    }
    if (glyphs_.empty()) throw std::runtime_error("no glyphs loaded from " + font.path());
}

GlyphSet::~GlyphSet() {
    for (Glyph& g : glyphs_) FT_Outline_Done(font_.library(), &g.outline);
}

void DiffStats::add(const Coverage& a, const Coverage& b) {
    const int x0 = std::min(a.box.x0, b.box.x0), y0 = std::min(a.box.y0, b.box.y0);
    const int x1 = std::max(a.box.x0 + a.box.width, b.box.x0 + b.box.width);
    const int y1 = std::max(a.box.y0 + a.box.height, b.box.y0 + b.box.height);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const int d = std::abs(static_cast<int>(a.at(x, y)) - static_cast<int>(b.at(x, y)));
            sum += d;
            max = std::max(max, d);
            if (d > 1) ++over1;
            if (d != 0) ++changed;
        }
    }
    pixels += static_cast<std::size_t>(x1 - x0) * static_cast<std::size_t>(y1 - y0);
}

void render_freetype(FT_Library lib, const FT_Outline& outline, int width, int height, std::uint8_t* buf) {
    FT_Bitmap bm{};
    bm.rows = static_cast<unsigned>(height);
    bm.width = static_cast<unsigned>(width);
    bm.pitch = width;
    bm.buffer = buf;
    bm.pixel_mode = FT_PIXEL_MODE_GRAY;
    bm.num_grays = 256;
    FT_Raster_Params params{};
    params.target = &bm;
    params.flags = FT_RASTER_FLAG_AA;
    FT_Outline copy = outline;  // a shallow copy of the handle; FreeType does not modify the outline
    FT_Outline_Render(lib, &copy, &params);
}

std::vector<int> parse_sizes(const std::string& list) {
    std::vector<int> sizes;
    for (std::size_t p = 0; p <= list.size();) {
        std::size_t q = list.find(',', p);
        if (q == std::string::npos) q = list.size();
        const int v = std::atoi(list.substr(p, q - p).c_str());
        if (v <= 0 || v > 1000) return {};
        sizes.push_back(v);
        p = q + 1;
    }
    return sizes;
}

bool CommonOptions::parse_common(int argc, char** argv, int& i, void (*usage)(const char*)) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
        if (i + 1 >= argc) usage(("missing value after " + a).c_str());
        return argv[++i];
    };
    if (a == "--quick") {
        quick = true;
        runs = 1;
    } else if (a == "--runs") {
        runs = std::max(1, std::atoi(value().c_str()));
    } else if (a == "--min-time") {
        min_time = std::atof(value().c_str());
        if (!(min_time >= 0)) usage("--min-time must be a number of seconds");
    } else if (a == "--sizes") {
        sizes = parse_sizes(value());
        if (sizes.empty()) usage("bad --sizes (pixel sizes 1..1000, comma-separated)");
    } else {
        return false;
    }
    return true;
}

void DiffStats::merge(const DiffStats& o) {
    sum += o.sum;
    pixels += o.pixels;
    max = std::max(max, o.max);
    over1 += o.over1;
    changed += o.changed;
}

}  // namespace bench
