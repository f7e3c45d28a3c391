// Internal (formats): href links between SVG elements (gradients, patterns and filters inherit
// attributes and content along them).
// Thread-safety: plain functions.
#pragma once

#include <pugixml.hpp>

#include <functional>
#include <initializer_list>
#include <string_view>
#include <vector>

namespace casteljau::svg {

// An element's link: `href`, which takes precedence, else `xlink:href` (SVG 2); "" when neither.
const char* href(const pugi::xml_node& n);

// `first` and the elements its chain of "#id" links reaches through `lookup`, while each is named
// one of `names` and none repeats (a cycle ends the chain), at most 32 long.
std::vector<pugi::xml_node> href_chain(const pugi::xml_node& first,
                                       const std::function<pugi::xml_node(std::string_view)>& lookup,
                                       std::initializer_list<std::string_view> names);

}  // namespace casteljau::svg
