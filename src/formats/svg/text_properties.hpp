// Internal (formats): the text properties of SVG text elements and the input text conversion
// builds for the layout (text_layout.hpp). text.cpp walks a text element and its tspan, tref, textPath
// and a children; text_properties.cpp reads the font and text properties each of them sets.
// Thread-safety: plain functions and values.
#pragma once

#include <pugixml.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "formats/svg/context.hpp"
#include "formats/svg/text_layout.hpp"

namespace casteljau::svg {

// Computed text properties along the text/tspan tree.
struct TextCtx {
    svg_text::FontSpec font;
    bool small_caps = false, no_kerning = false;
    std::vector<std::string> feature_settings;
    double letter_spacing = 0, word_spacing = 0;
    svg_text::Anchor anchor = svg_text::Anchor::Start;
    svg_text::Baseline dominant = svg_text::Baseline::Alphabetic;
    svg_text::Baseline baseline = svg_text::Baseline::Alphabetic;  // alignment-baseline or dominant
    std::vector<svg_text::Span::Shift> baseline_shifts;
    bool preserve = false;
    std::vector<svg_text::Decoration> decorations;
    int path = -1, path_element = -1;
    std::size_t style = 0;
    std::string direction;
    double viewport_width = 100;  // percentages of letter- and word-spacing (as resvg)
};

// The style index of decorations declared outside the text element: they take the text's own style.
inline constexpr std::size_t kTextElementStyle = static_cast<std::size_t>(-1);

// The layout input of one text element as its children are walked, with the elements that carry
// position lists (x, y, dx, dy, rotate, textLength).
struct TextBuild {
    svg_text::TextInput in;
    std::vector<Style> styles;
    struct Range {
        pugi::xml_node node;
        std::size_t begin = 0, end = 0;
        double font_size = 12;
    };
    std::vector<Range> ranges;  // elements with position lists, in document order
    std::size_t chars = 0;
    bool last_space = true;       // collapsing: the text so far ends in a space (or is empty)
    bool last_preserved = false;  // the last character came from xml:space="preserve" text
    bool truncated = false;
    int path_elements = 0;
};

// text_properties.cpp
// The words of a list separated by white space or commas.
std::vector<std::string_view> split_list(std::string_view v);
// A length for text properties: em and ex relative to `font_size`, percentages of `percent_of`,
// physical units at `dpi` pixels per inch.
std::optional<double> text_length(std::string_view v, double font_size, double percent_of, double dpi);
// A font family name, a generic family (serif, sans-serif, ...) replaced by the options' choice.
std::string generic_family(const Context& cx, std::string_view f);
void apply_font_family(const Context& cx, std::string_view v, TextCtx& ctx);
// font-feature-settings and font-variation-settings: a comma-separated list of a quoted tag
// and an optional value ("'liga' 0, 'smcp'"), as (tag, value) pairs without the quotes.
std::vector<std::pair<std::string, std::string>> tag_value_list(std::string_view v);
std::optional<int> font_weight(std::string_view v, int parent);
std::optional<double> font_stretch(std::string_view v);
// A font-size value: keywords, lengths (physical units at `dpi`), percentages of `parent`.
std::optional<double> font_size(std::string_view v, double parent, double dpi);
svg_text::Baseline baseline_kind(std::string_view v, svg_text::Baseline fallback);
// The `font` shorthand: [style] [variant] [weight] [stretch] size[/line-height] family-list.
void apply_font_shorthand(const Context& cx, std::string_view v, TextCtx& ctx, double parent_size);
// Applies the text properties `node` sets itself to `ctx` (inherited ones carry on to children).
void apply_text_props(Context& cx, const pugi::xml_node& node, TextCtx& ctx);

}  // namespace casteljau::svg
