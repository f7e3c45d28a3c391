// Core stage: the process-wide resource limits (casteljau/limits.hpp): one atomic per field, so
// that checks on any thread read a whole value without a lock.
#include "casteljau/limits.hpp"

#include <atomic>
#include <string>

namespace casteljau {
namespace {

// Calls f(field-of-a, field-of-b, name) for every field of two Limits-shaped structs, so that
// storing, loading and validating list the fields once.
template <class A, class B, class F>
void each_field(A& a, B& b, F&& f) {
    f(a.canvas_dimension, b.canvas_dimension, "canvas_dimension");
    f(a.canvas_pixels, b.canvas_pixels, "canvas_pixels");
    f(a.path_points, b.path_points, "path_points");
    f(a.flattened_segments, b.flattened_segments, "flattened_segments");
    f(a.nesting_depth, b.nesting_depth, "nesting_depth");
    f(a.svg_elements, b.svg_elements, "svg_elements");
    f(a.svg_image_nesting, b.svg_image_nesting, "svg_image_nesting");
    f(a.svgz_bytes, b.svgz_bytes, "svgz_bytes");
    f(a.css_rules, b.css_rules, "css_rules");
    f(a.svg_text_chars, b.svg_text_chars, "svg_text_chars");
    f(a.filter_pixels, b.filter_pixels, "filter_pixels");
    f(a.filter_primitives, b.filter_primitives, "filter_primitives");
    f(a.map_positions, b.map_positions, "map_positions");
    f(a.dashes, b.dashes, "dashes");
    f(a.font_file_bytes, b.font_file_bytes, "font_file_bytes");
    f(a.png_chunk_bytes, b.png_chunk_bytes, "png_chunk_bytes");
    f(a.png_ancillary_chunks, b.png_ancillary_chunks, "png_ancillary_chunks");
    f(a.jpeg_working_memory, b.jpeg_working_memory, "jpeg_working_memory");
    f(a.canvas_save_depth, b.canvas_save_depth, "canvas_save_depth");
    f(a.text_bytes, b.text_bytes, "text_bytes");
    f(a.input_bytes, b.input_bytes, "input_bytes");
    f(a.exact_work, b.exact_work, "exact_work");
}

struct AtomicLimits {
    std::atomic<int> canvas_dimension;
    std::atomic<long long> canvas_pixels;
    std::atomic<std::size_t> path_points, flattened_segments;
    std::atomic<int> nesting_depth;
    std::atomic<std::size_t> svg_elements;
    std::atomic<int> svg_image_nesting;
    std::atomic<std::size_t> svgz_bytes, css_rules, svg_text_chars;
    std::atomic<long long> filter_pixels;
    std::atomic<std::size_t> filter_primitives, map_positions, dashes;
    std::atomic<std::uint64_t> font_file_bytes;
    std::atomic<std::size_t> png_chunk_bytes;
    std::atomic<std::uint32_t> png_ancillary_chunks;
    std::atomic<std::uint64_t> jpeg_working_memory;
    std::atomic<std::size_t> canvas_save_depth;
    std::atomic<std::size_t> text_bytes;
    std::atomic<std::uint64_t> input_bytes;
    std::atomic<std::uint64_t> exact_work;

    AtomicLimits() { store(Limits{}); }
    void store(const Limits& l) {
        each_field(*this, l,
                   [](auto& dst, const auto& src, const char*) { dst.store(src, std::memory_order_relaxed); });
    }
};

AtomicLimits& state() {
    static AtomicLimits s;
    return s;
}

}  // namespace

Limits Limits::ceilings() noexcept {
    Limits c;               // canvas, path, segment and map-position limits: the defaults are the ceilings
    c.nesting_depth = 256;  // recursion depth of the SVG and JSON readers: a few KB of stack per level
    c.svg_elements = 100'000'000;
    c.svg_image_nesting = 16;
    c.svgz_bytes = std::size_t(1) << 30;
    c.css_rules = 1'000'000;
    c.svg_text_chars = 10'000'000;
    c.filter_pixels = limits::kMaxCanvasPixels;
    c.filter_primitives = 100'000;
    c.dashes = std::size_t(1) << 22;
    c.font_file_bytes = std::uint64_t(2) << 30;
    c.png_chunk_bytes = std::size_t(256) << 20;
    c.png_ancillary_chunks = 100'000;
    c.jpeg_working_memory = std::uint64_t(4) << 30;
    c.canvas_save_depth = 65536;
    c.text_bytes = std::size_t(256) << 20;
    c.input_bytes = std::uint64_t(64) << 30;
    c.exact_work = 5'000'000'000;
    return c;
}

Limits current_limits() noexcept {
    Limits out;
    each_field(out, state(),
               [](auto& dst, const auto& src, const char*) { dst = src.load(std::memory_order_relaxed); });
    return out;
}

void set_limits(const Limits& limits) {
    const Limits ceil = Limits::ceilings();
    each_field(limits, ceil, [](const auto& value, const auto& top, const char* name) {
        const auto lowest = std::string(name) == "svg_image_nesting" ? 0 : 1;
        if (value < static_cast<std::decay_t<decltype(value)>>(lowest) || value > top)
            throw Error(ErrorKind::InvalidArgument, std::string("Limits::") + name + " must be " +
                                                        std::to_string(lowest) + " to " + std::to_string(top) +
                                                        ", got " + std::to_string(value));
    });
    state().store(limits);
}

void reset_limits() noexcept { state().store(Limits{}); }

}  // namespace casteljau
