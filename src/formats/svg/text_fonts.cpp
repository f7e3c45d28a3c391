// Formats stage, SVG text: the fonts of a document's text (FontSet, text_layout.hpp): faces
// opened once per variation, family lists matched with fallback faces for missing characters, and
// the system's fallback fonts.
#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/error.hpp"
#include "formats/svg/text_layout.hpp"

namespace casteljau::svg_text {

namespace {

// What tells apart the instances of a variable face: the style's weight, width, size, slant and
// variations.
std::string variation_key(const FontSpec& spec) {
    std::string k = std::to_string(spec.weight) + "/" + std::to_string(spec.stretch) + "/" + std::to_string(spec.size) +
                    "/" + std::to_string(static_cast<int>(spec.slant));
    for (const Variation& v : spec.variations) k += "/" + v.tag + "=" + std::to_string(v.value);
    return k;
}

}  // namespace

const Font* FontSet::face(std::size_t index, const FontSpec& spec) {
    if (std::find(broken_.begin(), broken_.end(), index) != broken_.end()) return nullptr;
    const FontFaceInfo& info = db_->faces()[index];
    const std::string key = info.variable || !spec.variations.empty() ? variation_key(spec) : std::string();
    auto& slot = fonts_[{index, key}];
    if (slot) return slot.get();
    try {
        auto font = std::make_shared<Font>(db_->open(index));
        if (font->is_variable()) {
            // The weight and width the style asks for, then font-variation-settings over them.
            std::vector<Variation> vars;
            for (const VariationAxis& a : font->axes()) {
                if (a.tag == "wght") vars.push_back({"wght", static_cast<double>(spec.weight)});
                if (a.tag == "wdth") vars.push_back({"wdth", spec.stretch});
                if (a.tag == "opsz") vars.push_back({"opsz", spec.size});  // font-optical-sizing: auto
            }
            for (const Variation& v : spec.variations) {
                const bool known = std::any_of(font->axes().begin(), font->axes().end(),
                                               [&](const VariationAxis& a) { return a.tag == v.tag; });
                if (!known) continue;
                std::erase_if(vars, [&](const Variation& o) { return o.tag == v.tag; });
                vars.push_back(v);
            }
            if (!vars.empty()) font->set_variations(vars);
        }
        slot = std::move(font);
    } catch (const Error&) {
        broken_.push_back(index);
        fonts_.erase({index, key});
        return nullptr;
    }
    return slot.get();
}

std::vector<const Font*> FontSet::chain(const FontSpec& spec, std::u32string_view text) {
    std::vector<const Font*> out;
    std::vector<std::size_t> used;
    auto add = [&](std::size_t idx) {
        if (std::find(used.begin(), used.end(), idx) != used.end()) return;
        if (const Font* f = face(idx, spec)) {
            used.push_back(idx);
            out.push_back(f);
        }
    };
    for (const std::string& fam : spec.families)
        if (auto idx = db_->match(fam, spec.weight, spec.slant, spec.stretch)) add(*idx);
    for (char32_t c : text) {
        if (c < 0x20 || c == 0x200b || c == 0x200c || c == 0x200d || (c >= 0xfe00 && c <= 0xfe0f)) continue;
        if (std::any_of(out.begin(), out.end(), [&](const Font* f) { return f->has_glyph(c); })) continue;
        if (auto idx = db_->fallback(c, spec.weight, spec.slant, spec.stretch, !system_fallback_)) add(*idx);
    }
    return out;
}

std::shared_ptr<const Font> FontSet::shared(const Font* font) const {
    for (const auto& [key, f] : fonts_)
        if (f.get() == font) return f;
    return nullptr;
}

SystemFontFallback* FontSet::system(const Font& base) {
    if (!system_fallback_) return nullptr;
    std::unique_ptr<SystemFontFallback>& slot = system_[&base];
    if (!slot) slot = std::make_unique<SystemFontFallback>(base, std::string());
    return slot.get();
}

}  // namespace casteljau::svg_text
