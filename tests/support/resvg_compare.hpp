// The resvg corpora's comparison rules and size rule, shared by the Catch test of the older subset
// (tests/svg/test_svg_resvg.cpp) and the whole-suite conformance program (tests/conformance/).
//
// Both work on 8-bit premultiplied RGBA (so faint pixels carry little weight); Δ is the largest
// per-channel absolute difference at a pixel. See ../shared/conformance/resvg/README.md.
//   Rule A (simple): a pixel is bad when Δ > 32; a file passes with at most 0.5% bad pixels.
//   Rule B (edge-tolerant, primary): a pixel is bad when Δ > 24 and, in some channel, its value
//     lies outside [min - 24, max + 24] of the other image's 3x3 neighbourhood, checked in both
//     directions; a file passes with at most 0.1% bad pixels.
// A size mismatch fails both rules.
#pragma once

#include <filesystem>
#include <string>

#include "casteljau/paint.hpp"

namespace casteljau {
class SvgDocument;
}

namespace resvg_compare {

struct Result {
    bool size_ok = false;
    int bad_a = 0, bad_b = 0;  // bad pixels by rule A and rule B
    bool pass_a = false, pass_b = false;
};

// Compares `actual` with `reference` by rules A and B.
Result compare(const casteljau::Pixmap& actual, const casteljau::Pixmap& reference);

// A picture for a human: actual | reference | bad pixels (red: bad by rule B, orange: bad by rule A
// only, grey: the reference's alpha), side by side. Sizes may differ.
casteljau::Pixmap diff_image(const casteljau::Pixmap& actual, const casteljau::Pixmap& reference);

// Renders `doc` by the corpus size rule: 300 px wide and ceil(300 * H / W) high, W x H the
// document's integer intrinsic size (`native` true: the extra/ tests, at scale 1).
casteljau::Pixmap render_reference_size(const casteljau::SvgDocument& doc, bool native = false);

// The shared data folder: $CASTELJAU_SHARED_DIR when set, otherwise ../shared next to the source.
std::filesystem::path shared_dir();

}  // namespace resvg_compare
