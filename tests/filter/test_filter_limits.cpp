// Filter effects, bad input: each case ends in a clear error or the documented behaviour (README
// "Limits"), in bounded time and memory: a 1e9 standard deviation (clamped to
// limits::kMaxFilterDeviation device pixels), a 1e6 x 1e6 filter region (clipped to the canvas), a
// 1000 x 1000 convolution kernel (Error(Limit)), feImage referencing its own filter (the filter is
// ignored), too many primitives, a region above Limits::filter_pixels, and the CLI leaving no
// output file behind.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/filter.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/svg.hpp"
#include "cli_util.hpp"
#include "svg_test_util.hpp"

using namespace casteljau;

namespace {
std::string svg(const std::string& body, int w = 40, int h = 40) { return casteljau::test::svg_text(body, w, h); }
Pixmap render(const std::string& body, int w = 40, int h = 40) { return SvgDocument::parse(svg(body, w, h)).render(); }
}  // namespace

TEST_CASE("filter limits: a 1e9 stdDeviation is clamped and spreads the element to almost nothing",
          "[filter][limits]") {
    const Pixmap pm = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='40' height='40'>"
        "<feGaussianBlur stdDeviation='1e9'/></filter>"
        "<rect x='10' y='10' width='20' height='20' filter='url(#f)'/>");
    // 400 opaque pixels spread over a Gaussian of deviation 1000 px: far below one level.
    CHECK(pm.pixel(20, 20).a == 0);
    // The same with edgeMode duplicate over a full field stays full (the clamp does not lose mass).
    const Pixmap full = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='40' height='40'>"
        "<feGaussianBlur stdDeviation='1e9' edgeMode='duplicate'/></filter>"
        "<rect width='40' height='40' filter='url(#f)'/>");
    CHECK(full.pixel(20, 20).a == 255);
}

TEST_CASE("filter limits: a 1e6 x 1e6 filter region is clipped to the canvas", "[filter][limits]") {
    const Pixmap pm = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='-5e5' y='-5e5' width='1e6' height='1e6'>"
        "<feFlood flood-color='#0000ff'/><feGaussianBlur stdDeviation='3'/></filter>"
        "<rect width='1' height='1' filter='url(#f)'/>");
    CHECK(pm.pixel(20, 20) == PremulPixel{0, 0, 255, 255});
    // Pixels beyond the canvas take no part (documented): the blur fades at the canvas border.
    CHECK(pm.pixel(0, 0).a < 255);
    CHECK(pm.pixel(0, 0).a > 0);
}

TEST_CASE("filter limits: a 1000 x 1000 convolution kernel is Error(Limit)", "[filter][limits]") {
    std::string kernel;
    kernel.reserve(2000000);
    for (int i = 0; i < 1000 * 1000; ++i) kernel += "1 ";
    try {
        render("<filter id='f'><feConvolveMatrix order='1000' kernelMatrix='" + kernel +
               "'/></filter>"
               "<rect width='20' height='20' filter='url(#f)'/>");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Limit);
        CHECK(std::string(e.what()).find("feConvolveMatrix") != std::string::npos);
    }
}

TEST_CASE("filter limits: feImage referencing its own filtered element draws the element unfiltered",
          "[filter][limits]") {
    const SvgDocument d =
        SvgDocument::parse(svg("<filter id='f'><feImage href='#r'/><feOffset dx='10'/></filter>"
                               "<rect id='r' width='20' height='20' fill='#ff0000' filter='url(#f)'/>"));
    const Pixmap pm = d.render();
    CHECK(pm.pixel(5, 5) == PremulPixel{255, 0, 0, 255});
    CHECK(pm.pixel(25, 5).a == 0);
    bool warned = false;
    for (const std::string& w : d.warnings()) warned = warned || w.find("feImage") != std::string::npos;
    CHECK(warned);
    // Through a group that holds the element, and a chain of two filters: drawn, no hang.
    const Pixmap chain = render(
        "<filter id='a'><feImage href='#g'/></filter><filter id='b'><feImage href='#r'/></filter>"
        "<g id='g' filter='url(#b)'><rect id='r' width='20' height='20' fill='#ff0000' filter='url(#a)'/></g>");
    CHECK(chain.width() == 40);
}

TEST_CASE("filter limits: more than Limits::filter_primitives primitives is Error(Limit)", "[filter][limits]") {
    std::string prims;
    for (std::size_t i = 0; i <= current_limits().filter_primitives; ++i) prims += "<feOffset/>";
    CHECK_THROWS_AS(render("<filter id='f'>" + prims + "</filter><rect width='20' height='20' filter='url(#f)'/>"),
                    Error);
    filter::FilterGraph g;
    g.region = Rect::from_xywh(0, 0, 4, 4);
    g.primitives.resize(current_limits().filter_primitives + 1);
    Pixmap src(4, 4);
    CHECK_THROWS_AS(filter::apply_filter(g, Affine::identity(), src), Error);
}

TEST_CASE(
    "filter limits: a region above Limits::filter_pixels is Error(Limit), an input naming a later result "
    "Error(InvalidData)",
    "[filter][limits]") {
    Pixmap big(4200, 4100);
    filter::FilterGraph g;
    g.region = Rect::from_xywh(0, 0, 4200, 4100);
    filter::Primitive p;
    p.op = filter::Primitive::Flood;
    p.subregion = g.region;
    g.primitives.push_back(p);
    try {
        filter::apply_filter(g, Affine::identity(), big);
        FAIL("no error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
    filter::FilterGraph bad;
    bad.region = Rect::from_xywh(0, 0, 4, 4);
    filter::Primitive q;
    q.op = filter::Primitive::Offset;
    q.subregion = bad.region;
    q.inputs = {filter::Input::result(3)};
    bad.primitives.push_back(q);
    Pixmap small(4, 4);
    try {
        filter::apply_filter(bad, Affine::identity(), small);
        FAIL("no error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidData); }
}

TEST_CASE("filter limits: the CLI reports a too large kernel on one line, exits 1 and writes no file",
          "[filter][limits][cli]") {
    namespace fs = std::filesystem;
    const fs::path d = casteljau::test::scratch_dir("filter_limits");
    {
        std::ofstream f(d / "k.svg");
        f << svg(
            "<filter id='f'><feConvolveMatrix order='100' kernelMatrix='1'/></filter><rect width='9' height='9' "
            "filter='url(#f)'/>");
    }
    const auto r = casteljau::test::run_cli("svg " + casteljau::test::shell_quote((d / "k.svg").string()) + " -o " +
                                            casteljau::test::shell_quote((d / "k.png").string()));
    CHECK(r.status == 1);
    CHECK(r.err.rfind("casteljau: error: ", 0) == 0);
    CHECK(r.err.find("feConvolveMatrix") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(d / "k.png"));
}
