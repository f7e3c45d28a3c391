// What SVG documents convert to, without drawing them: the display list (src/formats/svg/
// display_list.hpp) of small documents, item by item. Each expected value is worked out by hand
// from the SVG and CSS specifications in the comments.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/paint.hpp"
#include "formats/svg/display_list.hpp"

using namespace casteljau;
using svg::DisplayItem;

namespace {

// The display list of `body` inside an svg of `attrs` (default 100 x 100 user units, no viewBox).
svg::DisplayList convert(const std::string& body, const std::string& attrs = "width='100' height='100'") {
    return svg::convert("<svg xmlns='http://www.w3.org/2000/svg' " + attrs + ">" + body + "</svg>");
}

std::vector<DisplayItem::Kind> kinds(const svg::DisplayList& items) {
    std::vector<DisplayItem::Kind> out;
    for (const DisplayItem& it : items) out.push_back(it.kind);
    return out;
}

// `m` applied to (x, y).
Point map(const Affine& m, double x, double y) { return m.apply({x, y}); }

}  // namespace

TEST_CASE("svg display list: a rect converts to one fill with its box and colour", "[svg][display_list]") {
    // A rect without stroke (stroke: none is the initial value) is one nonzero fill of its
    // rectangle in user space; with no viewBox, user space is document pixels (identity).
    const svg::DisplayList items = convert("<rect x='10' y='20' width='30' height='40' fill='#ff8000'/>");
    REQUIRE(items.size() == 1);
    const DisplayItem& it = items[0];
    CHECK(it.kind == DisplayItem::Fill);
    CHECK(it.path.bounds() == Rect{10, 20, 40, 60});
    CHECK(it.color == Color::rgba(255, 128, 0));
    CHECK(it.transform == Affine::identity());
    CHECK(it.rule == FillRule::NonZero);
    CHECK(it.opacity == 1);
    CHECK_FALSE(it.shader);
}

TEST_CASE("svg display list: the root viewBox maps user space to pixels", "[svg][display_list]") {
    // viewBox 0 0 20 10 into 200 x 100 (xMidYMid meet): scale min(200/20, 100/10) = 10, no offset.
    const svg::DisplayList items =
        convert("<rect x='1' y='2' width='3' height='4'/>", "width='200' height='100' viewBox='0 0 20 10'");
    REQUIRE(items.size() == 1);
    CHECK(items[0].transform == Affine{10, 0, 0, 10, 0, 0});
    CHECK(items[0].path.bounds() == Rect{1, 2, 4, 6});
    CHECK(items[0].color == Color::black());  // fill's initial value
}

TEST_CASE("svg display list: group opacity gives a layer with that opacity", "[svg][display_list]") {
    // opacity on a group composites the group as a whole: its content is drawn at full opacity
    // into a layer (BeginLayer .. EndLayer) that is blended back at 0.25.
    const svg::DisplayList items = convert("<g opacity='0.25'><rect width='10' height='10' fill-opacity='0.5'/></g>");
    REQUIRE(kinds(items) ==
            std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill, DisplayItem::EndLayer});
    CHECK(items[0].opacity == 0.25);
    CHECK(items[2].opacity == 0.25);
    CHECK(items[1].opacity == 0.5);  // fill-opacity stays on the fill
}

TEST_CASE("svg display list: display none converts to nothing", "[svg][display_list]") {
    // display: none removes the element and its subtree from rendering and from bounding boxes.
    CHECK(convert("<rect width='10' height='10' display='none'/>").empty());
    CHECK(convert("<g style='display:none'><rect width='10' height='10'/><circle r='5'/></g>").empty());
}

TEST_CASE("svg display list: visibility hidden leaves a bounds item", "[svg][display_list]") {
    // A hidden shape is not painted but still has geometry (it counts in its group's bounding
    // box): one Bounds item with the shape's path.
    const svg::DisplayList items = convert("<rect x='5' y='6' width='7' height='8' visibility='hidden'/>");
    REQUIRE(items.size() == 1);
    CHECK(items[0].kind == DisplayItem::Bounds);
    CHECK(items[0].path.bounds() == Rect{5, 6, 12, 14});
    // A hidden child of a visible group is hidden too: visibility is inherited.
    CHECK(kinds(convert("<g visibility='hidden'><rect width='1' height='1'/></g>")) ==
          std::vector<DisplayItem::Kind>{DisplayItem::Bounds});
}

TEST_CASE("svg display list: a clip-path clips a layer with its content as a mask", "[svg][display_list]") {
    // The clipped element is drawn into a layer; the clipPath's children follow between BeginClip
    // and EndMask as opaque black fills, whatever their own fill, in the clipped element's user space.
    const svg::DisplayList items = convert(
        "<clipPath id='c'><rect x='0' y='0' width='50' height='40' fill='red'/></clipPath>"
        "<rect width='100' height='100' fill='blue' clip-path='url(#c)'/>");
    REQUIRE(kinds(items) == std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill,
                                                           DisplayItem::BeginClip, DisplayItem::Fill,
                                                           DisplayItem::EndMask, DisplayItem::EndLayer});
    CHECK(items[1].color == Color::rgba(0, 0, 255));
    CHECK(items[3].color == Color::black());
    CHECK(items[3].path.bounds() == Rect{0, 0, 50, 40});
    CHECK(items[0].opacity == 1);
}

TEST_CASE("svg display list: clipPathUnits objectBoundingBox maps 0..1 onto the box", "[svg][display_list]") {
    // The clipped rect's box is (20, 10) 40 x 80: the clip content's unit square maps onto it.
    const svg::DisplayList items = convert(
        "<clipPath id='c' clipPathUnits='objectBoundingBox'><rect width='0.5' height='1'/></clipPath>"
        "<rect x='20' y='10' width='40' height='80' clip-path='url(#c)'/>");
    REQUIRE(items.size() == 6);
    REQUIRE(items[3].kind == DisplayItem::Fill);
    CHECK(items[3].transform == Affine{40, 0, 0, 80, 20, 10});
    CHECK(map(items[3].transform, 0.5, 1) == Point{40, 90});
}

TEST_CASE("svg display list: a mask gives a luminance mask over its region", "[svg][display_list]") {
    // mask-type defaults to luminance. The mask region defaults to objectBoundingBox -10% -10%
    // 120% 120%: for the masked box (0, 0) 50 x 50 that is (-5, -5) 60 x 60, a clip around the
    // mask's content.
    const svg::DisplayList items = convert(
        "<mask id='k'><rect width='100' height='100' fill='white'/></mask>"
        "<rect width='50' height='50' mask='url(#k)'/>");
    REQUIRE(kinds(items) == std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill,
                                                           DisplayItem::BeginMask, DisplayItem::PushClip,
                                                           DisplayItem::Fill, DisplayItem::PopClip,
                                                           DisplayItem::EndMask, DisplayItem::EndLayer});
    CHECK(items[2].luminance);
    CHECK(items[3].path.bounds() == Rect{-5, -5, 55, 55});
    CHECK(items[4].color == Color::rgba(255, 255, 255));
    // mask-type: alpha uses the content's alpha instead.
    const svg::DisplayList alpha = convert(
        "<mask id='k' style='mask-type:alpha'><rect width='100' height='100' fill='white'/></mask>"
        "<rect width='50' height='50' mask='url(#k)'/>");
    REQUIRE(alpha.size() == 8);
    REQUIRE(alpha[2].kind == DisplayItem::BeginMask);
    CHECK_FALSE(alpha[2].luminance);
}

TEST_CASE("svg display list: use of a symbol places its viewBox in a clipped viewport", "[svg][display_list]") {
    // The symbol's viewBox 0 0 10 10 maps onto the use's 50 x 50 at (20, 30): scale 5, translate
    // (20, 30). A symbol clips to its viewport (overflow: hidden is its user agent style).
    const svg::DisplayList items = convert(
        "<symbol id='s' viewBox='0 0 10 10'><rect width='10' height='10' fill='green'/></symbol>"
        "<use href='#s' x='20' y='30' width='50' height='50'/>");
    REQUIRE(kinds(items) ==
            std::vector<DisplayItem::Kind>{DisplayItem::PushClip, DisplayItem::Fill, DisplayItem::PopClip});
    CHECK(items[0].path.bounds() == Rect{20, 30, 70, 80});
    CHECK(items[1].transform == Affine{5, 0, 0, 5, 20, 30});
    CHECK(map(items[1].transform, 10, 10) == Point{70, 80});
    CHECK(items[1].color == Color::rgba(0, 128, 0));
}

TEST_CASE("svg display list: use of a shape translates it by x and y", "[svg][display_list]") {
    // use adds translate(x, y) after its own transform; the referenced element keeps its own.
    const svg::DisplayList items = convert(
        "<defs><rect id='r' width='4' height='4' transform='scale(2)'/></defs>"
        "<use href='#r' x='10' y='20' transform='translate(1 1)'/>");
    REQUIRE(items.size() == 1);
    CHECK(items[0].transform == Affine{2, 0, 0, 2, 11, 21});
}

TEST_CASE("svg display list: a linear gradient becomes a shader in bounding-box units", "[svg][display_list]") {
    // gradientUnits defaults to objectBoundingBox: gradient space (0, 0)-(1, 1) maps onto the
    // rect's box (10, 20) 40 x 40, and the default vector runs from x1 = 0% to x2 = 100%.
    const svg::DisplayList items = convert(
        "<linearGradient id='g'><stop offset='0' stop-color='red'/><stop offset='100%' stop-color='blue'/>"
        "</linearGradient><rect x='10' y='20' width='40' height='40' fill='url(#g)'/>");
    REQUIRE(items.size() == 1);
    REQUIRE(items[0].shader);
    const Shader& s = *items[0].shader;
    CHECK(s.kind() == Shader::Kind::Linear);
    CHECK(s.transform() == Affine{40, 0, 0, 40, 10, 20});
    REQUIRE(s.stops().size() == 2);
    CHECK(s.stops()[0].color == Color::rgba(255, 0, 0));
    CHECK(s.stops()[1].color == Color::rgba(0, 0, 255));
    CHECK(s.stops()[1].offset == 1);
    double t = -1;
    REQUIRE(s.parameter({0.25, 0.7}, t));  // horizontal vector: t is the x of gradient space
    CHECK(t == Approx(0.25));
}

TEST_CASE("svg display list: stroke percentages resolve against the viewport diagonal", "[svg][display_list]") {
    // viewBox 0 0 10 70: the normalised diagonal is sqrt((10^2 + 70^2) / 2) = sqrt(2500) = 50, so
    // stroke-width 10% = 5, dasharray 20% 40% = 10 20 and dashoffset 2% = 1.
    const svg::DisplayList items = convert(
        "<path d='M 0 0 L 10 70' fill='none' stroke='black' stroke-width='10%' stroke-dasharray='20% 40%'"
        " stroke-dashoffset='2%'/>",
        "width='10' height='70' viewBox='0 0 10 70'");
    REQUIRE(items.size() == 1);
    const DisplayItem& it = items[0];
    CHECK(it.kind == DisplayItem::Stroke);
    CHECK(it.stroke.width == Approx(5));
    REQUIRE(it.stroke.dashes.size() == 2);
    CHECK(it.stroke.dashes[0] == Approx(10));
    CHECK(it.stroke.dashes[1] == Approx(20));
    CHECK(it.stroke.dash_offset == Approx(1));
}

TEST_CASE("svg display list: markers are drawn at the vertices", "[svg][display_list]") {
    // Three vertices: marker-start at (10, 10), marker-mid at (50, 10), marker-end at (50, 40).
    // markerUnits userSpaceOnUse: no scaling by the stroke width; refX = refY = 0 sits on the
    // vertex; overflow visible: no clip. Each marker is a layer around its content.
    const svg::DisplayList items = convert(
        "<marker id='m' markerWidth='10' markerHeight='10' markerUnits='userSpaceOnUse' overflow='visible'>"
        "<rect width='2' height='1'/></marker>"
        "<path d='M 10 10 L 50 10 L 50 40' fill='none' marker-start='url(#m)' marker-mid='url(#m)'"
        " marker-end='url(#m)'/>");
    REQUIRE(items.size() == 9);
    const Point vertices[] = {{10, 10}, {50, 10}, {50, 40}};
    for (int i = 0; i < 3; ++i) {
        CHECK(items[3 * i].kind == DisplayItem::BeginLayer);
        REQUIRE(items[3 * i + 1].kind == DisplayItem::Fill);
        CHECK(items[3 * i + 2].kind == DisplayItem::EndLayer);
        CHECK(items[3 * i + 1].transform == Affine::translate(vertices[i].x, vertices[i].y));
    }
}

TEST_CASE("svg display list: orient auto turns a mid marker along the bisector", "[svg][display_list]") {
    // At (50, 10) the path comes in along +x (0 degrees) and leaves along +y (90 degrees): the
    // marker turns by their bisector, 45 degrees; markerUnits strokeWidth scales it by
    // stroke-width 2.
    const svg::DisplayList items = convert(
        "<marker id='m' markerWidth='10' markerHeight='10' orient='auto' overflow='visible'>"
        "<rect width='1' height='1'/></marker>"
        "<path d='M 10 10 L 50 10 L 50 40' fill='none' stroke-width='2' marker-mid='url(#m)'/>");
    REQUIRE(items.size() == 3);
    const Affine& m = items[1].transform;
    const double c = 2 * std::cos(kPi / 4);
    CHECK(m.a == Approx(c));
    CHECK(m.b == Approx(c));
    CHECK(m.c == Approx(-c));
    CHECK(m.d == Approx(c));
    CHECK(m.e == Approx(50));
    CHECK(m.f == Approx(10));
}

TEST_CASE("svg display list: a more specific CSS rule wins over a presentation attribute", "[svg][display_list]") {
    // Presentation attributes have the lowest priority; of the two rules, #r (specificity 1,0,0)
    // beats rect (0,0,1) whatever their order.
    const svg::DisplayList items = convert(
        "<style>#r { fill: blue } rect { fill: green }</style>"
        "<rect id='r' width='10' height='10' fill='red'/>");
    REQUIRE(items.size() == 1);
    CHECK(items[0].color == Color::rgba(0, 0, 255));
    // The style attribute beats both rules, and !important in a sheet beats the style attribute.
    CHECK(convert("<style>rect { fill: green }</style><rect width='1' height='1' style='fill: blue'/>")[0].color ==
          Color::rgba(0, 0, 255));
    CHECK(convert("<style>rect { fill: green !important }</style><rect width='1' height='1' style='fill: blue'/>")[0]
              .color == Color::rgba(0, 128, 0));
}

TEST_CASE("svg display list: a nested svg clips to its viewport", "[svg][display_list]") {
    // A nested svg at (10, 20) of 30 x 40 establishes a viewport clipped to that rectangle
    // (overflow: hidden); its content's user space starts at (10, 20).
    const svg::DisplayList items =
        convert("<svg x='10' y='20' width='30' height='40'><rect width='100' height='100'/></svg>");
    REQUIRE(kinds(items) ==
            std::vector<DisplayItem::Kind>{DisplayItem::PushClip, DisplayItem::Fill, DisplayItem::PopClip});
    CHECK(items[0].path.bounds() == Rect{10, 20, 40, 60});
    CHECK(items[1].transform == Affine::translate(10, 20));
}
