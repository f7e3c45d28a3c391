// Formats stage, internal: SVG filters. Reads a <filter> element (with its href chain) and its
// primitives into a filter::FilterGraph for one filtered element, and the `filter` property
// (url() references and the CSS filter functions) into a list of steps. The SVG reader
// (filters.cpp) supplies what it alone knows through SvgFilterEnv: the cascade, ids, lengths and the
// content of feImage.
// Coordinates: the graph is in the filtered element's user space. Thread-safety: plain functions.
#pragma once

#include <pugixml.hpp>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/filter.hpp"
#include "formats/svg/values.hpp"

namespace casteljau::svg_filter {

struct SvgFilterEnv {
    // The cascaded value of `name` on the node ("" when unset or `inherit`), and the inherited one.
    std::function<std::string(const pugi::xml_node&, const std::string&)> property;
    std::function<std::string(const pugi::xml_node&, const std::string&)> inherited;
    std::function<pugi::xml_node(std::string_view)> lookup;  // by id
    // A length with units ("" or invalid: nullopt); percentages against `percent_of`.
    std::function<std::optional<double>(std::string_view, double)> length;
    std::function<Color(std::string_view)> color;  // a CSS colour (currentColor resolved); throws when invalid
    // The content of an feImage (an image or a referenced element), drawn in the filtered element's
    // user space; empty when there is nothing to draw. `subregion` is the primitive's subregion.
    std::function<std::function<void(Pixmap&, const Affine&)>(const pugi::xml_node&, const Rect& subregion)> image;
    svg::Viewport viewport;  // for userSpaceOnUse percentages
    Color current_color = Color::black();
};

// One entry of the `filter` property: a url(#id) or a CSS filter function with its arguments.
struct FilterRef {
    std::string url;                // the id, for url()
    std::string function;           // the function name otherwise
    std::vector<std::string> args;  // its arguments, split at top-level spaces and commas
    bool commas = false;            // a top-level comma separated them (invalid in every filter function)
};

// Splits a `filter` value; nullopt when it is malformed (the property is then ignored).
std::optional<std::vector<FilterRef>> parse_filter_property(std::string_view value);

// The graph of filter `f` applied to an element whose bounding box (user units) is `bbox`;
// nullopt when the filter is invalid and the element must not be drawn.
std::optional<filter::FilterGraph> build_filter(const pugi::xml_node& f, const std::optional<Rect>& bbox,
                                                const SvgFilterEnv& env);

// The graph of one CSS filter function (grayscale(), blur(), drop-shadow(), ...); nullopt when
// its arguments are invalid.
std::optional<filter::FilterGraph> build_function(const FilterRef& fn, const std::optional<Rect>& bbox,
                                                  const SvgFilterEnv& env);

}  // namespace casteljau::svg_filter
