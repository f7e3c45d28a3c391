// C API: the process-wide resource limits (casteljau.h, casteljau_limits_*), a copy of
// casteljau::Limits field for field.
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "capi/handles.hpp"
#include "casteljau/limits.hpp"

using namespace casteljau;
using casteljau::capi::guard;

namespace {

// Calls f(c-field, c++-field) for every field, in the order of casteljau_limits.
template <class C, class L, class F>
void each_field(C& c, L& l, F&& f) {
    f(c.canvas_dimension, l.canvas_dimension);
    f(c.canvas_pixels, l.canvas_pixels);
    f(c.path_points, l.path_points);
    f(c.flattened_segments, l.flattened_segments);
    f(c.nesting_depth, l.nesting_depth);
    f(c.svg_elements, l.svg_elements);
    f(c.svg_image_nesting, l.svg_image_nesting);
    f(c.svgz_bytes, l.svgz_bytes);
    f(c.css_rules, l.css_rules);
    f(c.svg_text_chars, l.svg_text_chars);
    f(c.filter_pixels, l.filter_pixels);
    f(c.filter_primitives, l.filter_primitives);
    f(c.map_positions, l.map_positions);
    f(c.dashes, l.dashes);
    f(c.font_file_bytes, l.font_file_bytes);
    f(c.png_chunk_bytes, l.png_chunk_bytes);
    f(c.png_ancillary_chunks, l.png_ancillary_chunks);
    f(c.jpeg_working_memory, l.jpeg_working_memory);
    f(c.canvas_save_depth, l.canvas_save_depth);
    f(c.text_bytes, l.text_bytes);
    f(c.input_bytes, l.input_bytes);
    f(c.exact_work, l.exact_work);
}

// A size the caller's struct may have: a whole number of leading fields (some prefix of the
// fields ends exactly there, padding after the last one included).
bool valid_size(std::size_t size) {
    if (size == 0 || size > sizeof(casteljau_limits)) return false;
    if (size == sizeof(casteljau_limits)) return true;
    casteljau_limits c{};
    Limits l;
    bool ok = false;
    each_field(c, l, [&](auto& field, auto&) {
        const std::size_t end =
            reinterpret_cast<const char*>(&field) - reinterpret_cast<const char*>(&c) + sizeof field;
        if (end == size) ok = true;
    });
    return ok;
}

// Values the C struct's type can hold; larger C++ values (none today) would saturate.
template <class To, class From>
To narrow(From v) {
    if (std::cmp_greater(v, std::numeric_limits<To>::max())) return std::numeric_limits<To>::max();
    if (std::cmp_less(v, std::numeric_limits<To>::min())) return std::numeric_limits<To>::min();
    return static_cast<To>(v);
}

casteljau_limits to_c(Limits l) {
    casteljau_limits c{};
    each_field(c, l, [](auto& cf, auto& lf) { cf = narrow<std::remove_reference_t<decltype(cf)>>(lf); });
    return c;
}

}  // namespace

extern "C" {

casteljau_status casteljau_limits_get(casteljau_limits* out, size_t size) {
    return guard([&] {
        casteljau::capi::need(out, "limits");
        if (!valid_size(size))
            throw Error(ErrorKind::InvalidArgument, "casteljau_limits_get: size is not a casteljau_limits size");
        const casteljau_limits c = to_c(current_limits());
        std::memcpy(out, &c, size);
    });
}

casteljau_status casteljau_limits_set(const casteljau_limits* limits, size_t size) {
    return guard([&] {
        casteljau::capi::need(limits, "limits");
        if (!valid_size(size))
            throw Error(ErrorKind::InvalidArgument, "casteljau_limits_set: size is not a casteljau_limits size");
        // The caller's prefix over the limits in force.
        Limits l = current_limits();
        casteljau_limits c = to_c(l);
        std::memcpy(&c, limits, size);
        each_field(c, l, [](auto& cf, auto& lf) {
            using T = std::remove_reference_t<decltype(lf)>;
            // A value beyond the C++ field's range is past its ceiling: pass the field's maximum
            // on so that set_limits names the field.
            lf = narrow<T>(cf);
        });
        set_limits(l);
    });
}

void casteljau_limits_reset(void) { reset_limits(); }

}  // extern "C"
