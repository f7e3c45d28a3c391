// Internal (formats): the value syntaxes SVG filters read (numbers, number lists, fractions)
// and the colour matrices of feColorMatrix and the CSS filter functions, shared by
// filter_graphs.cpp and filter_functions.cpp.
// Thread-safety: plain functions.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace casteljau::svg_filter {

// `s` without leading and trailing white space.
std::string_view trim(std::string_view s);

// Whitespace- and comma-separated numbers; nullopt when any item is not a finite number.
std::optional<std::vector<double>> numbers(std::string_view s);

// Exactly one number; nullopt otherwise.
std::optional<double> number(std::string_view s);

// A number or a percentage (as a fraction), for objectBoundingBox units.
std::optional<double> fraction(std::string_view s);

// feColorMatrix's matrices (5 x 4, row-major): the identity, saturate, hueRotate (in degrees) and
// luminanceToAlpha.
std::array<double, 20> identity_matrix();
std::array<double, 20> saturate_matrix(double s);
std::array<double, 20> hue_rotate_matrix(double degrees);
std::array<double, 20> luminance_to_alpha_matrix();

}  // namespace casteljau::svg_filter
