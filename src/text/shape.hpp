// Text stage, internal: itemization into runs and HarfBuzz shaping of one paragraph, the
// implementation of TextShaper (casteljau/shaping.hpp), used directly by layout_text.
//
// A run is a maximal range of code points with one bidi level, one script and one font of the
// fallback chain. Each run is shaped with the whole paragraph as context (so Arabic joining and
// kerning see across run edges), in the run's direction; its glyphs come out in visual order.
#pragma once

#include <hb.h>

#include <cstdint>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "casteljau/font.hpp"
#include "casteljau/shaping.hpp"
#include "casteljau/text.hpp"

namespace casteljau::text_detail {

class SystemFallback;

class Shaper {
public:
    // Validates the style's script, language and features (Error(Parse)). `vertical`: shape top to
    // bottom (HarfBuzz's TTB direction, vertical metrics and the 'vert' feature) instead of by the
    // bidi levels; glyphs then advance by y_advance. `fallback`: where a cluster no font of the
    // chain has finds one (null: nowhere, it shows the first font's .notdef); the fonts it gives
    // are appended to fonts() as they are first used.
    Shaper(std::span<const Font* const> fonts, const TextStyle& style, bool vertical = false,
           SystemFallback* fallback = nullptr);
    ~Shaper();
    Shaper(const Shaper&) = delete;
    Shaper& operator=(const Shaper&) = delete;

    // Shapes `para` (tabs already replaced) with the given bidi levels into `runs` (logical order).
    void shape_paragraph(std::u32string_view para, std::span<const std::uint8_t> levels, std::vector<ShapedRun>& runs);

    // The chain followed by the fallback fonts used so far: ShapedGlyph::font indexes it.
    const std::vector<const Font*>& fonts() const { return fonts_; }

private:
    // A fallback font (its index in fonts()) that has `cluster`, or kNoFont.
    static constexpr std::size_t kNoFont = SIZE_MAX;
    std::size_t fallback_font(std::u32string_view cluster);

    std::vector<const Font*> fonts_;
    std::size_t chain_size_ = 0;
    SystemFallback* fallback_ = nullptr;
    double size_;
    bool vertical_ = false;
    hb_buffer_t* buf_ = nullptr;
    std::vector<hb_feature_t> features_;
    hb_script_t script_override_ = HB_SCRIPT_INVALID;
    hb_language_t language_ = HB_LANGUAGE_INVALID;
    std::vector<std::uint16_t> font_of_;
    std::vector<hb_script_t> script_of_;
};

}  // namespace casteljau::text_detail
