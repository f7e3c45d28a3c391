// Text stage, shaping: itemization (script, font fallback) and HarfBuzz (src/text/shape.hpp,
// include/casteljau/shaping.hpp).
#include "text/shape.hpp"

#include <hb-ft.h>

#include <memory>
#include <string>
#include <utility>

#include "casteljau/error.hpp"
#include "text/font_fallback.hpp"
#include "text/font_impl.hpp"

namespace casteljau::text_detail {

namespace {

bool is_mark(hb_unicode_general_category_t cat) {
    return cat == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK || cat == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
           cat == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

// Characters that belong with the character before them whatever the fonts say: joiners, variation
// selectors and other default-ignorable format characters.
bool is_attached_format(char32_t c) {
    return c == 0x200c || c == 0x200d || (c >= 0xfe00 && c <= 0xfe0f) || (c >= 0xe0100 && c <= 0xe01ef) ||
           c == 0x034f || (c >= 0x180b && c <= 0x180d) || c == 0x2060 || c == 0xfeff;
}

bool is_weak_script(hb_script_t s) {
    return s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN;
}

bool is_regional_indicator(char32_t c) { return c >= 0x1f1e6 && c <= 0x1f1ff; }

// End of the cluster that starts at para[i], for choosing its font: the base, its marks, joiners,
// variation selectors, tags and skin-tone modifiers, the character after each zero-width joiner,
// and the second of a pair of regional indicators (a flag).
std::size_t cluster_end(std::u32string_view para, std::size_t i, hb_unicode_funcs_t* uf) {
    const std::size_t n = para.size();
    std::size_t e = i + 1;
    if (is_regional_indicator(para[i]) && e < n && is_regional_indicator(para[e])) return e + 1;
    while (e < n) {
        const char32_t c = para[e];
        if (c == 0x200d && e + 1 < n) {
            e += 2;
        } else if (is_mark(hb_unicode_general_category(uf, c)) || is_attached_format(c) ||
                   (c >= 0xe0020 && c <= 0xe007f) || (c >= 0x1f3fb && c <= 0x1f3ff)) {
            ++e;
        } else {
            break;
        }
    }
    return e;
}

}  // namespace

Shaper::Shaper(std::span<const Font* const> fonts, const TextStyle& style, bool vertical, SystemFallback* fallback)
    : fonts_(fonts.begin(), fonts.end()),
      chain_size_(fonts.size()),
      fallback_(fallback),
      size_(style.size),
      vertical_(vertical) {
    for (const std::string& f : style.features) {
        hb_feature_t feat;
        if (!hb_feature_from_string(f.c_str(), static_cast<int>(f.size()), &feat))
            throw Error(ErrorKind::Parse, "invalid font feature '" + f + "' (expected e.g. kern=0, liga, +smcp)");
        features_.push_back(feat);
    }
    if (!style.script.empty()) {
        bool ok = style.script.size() == 4;
        for (char c : style.script) ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'));
        if (!ok)
            throw Error(ErrorKind::Parse,
                        "invalid script '" + style.script + "' (expected an ISO 15924 tag like Latn, Arab, Hebr)");
        script_override_ = hb_script_from_string(style.script.c_str(), 4);
        if (script_override_ == HB_SCRIPT_INVALID || script_override_ == HB_SCRIPT_UNKNOWN)
            throw Error(ErrorKind::Parse, "unknown script '" + style.script + "'");
    }
    if (!style.language.empty()) {
        for (char c : style.language)
            if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'))
                throw Error(ErrorKind::Parse,
                            "invalid language tag '" + style.language + "' (expected BCP 47, e.g. en, ar, tr)");
        language_ = hb_language_from_string(style.language.c_str(), static_cast<int>(style.language.size()));
    }
    buf_ = hb_buffer_create();
    if (!hb_buffer_allocation_successful(buf_)) {
        hb_buffer_destroy(buf_);
        throw std::bad_alloc();
    }
}

Shaper::~Shaper() { hb_buffer_destroy(buf_); }

std::size_t Shaper::fallback_font(std::u32string_view cluster) {
    const Font* f = fallback_ ? fallback_->find(cluster) : nullptr;
    if (!f) return kNoFont;
    for (std::size_t k = chain_size_; k < fonts_.size(); ++k)
        if (fonts_[k] == f) return k;
    if (fonts_.size() >= 0xffff) return kNoFont;
    fonts_.push_back(f);
    return fonts_.size() - 1;
}

void Shaper::shape_paragraph(std::u32string_view para, std::span<const std::uint8_t> levels,
                             std::vector<ShapedRun>& runs) {
    runs.clear();
    const std::size_t n = para.size();
    if (n == 0) return;
    hb_unicode_funcs_t* uf = hb_unicode_funcs_get_default();
    const std::size_t nfonts = chain_size_;

    // Fonts: each character from the first font of the chain that has it; marks, joiners and weak
    // characters (spaces, punctuation) stay with the previous character's font when it has them
    // (unless that character is an emoji: text after it goes back to the text fonts). A cluster
    // whose first character no font of the chain has takes a fallback font that has the whole
    // cluster.
    font_of_.assign(n, 0);
    script_of_.assign(n, HB_SCRIPT_COMMON);
    for (std::size_t i = 0; i < n; ++i) script_of_[i] = hb_unicode_script(uf, para[i]);
    bool after_emoji = false;
    for (std::size_t i = 0; i < n; ++i) {
        const char32_t c = para[i];
        const bool attach = is_mark(hb_unicode_general_category(uf, c)) || is_attached_format(c);
        const bool weak = attach || is_weak_script(script_of_[i]);
        if (i > 0 && is_attached_format(c)) {
            font_of_[i] = font_of_[i - 1];
            continue;
        }
        const bool keep = !after_emoji || attach;
        after_emoji = false;
        if (i > 0 && weak && keep && fonts_[font_of_[i - 1]]->has_glyph(c)) {
            font_of_[i] = font_of_[i - 1];
            continue;
        }
        std::size_t f = 0;
        while (f < nfonts && !fonts_[f]->has_glyph(c)) ++f;
        if (f == nfonts && fallback_ && !(i > 0 && attach)) {
            const std::size_t e = cluster_end(para, i, uf);
            const std::size_t found = fallback_font(para.substr(i, e - i));
            if (found != kNoFont) {
                f = found;
                for (std::size_t k = i; k < e; ++k) font_of_[k] = static_cast<std::uint16_t>(f);
                after_emoji = is_emoji_cluster(para.substr(i, e - i));
                i = e - 1;
                continue;
            }
        }
        if (f == nfonts) f = (i > 0 && weak) ? font_of_[i - 1] : 0;  // nobody has it: .notdef
        font_of_[i] = static_cast<std::uint16_t>(f);
    }
    // Scripts: common and inherited characters take the script before them (after them at the start).
    hb_script_t first = HB_SCRIPT_COMMON;
    for (std::size_t i = 0; i < n; ++i)
        if (!is_weak_script(script_of_[i])) {
            first = script_of_[i];
            break;
        }
    hb_script_t cur = first;
    for (std::size_t i = 0; i < n; ++i) {
        if (is_weak_script(script_of_[i]))
            script_of_[i] = cur;
        else
            cur = script_of_[i];
    }

    const hb_language_t lang = language_ != HB_LANGUAGE_INVALID ? language_ : hb_language_get_default();
    for (std::size_t b = 0; b < n;) {
        std::size_t e = b + 1;
        while (e < n && levels[e] == levels[b] && font_of_[e] == font_of_[b] && script_of_[e] == script_of_[b]) ++e;
        ShapedRun run;
        run.begin = static_cast<std::uint32_t>(b);
        run.end = static_cast<std::uint32_t>(e);
        run.level = levels[b];
        run.font = font_of_[b];
        const Font& font = *fonts_[run.font];

        hb_buffer_clear_contents(buf_);
        hb_buffer_add_utf32(buf_, reinterpret_cast<const std::uint32_t*>(para.data()), static_cast<int>(n),
                            static_cast<unsigned>(b), static_cast<int>(e - b));
        hb_buffer_set_direction(buf_, vertical_         ? HB_DIRECTION_TTB
                                      : (run.level & 1) ? HB_DIRECTION_RTL
                                                        : HB_DIRECTION_LTR);
        hb_buffer_set_script(buf_, script_override_ != HB_SCRIPT_INVALID ? script_override_ : script_of_[b]);
        hb_buffer_set_language(buf_, lang);
        unsigned flags = HB_BUFFER_FLAG_DEFAULT;
        if (b == 0) flags |= HB_BUFFER_FLAG_BOT;
        if (e == n) flags |= HB_BUFFER_FLAG_EOT;
        hb_buffer_set_flags(buf_, static_cast<hb_buffer_flags_t>(flags));
        hb_shape(font.impl().hb, buf_, features_.data(), static_cast<unsigned>(features_.size()));
        if (!hb_buffer_allocation_successful(buf_)) throw std::bad_alloc();

        unsigned count = 0;
        const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf_, &count);
        const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf_, &count);
        // HarfBuzz positions are in 1/64 font units (the face is sized at units_per_em px).
        const double k = size_ / (font.units_per_em() * kUnits26_6);
        run.glyphs.resize(count);
        for (unsigned g = 0; g < count; ++g) {
            ShapedGlyph& sg = run.glyphs[g];
            sg.glyph = info[g].codepoint;
            sg.font = run.font;
            sg.cluster = info[g].cluster;
            sg.advance = pos[g].x_advance * k;
            sg.x_offset = pos[g].x_offset * k;
            sg.y_offset = pos[g].y_offset * k;
            sg.y_advance = pos[g].y_advance * k;
        }
        runs.push_back(std::move(run));
        b = e;
    }
}

}  // namespace casteljau::text_detail

namespace casteljau {

struct SystemFontFallback::Impl {
    Impl(const Font& base, std::string language) : fallback(base, std::move(language)) {}
    text_detail::SystemFallback fallback;
};

SystemFontFallback::SystemFontFallback(const Font& base, std::string language)
    : impl_(std::make_unique<Impl>(base, std::move(language))) {}

SystemFontFallback::~SystemFontFallback() = default;

class TextShaper::Impl : public text_detail::Shaper {
public:
    using Shaper::Shaper;
};

TextShaper::TextShaper(std::span<const Font* const> fonts, const TextStyle& style, bool vertical,
                       SystemFontFallback* system)
    : impl_(std::make_unique<Impl>(fonts, style, vertical, system ? &system->impl_->fallback : nullptr)) {}

TextShaper::~TextShaper() = default;

const std::vector<const Font*>& TextShaper::fonts() const { return impl_->fonts(); }

void TextShaper::shape_paragraph(std::u32string_view paragraph, std::span<const std::uint8_t> levels,
                                 std::vector<ShapedRun>& runs) {
    impl_->shape_paragraph(paragraph, levels, runs);
}

bool letter_spacing_allowed(char32_t c) {
    switch (hb_unicode_script(hb_unicode_funcs_get_default(), c)) {
        case HB_SCRIPT_ARABIC:
        case HB_SCRIPT_SYRIAC:
        case HB_SCRIPT_NKO:
        case HB_SCRIPT_MANICHAEAN:
        case HB_SCRIPT_PSALTER_PAHLAVI:
        case HB_SCRIPT_MANDAIC:
        case HB_SCRIPT_MONGOLIAN:
        case HB_SCRIPT_PHAGS_PA:
        case HB_SCRIPT_DEVANAGARI:
        case HB_SCRIPT_BENGALI:
        case HB_SCRIPT_GURMUKHI:
        case HB_SCRIPT_MODI:
        case HB_SCRIPT_SHARADA:
        case HB_SCRIPT_SYLOTI_NAGRI:
        case HB_SCRIPT_TIRHUTA:
        case HB_SCRIPT_OGHAM: return false;
        default: return true;
    }
}

}  // namespace casteljau
