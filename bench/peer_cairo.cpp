// bench/peer_cairo.cpp: Cairo as a peer: an A8 image surface per glyph (all over one shared,
// preallocated buffer), cairo_fill with CAIRO_ANTIALIAS_DEFAULT and the winding rule. prepare()
// creates the surfaces and contexts and converts each outline to a cairo_path_t (quadratics raised
// exactly to cubics: Cairo has no quadratic segment); render() clears the box, appends the path
// and fills it.
#include <cairo.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "renderer.hpp"

namespace bench {
namespace {

struct ToCairo {
    cairo_t* cr;
    const casteljau::Affine& m;
    void move(casteljau::Point p) {
        const auto q = m(p);
        cairo_move_to(cr, q.x, q.y);
    }
    void line(casteljau::Point, casteljau::Point p) {
        const auto q = m(p);
        cairo_line_to(cr, q.x, q.y);
    }
    void quad(casteljau::Point p0, casteljau::Point c, casteljau::Point p) {
        const auto a = m(p0), qc = m(c), b = m(p);
        const auto c1 = a + (qc - a) * (2.0 / 3.0), c2 = b + (qc - b) * (2.0 / 3.0);
        cairo_curve_to(cr, c1.x, c1.y, c2.x, c2.y, b.x, b.y);
    }
    void cubic(casteljau::Point, casteljau::Point c1, casteljau::Point c2, casteljau::Point p) {
        const auto q1 = m(c1), q2 = m(c2), q = m(p);
        cairo_curve_to(cr, q1.x, q1.y, q2.x, q2.y, q.x, q.y);
    }
    void conic(casteljau::Point, casteljau::Point, casteljau::Point p, double) {  // not in TrueType
        const auto q = m(p);
        cairo_line_to(cr, q.x, q.y);
    }
    void close(casteljau::Point, casteljau::Point) { cairo_close_path(cr); }
};

class CairoRenderer final : public Renderer {
public:
    ~CairoRenderer() override { release(); }
    std::string name() const override { return "Cairo"; }
    std::string version() const override { return cairo_version_string(); }

    void prepare(const GlyphSet& set) override {
        release();
        set_ = &set;
        std::size_t bytes = 0;
        for (const Glyph& g : set.glyphs()) {
            const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_A8, g.box.width);
            bytes = std::max(bytes, static_cast<std::size_t>(stride) * static_cast<std::size_t>(g.box.height));
        }
        buf_.assign(bytes, 0);
        for (const Glyph& g : set.glyphs()) {
            const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_A8, g.box.width);
            cairo_surface_t* s =
                cairo_image_surface_create_for_data(buf_.data(), CAIRO_FORMAT_A8, g.box.width, g.box.height, stride);
            cairo_t* cr = cairo_create(s);
            if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) throw std::runtime_error("cairo_create failed");
            cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
            cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
            cairo_set_source_rgba(cr, 0, 0, 0, 1);
            g.path.visit(ToCairo{cr, g.to_box});
            cairo_path_t* path = cairo_copy_path(cr);
            cairo_new_path(cr);
            surfaces_.push_back(s);
            contexts_.push_back(cr);
            paths_.push_back(path);
            strides_.push_back(stride);
        }
    }

    Coverage render(std::size_t i) override {
        const Glyph& g = set_->glyphs()[i];
        std::memset(buf_.data(), 0, static_cast<std::size_t>(strides_[i]) * static_cast<std::size_t>(g.box.height));
        cairo_surface_mark_dirty(surfaces_[i]);
        cairo_t* cr = contexts_[i];
        cairo_append_path(cr, paths_[i]);
        cairo_fill(cr);
        cairo_surface_flush(surfaces_[i]);
        return {buf_.data(), strides_[i], g.box};
    }

private:
    void release() {
        for (cairo_path_t* p : paths_) cairo_path_destroy(p);
        for (cairo_t* c : contexts_) cairo_destroy(c);
        for (cairo_surface_t* s : surfaces_) cairo_surface_destroy(s);
        paths_.clear();
        contexts_.clear();
        surfaces_.clear();
        strides_.clear();
    }

    const GlyphSet* set_ = nullptr;
    std::vector<std::uint8_t> buf_;
    std::vector<cairo_surface_t*> surfaces_;
    std::vector<cairo_t*> contexts_;
    std::vector<cairo_path_t*> paths_;
    std::vector<int> strides_;
};

}  // namespace

std::unique_ptr<Renderer> make_cairo_renderer() { return std::make_unique<CairoRenderer>(); }

}  // namespace bench
