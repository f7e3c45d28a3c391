// bench/peer_agg.cpp: AGG 2.x as a peer: rasterizer_scanline_aa (nonzero) + scanline_u8 +
// renderer_scanline_aa_solid over a gray8 pixel format; curves through conv_curve with its
// defaults (incremental-free subdivision, approximation_scale 1). The glyph is built once in
// prepare() as an agg::path_storage in the box's pixel space; render() clears the box, feeds the
// curve converter to the rasterizer and sweeps the scanlines into the buffer.
#include <agg_conv_curve.h>
#include <agg_path_storage.h>
#include <agg_pixfmt_gray.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_u.h>

#include <cstring>

#include "renderer.hpp"

namespace bench {
namespace {

struct ToAgg {
    agg::path_storage& ps;
    const casteljau::Affine& m;
    void move(casteljau::Point p) {
        const auto q = m(p);
        ps.move_to(q.x, q.y);
    }
    void line(casteljau::Point, casteljau::Point p) {
        const auto q = m(p);
        ps.line_to(q.x, q.y);
    }
    void quad(casteljau::Point, casteljau::Point c, casteljau::Point p) {
        const auto qc = m(c), q = m(p);
        ps.curve3(qc.x, qc.y, q.x, q.y);
    }
    void cubic(casteljau::Point, casteljau::Point c1, casteljau::Point c2, casteljau::Point p) {
        const auto q1 = m(c1), q2 = m(c2), q = m(p);
        ps.curve4(q1.x, q1.y, q2.x, q2.y, q.x, q.y);
    }
    void conic(casteljau::Point, casteljau::Point, casteljau::Point p, double) {  // not in TrueType
        const auto q = m(p);
        ps.line_to(q.x, q.y);
    }
    void close(casteljau::Point, casteljau::Point) { ps.close_polygon(); }
};

class AggRenderer final : public Renderer {
public:
    std::string name() const override { return "AGG"; }
    std::string version() const override { return CASTELJAU_AGG_VERSION; }

    void prepare(const GlyphSet& set) override {
        set_ = &set;
        paths_.clear();
        paths_.resize(set.size());
        for (std::size_t i = 0; i < set.size(); ++i) {
            const Glyph& g = set.glyphs()[i];
            set.glyphs()[i].path.visit(ToAgg{paths_[i], g.to_box});
        }
        buf_.assign(set.max_box_pixels(), 0);
    }

    Coverage render(std::size_t i) override {
        const Glyph& g = set_->glyphs()[i];
        const int w = g.box.width, h = g.box.height;
        std::memset(buf_.data(), 0, g.box.pixels());
        agg::rendering_buffer rbuf(buf_.data(), static_cast<unsigned>(w), static_cast<unsigned>(h), w);
        agg::pixfmt_gray8 pixf(rbuf);
        agg::renderer_base<agg::pixfmt_gray8> base(pixf);
        agg::renderer_scanline_aa_solid<agg::renderer_base<agg::pixfmt_gray8>> ren(base);
        ren.color(agg::gray8(255, 255));
        ras_.reset();
        agg::conv_curve<agg::path_storage> curve(paths_[i]);
        ras_.add_path(curve);
        agg::render_scanlines(ras_, sl_, ren);
        return {buf_.data(), w, g.box};
    }

private:
    const GlyphSet* set_ = nullptr;
    std::vector<agg::path_storage> paths_;
    std::vector<std::uint8_t> buf_;
    agg::rasterizer_scanline_aa<> ras_;
    agg::scanline_u8 sl_;
};

}  // namespace

std::unique_ptr<Renderer> make_agg_renderer() { return std::make_unique<AggRenderer>(); }

}  // namespace bench
