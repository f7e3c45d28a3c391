// Text stage, layout: paragraphs, bidi, shaping, line breaking, visual order and alignment
// (include/casteljau/text.hpp).
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <unordered_map>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/shaping.hpp"
#include "casteljau/text.hpp"
#include "text/color_glyphs.hpp"
#include "text/font_fallback.hpp"
#include "text/line_break.hpp"
#include "text/shape.hpp"

namespace casteljau {

namespace {

// Spaces at which lines may break and which hang at the end of a line (not NBSP, U+2007, U+202F).
bool is_break_space(char32_t c) {
    return c == 0x20 || c == 0x3000 || c == 0x1680 || (c >= 0x2000 && c <= 0x2006) || (c >= 0x2008 && c <= 0x200a) ||
           c == 0x205f;
}

}  // namespace

Rect TextLayout::bounds() const {
    Rect box{0, 0, width, height};
    if (ink.empty()) return box;
    return box.united(ink);
}

TextLayout layout_text(std::string_view utf8, const Font& font, const TextStyle& style) {
    const Font* f = &font;
    return layout_text(utf8, std::span<const Font* const>(&f, 1), style);
}

namespace {

void check_layout_arguments(std::string_view utf8, std::span<const Font* const> fonts, const TextStyle& style) {
    if (fonts.empty()) throw Error(ErrorKind::InvalidArgument, "layout_text needs at least one font");
    if (fonts.size() > 0xffff) throw Error(ErrorKind::Limit, "layout_text accepts at most 65535 fonts");
    for (const Font* f : fonts)
        if (!f) throw Error(ErrorKind::InvalidArgument, "layout_text: null font in the font list");
    check_font_size(style.size);
    if (!std::isfinite(style.line_height) || style.line_height <= 0 || style.line_height > 100)
        throw Error(ErrorKind::InvalidArgument,
                    "line height must be a number in (0, 100], got " + std::to_string(style.line_height));
    if (!std::isfinite(style.max_width) || style.max_width < 0 || style.max_width > limits::kMaxCanvasDimension * 16.0)
        throw Error(ErrorKind::InvalidArgument,
                    "wrap width must be 0 (no wrapping) or a positive number of pixels up to " +
                        std::to_string(limits::kMaxCanvasDimension * 16));
    if (const std::size_t max_bytes = current_limits().text_bytes; utf8.size() > max_bytes)
        throw Error(ErrorKind::Limit, "text of " + std::to_string(utf8.size()) + " bytes exceeds the limit of " +
                                          std::to_string(max_bytes) + " bytes");
}

// Lays out the text paragraph by paragraph, line by line, into a TextLayout: the glyphs and lines
// before alignment. Scratch vectors are kept across paragraphs.
class Paragraphs {
public:
    Paragraphs(TextLayout& L, text_detail::Shaper& shaper, const TextStyle& style, const FontMetrics& fm)
        : L_(L), shaper_(shaper), style_(style) {
        const double scale = style.size / fm.units_per_em;
        ascender_ = fm.ascender * scale;
        line_advance_ = style.line_height * fm.line_spacing() * scale;
    }

    void run() {
        const std::u32string& text = L_.text;
        std::size_t pos = 0;
        while (pos <= text.size()) {
            // One paragraph: [pos, pe), ended by \n, \r\n, \r, U+2029, U+2028, U+0085 or the end.
            std::size_t pe = pos;
            while (pe < text.size() && text[pe] != U'\n' && text[pe] != U'\r' && text[pe] != 0x2029 &&
                   text[pe] != 0x2028 && text[pe] != 0x85)
                ++pe;
            std::size_t next = pe;
            if (next < text.size())
                next += (text[next] == U'\r' && next + 1 < text.size() && text[next + 1] == U'\n') ? 2 : 1;
            paragraph(pos, pe);
            if (pe >= text.size()) break;
            pos = next;
            if (pos == text.size()) {
                // A trailing line break starts one more (empty) line.
                TextLine line;
                line.first_glyph = L_.glyphs.size();
                line.baseline = baseline();
                line.text_begin = line.text_end = pos;
                L_.lines.push_back(line);
                break;
            }
        }
    }

private:
    struct LineRange {
        std::size_t begin, end;  // code points in the paragraph; end includes trailing spaces
    };
    struct Piece {
        const ShapedRun* run;
        std::size_t g0, g1;  // glyph range within the run (visual order)
    };

    double baseline() const { return ascender_ + static_cast<double>(L_.lines.size()) * line_advance_; }

    // The paragraph L.text[pos, pe): shaped, broken into lines, each line laid out.
    void paragraph(std::size_t pos, std::size_t pe) {
        work_.assign(L_.text, pos, pe - pos);  // as shaped: tabs become spaces
        for (char32_t& c : work_)
            if (c == U'\t') c = U' ';
        const std::u32string_view para(work_);
        const int para_level = resolve_bidi_levels(para, style_.direction, levels_);
        shaper_.shape_paragraph(para, levels_, runs_);
        cluster_advances(para.size());
        break_lines(para);
        for (const LineRange& lr : ranges_) line(para, lr, pos, para_level == 1);
    }

    // Advance of each code point (glyph advances summed by cluster) and cluster starts.
    void cluster_advances(std::size_t n) {
        adv_.assign(n, 0.0);
        cluster_start_.assign(n + 1, 0);
        cluster_start_[n] = 1;
        for (const ShapedRun& r : runs_)
            for (const ShapedGlyph& g : r.glyphs)
                if (g.cluster < n) {
                    adv_[g.cluster] += g.advance;
                    cluster_start_[g.cluster] = 1;
                }
    }

    // Greedy line breaking at the UAX #14 opportunities (none needed without a wrap width).
    void break_lines(std::u32string_view para) {
        const std::size_t n = para.size();
        if (style_.max_width > 0)
            text_detail::line_break_opportunities(para, style_.language, breaks_);
        else
            breaks_.assign(n + 1, 0);
        ranges_.clear();
        std::size_t line_begin = 0;
        double width = 0;  // of the line so far, trailing spaces of earlier words included
        std::size_t s = 0;
        while (s < n) {
            std::size_t e = s + 1;  // the word [s, e): up to the next break opportunity
            while (e < n && !(cluster_start_[e] && breaks_[e])) ++e;
            std::size_t ink_end = e;
            while (ink_end > s && is_break_space(para[ink_end - 1])) --ink_end;
            double w_ink = 0, w_space = 0;
            for (std::size_t i = s; i < ink_end; ++i) w_ink += adv_[i];
            for (std::size_t i = ink_end; i < e; ++i) w_space += adv_[i];
            if (style_.max_width > 0 && s > line_begin && width + w_ink > style_.max_width) {
                ranges_.push_back({line_begin, s});
                line_begin = s;
                width = 0;
            }
            width += w_ink + w_space;
            s = e;
        }
        ranges_.push_back({line_begin, n});
    }

    // One line: the runs' glyphs in it (trailing spaces dropped: they hang, rule L1) in visual
    // order, placed along the baseline. `pos`: the paragraph's first code point in the text.
    void line(std::u32string_view para, const LineRange& lr, std::size_t pos, bool rtl) {
        std::size_t ink_end = lr.end;
        while (ink_end > lr.begin && is_break_space(para[ink_end - 1])) --ink_end;
        pieces_.clear();
        piece_levels_.clear();
        for (const ShapedRun& r : runs_) {
            if (r.end <= lr.begin || r.begin >= ink_end) continue;
            std::size_t g0 = r.glyphs.size(), g1 = 0;
            for (std::size_t g = 0; g < r.glyphs.size(); ++g) {
                const std::uint32_t c = r.glyphs[g].cluster;
                if (c >= lr.begin && c < ink_end) {
                    g0 = std::min(g0, g);
                    g1 = std::max(g1, g + 1);
                }
            }
            if (g0 >= g1) continue;
            pieces_.push_back({&r, g0, g1});
            piece_levels_.push_back(r.level);
        }
        bidi_visual_order(piece_levels_, order_);

        TextLine line;
        line.rtl = rtl;
        line.first_glyph = L_.glyphs.size();
        line.baseline = baseline();
        line.text_begin = pos + lr.begin;
        line.text_end = pos + lr.end;
        double pen = 0;
        for (std::size_t oi : order_) {
            const Piece& p = pieces_[oi];
            for (std::size_t g = p.g0; g < p.g1; ++g) {
                const ShapedGlyph& sg = p.run->glyphs[g];
                // A glyph inside the range whose cluster falls outside (cannot happen with
                // monotone clusters) is skipped rather than drawn twice.
                if (sg.cluster < lr.begin || sg.cluster >= ink_end) continue;
                PositionedGlyph pg;
                pg.glyph = sg.glyph;
                pg.font = sg.font;
                pg.cluster = static_cast<std::uint32_t>(pos + sg.cluster);
                pg.position = {pen + sg.x_offset, line.baseline - sg.y_offset};
                L_.glyphs.push_back(pg);
                pen += sg.advance;
            }
        }
        line.glyph_count = L_.glyphs.size() - line.first_glyph;
        line.width = pen;
        L_.lines.push_back(line);
    }

    TextLayout& L_;
    text_detail::Shaper& shaper_;
    const TextStyle& style_;
    double ascender_ = 0, line_advance_ = 0;
    std::u32string work_;
    std::vector<std::uint8_t> levels_;
    std::vector<ShapedRun> runs_;
    std::vector<double> adv_;
    std::vector<char> cluster_start_;
    std::vector<char> breaks_;
    std::vector<LineRange> ranges_;
    std::vector<std::uint8_t> piece_levels_;
    std::vector<std::size_t> order_;
    std::vector<Piece> pieces_;
};

// Moves each line to its alignment within the layout's width (the wrap width, else the widest
// line).
void align_lines(TextLayout& L, const TextStyle& style) {
    double widest = 0;
    for (const TextLine& l : L.lines) widest = std::max(widest, l.width);
    L.width = style.max_width > 0 ? style.max_width : widest;
    for (TextLine& l : L.lines) {
        TextAlign a = style.align;
        if (a == TextAlign::Start) a = l.rtl ? TextAlign::Right : TextAlign::Left;
        double x = 0;
        if (a == TextAlign::Center)
            x = (L.width - l.width) / 2;
        else if (a == TextAlign::Right)
            x = L.width - l.width;
        l.x = x;
        for (std::size_t g = l.first_glyph; g < l.first_glyph + l.glyph_count; ++g) L.glyphs[g].position.x += x;
    }
}

// The union of the glyphs' ink boxes (glyph bounds memoized per font and glyph).
void ink_bounds(TextLayout& L, const TextStyle& style) {
    std::unordered_map<std::uint64_t, Rect> glyph_bounds;
    bool have_ink = false;
    for (const PositionedGlyph& g : L.glyphs) {
        const std::uint64_t key = static_cast<std::uint64_t>(g.font) << 32 | g.glyph;
        auto it = glyph_bounds.find(key);
        if (it == glyph_bounds.end()) {
            const Font& font = *L.fonts[g.font];
            const bool color = text_detail::color_glyph_kind(font, g.glyph) != text_detail::ColorGlyphKind::None;
            it = glyph_bounds
                     .emplace(key, color ? text_detail::color_glyph_bounds(font, g.glyph)
                                         : font.glyph_metrics(g.glyph).bounds)
                     .first;
        }
        const Rect& b = it->second;
        if (b.empty()) continue;
        const double s = style.size / L.fonts[g.font]->units_per_em();
        const Rect r{g.position.x + b.x0 * s, g.position.y - b.y1 * s, g.position.x + b.x1 * s,
                     g.position.y - b.y0 * s};
        L.ink = have_ink ? L.ink.united(r) : r;
        have_ink = true;
    }
}

}  // namespace

TextLayout layout_text(std::string_view utf8, std::span<const Font* const> fonts, const TextStyle& style) {
    check_layout_arguments(utf8, fonts, style);
    TextLayout L;
    L.fonts.assign(fonts.begin(), fonts.end());
    L.size = style.size;
    L.text = decode_utf8(utf8);
    if (L.text.empty()) return L;

    std::unique_ptr<text_detail::SystemFallback> fallback;
    if (style.system_fonts) fallback = std::make_unique<text_detail::SystemFallback>(*fonts[0], style.language);
    text_detail::Shaper shaper(fonts, style, false, fallback.get());
    const FontMetrics& fm = fonts[0]->metrics();
    Paragraphs(L, shaper, style, fm).run();
    L.fonts = shaper.fonts();
    if (fallback) L.system_fonts.assign(fallback->fonts().begin(), fallback->fonts().end());

    align_lines(L, style);
    const double scale = style.size / fm.units_per_em;
    const double ascender = fm.ascender * scale, descender = fm.descender * scale;
    const double line_advance = style.line_height * fm.line_spacing() * scale;
    L.height = L.lines.empty() ? 0 : ascender - descender + static_cast<double>(L.lines.size() - 1) * line_advance;
    ink_bounds(L, style);
    return L;
}

}  // namespace casteljau
