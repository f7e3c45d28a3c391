// tests/support/glyph_outline.cpp: see glyph_outline.hpp.
#include "glyph_outline.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <stdexcept>

namespace casteljau::testing {

struct GlyphFont::Impl {
    FT_Library lib = nullptr;
    FT_Face face = nullptr;
};

GlyphFont::GlyphFont(const std::string& file) : impl_(new Impl) {
    if (FT_Init_FreeType(&impl_->lib) != 0) {
        delete impl_;
        throw std::runtime_error("FT_Init_FreeType failed");
    }
    if (FT_New_Face(impl_->lib, file.c_str(), 0, &impl_->face) != 0) {
        FT_Done_FreeType(impl_->lib);
        delete impl_;
        throw std::runtime_error("FreeType cannot open " + file);
    }
}

GlyphFont::~GlyphFont() {
    FT_Done_Face(impl_->face);
    FT_Done_FreeType(impl_->lib);
    delete impl_;
}

int GlyphFont::units_per_em() const { return impl_->face->units_per_EM; }

namespace {

struct Decompose {
    Path* out;
    double s;  // pixels per font unit
    Point o;   // origin in pixels
    bool open = false;
    Point map(const FT_Vector* v) const {
        return {o.x + s * static_cast<double>(v->x), o.y - s * static_cast<double>(v->y)};
    }
};

int cb_move(const FT_Vector* to, void* user) {
    auto* d = static_cast<Decompose*>(user);
    if (d->open) d->out->close();
    d->out->move_to(d->map(to));
    d->open = true;
    return 0;
}
int cb_line(const FT_Vector* to, void* user) {
    auto* d = static_cast<Decompose*>(user);
    d->out->line_to(d->map(to));
    return 0;
}
int cb_conic(const FT_Vector* c, const FT_Vector* to, void* user) {
    auto* d = static_cast<Decompose*>(user);
    d->out->quad_to(d->map(c), d->map(to));
    return 0;
}
int cb_cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto* d = static_cast<Decompose*>(user);
    d->out->cubic_to(d->map(c1), d->map(c2), d->map(to));
    return 0;
}

}  // namespace

double GlyphFont::append_glyph(char32_t cp, double px, Point origin, Path& out) const {
    FT_Face f = impl_->face;
    const FT_UInt gi = FT_Get_Char_Index(f, cp);
    if (FT_Load_Glyph(f, gi, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0)
        throw std::runtime_error("FT_Load_Glyph failed");
    if (f->glyph->format != FT_GLYPH_FORMAT_OUTLINE) throw std::runtime_error("glyph is not an outline");
    const double s = px / f->units_per_EM;
    Decompose d{&out, s, origin};
    FT_Outline_Funcs funcs{};
    funcs.move_to = cb_move;
    funcs.line_to = cb_line;
    funcs.conic_to = cb_conic;
    funcs.cubic_to = cb_cubic;
    funcs.shift = 0;
    funcs.delta = 0;
    if (FT_Outline_Decompose(&f->glyph->outline, &funcs, &d) != 0)
        throw std::runtime_error("FT_Outline_Decompose failed");
    if (d.open) out.close();
    return s * static_cast<double>(f->glyph->advance.x);
}

Path GlyphFont::text(std::u32string_view str, double px, Point origin) const {
    Path p;
    for (char32_t c : str) origin.x += append_glyph(c, px, origin, p);
    return p;
}

std::string dejavu_sans_path() { return std::string(CASTELJAU_SOURCE_DIR) + "/fonts/DejaVuSans.ttf"; }

}  // namespace casteljau::testing
