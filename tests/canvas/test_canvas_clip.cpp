// Canvas clipping: the coverage of a fill inside a clip path is the product of the shape's and
// the clip's exact-area coverage (each computed on its own by the rasterizer), within 1/255; clips
// intersect; save/restore brings the previous clip back.
#include <catch2/catch.hpp>

#include <cstdlib>

#include "casteljau/canvas.hpp"

using namespace casteljau;

namespace {

// Alpha of every pixel after filling `shape` in opaque white on a transparent canvas clipped by
// each of `clips` in turn.
Pixmap fill_clipped(const Path& shape, const std::vector<std::pair<Path, FillRule>>& clips, int w, int h) {
    Pixmap pm(w, h);
    Canvas c(pm);
    for (const auto& [p, rule] : clips) c.clip_path(p, rule);
    c.fill_path(shape, Paint::solid(Color::white()));
    return pm;
}

std::uint8_t coverage(const Mask& m, int x, int y) { return m.at(x, y); }

}  // namespace

TEST_CASE("clip_path: coverage is the product of shape and clip coverage within 1/255", "[canvas][clip]") {
    const int w = 64, h = 48;
    Path shape;
    shape.add_ellipse({30.3, 22.7}, 24.1, 17.6);
    Path clip;
    clip.move_to(5.2, 40.9).line_to(58.7, 3.3).line_to(61.1, 44.4).close();  // a slanted triangle
    Path clip2;
    clip2.add_circle({40.5, 25.25}, 15.3);
    Rasterizer r;
    const Mask ms = r.fill_mask(shape, Affine{}), mc = r.fill_mask(clip, Affine{}), mc2 = r.fill_mask(clip2, Affine{});

    const Pixmap one = fill_clipped(shape, {{clip, FillRule::NonZero}}, w, h);
    const Pixmap two = fill_clipped(shape, {{clip, FillRule::NonZero}, {clip2, FillRule::EvenOdd}}, w, h);
    int bad1 = 0, bad2 = 0, partial = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double s = coverage(ms, x, y) / 255.0, k = coverage(mc, x, y) / 255.0,
                         k2 = coverage(mc2, x, y) / 255.0;
            bad1 += std::abs(one.pixel(x, y).a - s * k * 255) > 1.0;
            bad2 += std::abs(two.pixel(x, y).a - s * k * k2 * 255) > 1.5;  // two roundings
            partial += s * k > 0 && s * k < 1;
        }
    CHECK(partial > 50);  // the check covers anti-aliased edges, not just 0 and 1
    CHECK(bad1 == 0);
    CHECK(bad2 == 0);
}

TEST_CASE("clip_path: even-odd and nonzero clip rules differ inside a self-overlap", "[canvas][clip]") {
    Path twice;  // two nested squares of the same orientation: nonzero keeps the hole, even-odd cuts it
    twice.add_rect({4, 4, 28, 28});
    twice.add_rect({10, 10, 22, 22});
    Path all;
    all.add_rect({0, 0, 32, 32});
    const Pixmap nz = fill_clipped(all, {{twice, FillRule::NonZero}}, 32, 32);
    const Pixmap eo = fill_clipped(all, {{twice, FillRule::EvenOdd}}, 32, 32);
    CHECK(nz.pixel(16, 16).a == 255);
    CHECK(eo.pixel(16, 16).a == 0);
    CHECK(nz.pixel(6, 6).a == 255);
    CHECK(eo.pixel(6, 6).a == 255);
    CHECK(nz.pixel(2, 2).a == 0);
}

TEST_CASE("clip_rect: whole pixels clip exactly, fractional edges clip by their area", "[canvas][clip]") {
    Pixmap pm(20, 10);
    Canvas c(pm);
    c.clip_rect({2.25, 0, 10.5, 10});
    c.fill_rect({0, 0, 20, 10}, Paint::solid(Color::white()));
    CHECK(pm.pixel(1, 5).a == 0);
    CHECK(std::abs(pm.pixel(2, 5).a - 0.75 * 255) <= 1);
    CHECK(pm.pixel(5, 5).a == 255);
    CHECK(std::abs(pm.pixel(10, 5).a - 0.5 * 255) <= 1);
    CHECK(pm.pixel(11, 5).a == 0);
    // Rotated: a rect turned by 45 degrees about its centre clips a diamond.
    Pixmap d(20, 20);
    Canvas cd(d);
    cd.translate(10, 10);
    cd.rotate(0.7853981633974483);
    cd.clip_rect({-5, -5, 5, 5});
    cd.reset_transform();
    cd.fill_rect({0, 0, 20, 20}, Paint::solid(Color::white()));
    CHECK(d.pixel(10, 10).a == 255);
    CHECK(d.pixel(10, 1).a == 0);  // above the diamond's top corner (10, 2.93)
    CHECK(d.pixel(14, 5).a == 0);  // outside an edge, inside the axis-aligned bounds
}

TEST_CASE("save and restore bring back transform, clip, opacity and blend mode", "[canvas][clip]") {
    Pixmap pm(10, 10);
    Canvas c(pm);
    c.save();
    c.translate(3, 4);
    c.clip_rect({0, 0, 2, 2});
    Path p;
    p.add_circle({1, 1}, 1);
    c.clip_path(p);
    c.set_opacity(0.5);
    c.set_blend_mode(BlendMode::Multiply);
    CHECK(c.clip() == IRect{3, 4, 5, 6});
    CHECK(c.clip_mask() != nullptr);
    c.restore();
    CHECK(c.transform() == Affine{});
    CHECK(c.clip() == IRect{0, 0, 10, 10});
    CHECK(c.clip_mask() == nullptr);
    CHECK(c.opacity() == 1.0);
    CHECK(c.blend_mode() == BlendMode::SourceOver);
    c.restore();  // nothing saved: no-op
    CHECK(c.save_count() == 0);
}

TEST_CASE("clear fills the clip only, its anti-aliased edge blended by coverage", "[canvas][clip]") {
    Pixmap pm(10, 4);
    pm.fill(Color::rgba(0, 0, 255, 255));
    Canvas c(pm);
    c.clip_rect({0, 0, 4.5, 4});
    c.clear(Color::rgba(255, 0, 0, 255));
    CHECK(pm.pixel(0, 0) == PremulPixel{255, 0, 0, 255});
    CHECK(std::abs(pm.pixel(4, 0).r - 128) <= 1);
    CHECK(std::abs(pm.pixel(4, 0).b - 128) <= 1);
    CHECK(pm.pixel(6, 0) == PremulPixel{0, 0, 255, 255});
}

TEST_CASE("clip_path: rotated clips reaching past the canvas, or wholly outside it", "[canvas][clip]") {
    // The clip is rasterized only where its transformed bounds meet the current clip: the pixels
    // must be those of the clip's coverage over the whole canvas times the shape's.
    const int w = 40, h = 30;
    Path shape;
    shape.add_rect(Rect{-5, -5, 45, 35});
    Path clip;
    clip.add_ellipse({36.2, 4.7}, 14.3, 6.1);  // reaches past the top right corner
    const Affine rot = Affine::translate(20, 15) * Affine::rotate(0.7) * Affine::translate(-20, -15);
    Rasterizer r;
    const Mask mc = r.fill_mask(clip, rot, FillOptions{}, IRect{0, 0, w, h});
    Pixmap pm(w, h);
    Canvas c(pm);
    c.set_transform(rot);
    c.clip_path(clip);
    c.reset_transform();
    c.fill_path(shape, Paint::solid(Color::white()));
    int bad = 0, inked = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            bad += pm.pixel(x, y).a != mc.at(x, y);
            inked += pm.pixel(x, y).a != 0;
        }
    CHECK(inked > 20);
    CHECK(bad == 0);
    // A clip wholly outside the canvas leaves nothing to draw.
    Pixmap none(w, h);
    Canvas d(none);
    Path far;
    far.add_circle({200, 200}, 5);
    d.clip_path(far);
    d.fill_path(shape, Paint::solid(Color::white()));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) CHECK(none.pixel(x, y).a == 0);
}

TEST_CASE("fill_round_stroke and fill_coverage composite the round-stroke rows as fill_mask composites their mask",
          "[canvas][clip][round_stroke]") {
    // Half-transparent red over a blue background, under a clip path and a clip rectangle: the
    // rows go straight to the pixels, or are recorded over the whole image and composited later
    // (cut to the clip rectangle then), and must give what the mask of the same strokes gives.
    const std::vector<LineSegment> segs{
        {{3.2, 4.1}, {150.6, 30.3}}, {{20.5, 35.0}, {140.2, 2.7}}, {{90, 20}, {90, 20}}};
    Path clip;
    clip.add_rect({10.5, 0, 120.25, 40});
    enum Mode { kDirect, kMask, kRecorded };
    auto draw = [&](Mode mode) {
        Pixmap pm(160, 40);
        Canvas c(pm);
        c.fill_rect({0, 0, 160, 40}, Paint::solid(Color::rgba(20, 40, 200)));
        c.clip_path(clip);
        c.clip_rect({0, 3, 160, 37});
        const Paint red = Paint::solid(Color::rgba(230, 20, 10, 128));
        if (mode == kDirect) {
            c.fill_round_stroke(segs, 1.3, red);
        } else if (mode == kMask) {
            c.fill_mask(round_stroke_mask(segs, 1.3, {0, 0, 160, 40}), red);
        } else {
            CoverageRows rows;
            round_stroke_spans(segs, 1.3, {0, 0, 160, 40}, rows);
            c.fill_coverage(rows, red);
        }
        return pm;
    };
    const Pixmap a = draw(kDirect), b = draw(kMask), r = draw(kRecorded);
    int differ = 0, differ_recorded = 0, red = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 160; ++x) {
            differ += !(a.pixel(x, y) == b.pixel(x, y));
            differ_recorded += !(r.pixel(x, y) == b.pixel(x, y));
            red += a.pixel(x, y).r > 100;
        }
    CHECK(differ == 0);
    CHECK(differ_recorded == 0);
    CHECK(red > 200);
    CHECK(a.pixel(5, 5).r < 30);    // outside the clip path
    CHECK(a.pixel(60, 38).r < 30);  // outside the clip rectangle
}
