// Internal (text module): fonts found through the system's font configuration (fontconfig) for
// character clusters that no font of a layout's chain can show.
//
// A query is the base font's family (or the generic family "emoji" for clusters in emoji
// presentation), a language (the style's, else none), the base font's weight and slant. fontconfig
// sorts every installed face for it once per process; a cluster then takes the first face of that
// list whose character set holds all its code points (default-ignorable ones excepted), and the
// answer is remembered per (query, cluster), also on disk for later processes
// (src/text/fallback_cache.hpp): fontconfig is started only for a cluster with no answer there
// (or whose face no longer loads or maps it). The caches are process-wide and guarded by a mutex;
// each layout loads its own Fonts of the faces it uses (a Font serves one thread at a time; the
// files are mapped, so a face costs its tables' parsing, not a copy).
#pragma once

#include <hb.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/font.hpp"

namespace casteljau::text_detail {

// Code points a cluster may carry that fonts need not map: joiners, variation selectors, tags.
bool is_fallback_ignorable(char32_t c);
// Whether a cluster starting with `c` and holding `cluster` shows as emoji: Emoji_Presentation,
// an emoji variation selector (U+FE0F), a skin-tone modifier or a keycap.
bool is_emoji_cluster(std::u32string_view cluster);

class SystemFallback {
public:
    // `base`: the font whose family, weight and slant the fallback fonts should match;
    // `language`: a BCP 47 tag or "".
    SystemFallback(const Font& base, std::string language);
    ~SystemFallback();
    SystemFallback(const SystemFallback&) = delete;
    SystemFallback& operator=(const SystemFallback&) = delete;

    // A font that maps every code point of `cluster`, or null. The font lives as long as this
    // object (or longer: see take_fonts); the same face is returned for every cluster it serves.
    const Font* find(std::u32string_view cluster);
    // The fonts found so far, in the order they were first returned.
    const std::vector<std::shared_ptr<Font>>& fonts() const { return fonts_; }

private:
    // This layout's Font for a face (loaded on first use); null when it cannot be loaded, or when
    // `must_map` is given and the face lacks one of its code points (an answer kept on disk).
    const Font* font_for(const std::string& file, int index, const std::u32string* must_map = nullptr);

    std::string family_, language_;
    int weight_ = 400;
    bool italic_ = false;
    std::vector<std::shared_ptr<Font>> fonts_;
    std::vector<std::pair<std::string, int>> font_ids_;  // (file, face index) of fonts_[i]
};

}  // namespace casteljau::text_detail
