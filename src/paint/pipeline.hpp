// Paint stage, internal: the pipeline every drawer composites through. One PaintPipeline is set up
// per drawing call from a Paint, the user-to-pixel transform, the drawer's opacity and blend mode;
// run() then shades (solid colour, gradient or image, x opacity), blends and composites one row of
// pixels weighted by 8-bit coverage.
#pragma once

#include <cstdint>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/paint.hpp"

namespace casteljau {

class PaintPipeline {
public:
    // `opacity` multiplies the paint's; `mode` is used when the paint's blend mode is SourceOver.
    // `scratch` holds one row of shader colours; it grows to the widest row, never per pixel.
    PaintPipeline(const Paint& paint, const Affine& user_to_pixel, double opacity, BlendMode mode,
                  std::vector<std::uint8_t>& scratch);
    // True when nothing can change a pixel (transparent source-over paint, singular shader transform).
    bool paints_nothing() const { return skip_; }
    // Composites pixels x .. x + length - 1 of row y of `pm` with `coverage` (length bytes).
    void run(Pixmap& pm, int x, int y, int length, const std::uint8_t* coverage);

private:
    Paint solid_;  // the paint with the combined opacity, for the solid source-over path
    const Shader* shader_ = nullptr;
    Affine inverse_;
    double opacity_ = 1;
    BlendMode mode_ = BlendMode::SourceOver;
    std::uint8_t premul_[4] = {0, 0, 0, 0};
    bool skip_ = false;
    std::vector<std::uint8_t>& scratch_;
};

}  // namespace casteljau
