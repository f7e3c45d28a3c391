// What SVG documents convert to, without drawing them: the document structure (namespaces, DTD
// entities, conditional processing on the root, the transform property, inherited currentColor,
// the root's background) and details of clips, masks, markers and paint servers. Each expected
// value is worked out by hand from the XML, SVG and CSS specifications in the comments (or, for
// the cases the specifications leave open, from the rule the comment states).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/paint.hpp"
#include "formats/svg/display_list.hpp"

using namespace casteljau;
using svg::DisplayItem;

namespace {

const std::string kSvgOpen = "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'>";

// The display list of `body` inside a 100 x 100 svg (no viewBox: user space is pixels).
svg::DisplayList convert(const std::string& body) { return svg::convert(kSvgOpen + body + "</svg>"); }

std::vector<DisplayItem::Kind> kinds(const svg::DisplayList& items) {
    std::vector<DisplayItem::Kind> out;
    for (const DisplayItem& it : items) out.push_back(it.kind);
    return out;
}

// The bounds of item `it`'s path in document pixels (its transform is a translation here).
Rect map_rect(const DisplayItem& it) {
    const Rect b = it.path.bounds();
    const Point p0 = it.transform.apply({b.x0, b.y0}), p1 = it.transform.apply({b.x1, b.y1});
    return Rect{p0.x, p0.y, p1.x, p1.y};
}

}  // namespace

TEST_CASE("svg display list: an inherited currentColor takes the colour of the element painted",
          "[svg][display_list]") {
    // CSS Color 4: currentColor computes to itself and is inherited as the keyword, so fill and
    // stroke set to currentColor on an outer group use the `color` of the rect, set in between.
    const svg::DisplayList fill =
        convert("<g fill='currentColor'><g color='green'><rect width='10' height='10'/></g></g>");
    REQUIRE(fill.size() == 1);
    CHECK(fill[0].color == Color::rgba(0, 128, 0));
    const svg::DisplayList stroke =
        convert("<g stroke='currentColor'><g color='#0000ff'><rect width='10' height='10' fill='none'/></g></g>");
    REQUIRE(stroke.size() == 1);
    CHECK(stroke[0].kind == DisplayItem::Stroke);
    CHECK(stroke[0].color == Color::rgba(0, 0, 255));
}

TEST_CASE("svg display list: the transform property of CSS wins over the attribute", "[svg][display_list]") {
    // SVG 2 makes transform a presentation attribute of the CSS transform property: a style sheet
    // or a style attribute overrides it. transform-origin is 0 0 for SVG elements.
    const svg::DisplayList sheet = convert(
        "<style>#r { transform: scale(2) }</style><rect id='r' width='10' height='10' transform='translate(5)'/>");
    REQUIRE(sheet.size() == 1);
    CHECK(sheet[0].transform == Affine{2, 0, 0, 2, 0, 0});
    const svg::DisplayList inline_style = convert("<rect width='10' height='10' style='transform:translate(3, 4)'/>");
    REQUIRE(inline_style.size() == 1);
    CHECK(inline_style[0].transform == Affine{1, 0, 0, 1, 3, 4});
}

TEST_CASE("svg display list: an unparsable transform is ignored, the element is drawn", "[svg][display_list]") {
    // An attribute value that does not parse is an error in the value: the attribute is treated as
    // not specified (the identity), as browsers do.
    const svg::DisplayList items = convert("<rect width='10' height='10' transform='qwe'/>");
    REQUIRE(items.size() == 1);
    CHECK(items[0].transform == Affine::identity());
}

TEST_CASE("svg display list: systemLanguage on the root svg can turn the document off", "[svg][display_list]") {
    // Conditional processing applies to the root as to any element: with the user language
    // English, a root for Russian only renders nothing.
    CHECK(svg::convert("<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10' systemLanguage='ru-RU'>"
                       "<rect width='10' height='10'/></svg>")
              .empty());
    CHECK(svg::convert("<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10' systemLanguage='en-US'>"
                       "<rect width='10' height='10'/></svg>")
              .size() == 1);
}

TEST_CASE("svg display list: elements outside the SVG namespace are not rendered", "[svg][display_list]") {
    // Namespaces in XML: an unprefixed element is in the default namespace in scope; here the
    // group redeclares it, so its unprefixed rect is not an SVG rect, while s:rect (s bound to
    // the SVG namespace) is.
    const svg::DisplayList items = convert(
        "<s:g xmlns='http://www.example.org/notsvg' xmlns:s='http://www.w3.org/2000/svg'>"
        "<s:rect width='10' height='10' fill='green'/><rect width='20' height='20' fill='red'/></s:g>");
    REQUIRE(items.size() == 1);
    CHECK(items[0].color == Color::rgba(0, 128, 0));
    CHECK(items[0].path.bounds() == Rect{0, 0, 10, 10});
}

TEST_CASE("svg display list: internal DTD entities are expanded", "[svg][display_list]") {
    // XML 1.0 section 4.4: an internal general entity is replaced by its text, in attribute values
    // and in content, where its markup is parsed as elements.
    const std::string doctype =
        "<!DOCTYPE svg [\n  <!ENTITY colour 'green'>\n"
        "  <!ENTITY two \"<rect width='1' height='1'/><rect x='5' width='1' height='&h;'/>\">\n"
        "  <!ENTITY h '2'>\n]>\n";
    const svg::DisplayList items =
        svg::convert(doctype + kSvgOpen + "<rect width='10' height='10' fill='&colour;'/><g>&two;</g></svg>");
    REQUIRE(items.size() == 3);
    CHECK(items[0].color == Color::rgba(0, 128, 0));
    CHECK(items[1].path.bounds() == Rect{0, 0, 1, 1});
    CHECK(items[2].path.bounds() == Rect{5, 0, 6, 2});  // &h; inside &two; expanded too
}

TEST_CASE("svg display list: entity expansion has limits against entity bombs", "[svg][display_list]") {
    // Each level multiplies the text by ten: nine levels would be 10^9 copies. Nesting past a
    // few levels (and expansions past the size cap) are refused with an error.
    std::string dtd = "<!DOCTYPE svg [<!ENTITY a0 'lol'>";
    for (int i = 1; i < 10; ++i) {
        dtd += "<!ENTITY a" + std::to_string(i) + " '";
        for (int k = 0; k < 10; ++k) dtd += "&a" + std::to_string(i - 1) + ";";
        dtd += "'>";
    }
    dtd += "]>";
    CHECK_THROWS_AS(svg::convert(dtd + kSvgOpen + "<text>&a9;</text></svg>"), Error);
    // A self-referencing entity is refused too.
    CHECK_THROWS_AS(svg::convert("<!DOCTYPE svg [<!ENTITY e 'x&e;'>]>" + kSvgOpen + "<text>&e;</text></svg>"), Error);
}

TEST_CASE("svg display list: clip-rule is inherited into a clipPath from its parent", "[svg][display_list]") {
    // clip-rule is an inherited property; a clipPath inside a group inherits the group's value
    // like any element, so its path clips with even-odd.
    const svg::DisplayList items = convert(
        "<g clip-rule='evenodd'><clipPath id='c'><rect width='50' height='50'/></clipPath></g>"
        "<rect width='100' height='100' clip-path='url(#c)'/>");
    REQUIRE(kinds(items) == std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill,
                                                           DisplayItem::BeginClip, DisplayItem::Fill,
                                                           DisplayItem::EndMask, DisplayItem::EndLayer});
    CHECK(items[3].rule == FillRule::EvenOdd);
}

TEST_CASE("svg display list: the root's background-color fills the whole canvas first", "[svg][display_list]") {
    // CSS backgrounds: the root element's background covers the whole canvas, under the content
    // and outside the viewBox mapping: one fill of the output rectangle in pixels.
    const svg::DisplayList items = svg::convert(
        "<svg xmlns='http://www.w3.org/2000/svg' width='40' height='20' viewBox='-10 -10 20 10' "
        "style='background-color: #0000ff80'><rect width='1' height='1'/></svg>");
    REQUIRE(items.size() == 2);
    CHECK(items[0].kind == DisplayItem::Fill);
    CHECK(items[0].transform == Affine::identity());
    CHECK(items[0].path.bounds() == Rect{0, 0, 40, 20});
    CHECK(items[0].color == Color::rgba(0, 0, 255, 128));
}

TEST_CASE("svg display list: a mask that names itself in its content draws that content unmasked",
          "[svg][display_list]") {
    // A reference cycle is an error the specification leaves open; the reference back into the
    // mask is dropped (taken as mask: none) and the rest drawn. The masked rect is drawn in a
    // layer, then the mask region (-10% .. 120% of the box: -1, -1, 12 x 12) clips the mask's
    // white rect, now without a mask of its own.
    const svg::DisplayList items = convert(
        "<mask id='m'><rect width='10' height='10' fill='white' mask='url(#m)'/></mask>"
        "<rect width='10' height='10' fill='green' mask='url(#m)'/>");
    REQUIRE(kinds(items) == std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill,
                                                           DisplayItem::BeginMask, DisplayItem::PushClip,
                                                           DisplayItem::Fill, DisplayItem::PopClip,
                                                           DisplayItem::EndMask, DisplayItem::EndLayer});
    CHECK(items[3].path.bounds() == Rect{-1, -1, 11, 11});
    CHECK(items[4].color == Color::white());
}

TEST_CASE("svg display list: of two masks that mask each other, the later one loses its mask", "[svg][display_list]") {
    // Masks are scanned in document order: mask a names b, and b names a back, so b's reference
    // is the one dropped. The rect masked by b gets b's content only (the 5 x 5 rect).
    const svg::DisplayList items = convert(
        "<mask id='a' mask='url(#b)'><rect width='10' height='10' fill='white'/></mask>"
        "<mask id='b' mask='url(#a)'><rect width='5' height='5' fill='white'/></mask>"
        "<rect width='10' height='10' mask='url(#b)'/>");
    REQUIRE(kinds(items) == std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill,
                                                           DisplayItem::BeginMask, DisplayItem::PushClip,
                                                           DisplayItem::Fill, DisplayItem::PopClip,
                                                           DisplayItem::EndMask, DisplayItem::EndLayer});
    CHECK(items[4].path.bounds() == Rect{0, 0, 5, 5});
}

TEST_CASE("svg display list: a marker's orient in grad", "[svg][display_list]") {
    // orient takes a CSS angle: 40grad is 40 * 360 / 400 = 36 degrees. The marker (user-space
    // units, overflow visible, ref 0 0) maps its content by translate(vertex) * rotate(36deg).
    const svg::DisplayList items = convert(
        "<marker id='m' markerUnits='userSpaceOnUse' orient='40grad' overflow='visible'>"
        "<rect width='1' height='1'/></marker><path d='M 10 10 L 20 10' fill='none' marker-start='url(#m)'/>");
    REQUIRE(kinds(items) ==
            std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill, DisplayItem::EndLayer});
    const double r = 36 * 3.14159265358979323846 / 180;
    CHECK(items[1].transform.a == Approx(std::cos(r)));
    CHECK(items[1].transform.b == Approx(std::sin(r)));
    CHECK(items[1].transform.e == Approx(10));
    CHECK(items[1].transform.f == Approx(10));
}

TEST_CASE("svg display list: a marker's percentages are of the viewport it is drawn in", "[svg][display_list]") {
    // refX, refY, markerWidth and markerHeight in percent resolve against the viewport the marked
    // shape is in (here 100 x 100): refX 5% = 5, refY 10% = 10, markerWidth 10% = 10 and
    // markerHeight 20% = 20. The content is placed with the reference point on the vertex
    // (20, 30), so the marker's clip rectangle (0, 0) 10 x 20 lands at (15, 20) .. (25, 40).
    const svg::DisplayList items = convert(
        "<marker id='m' markerUnits='userSpaceOnUse' refX='5%' refY='10%' markerWidth='10%' markerHeight='20%'>"
        "<rect width='1' height='1'/></marker><path d='M 20 30 L 40 30' fill='none' marker-start='url(#m)'/>");
    REQUIRE(kinds(items) == std::vector<DisplayItem::Kind>{DisplayItem::BeginLayer, DisplayItem::Fill,
                                                           DisplayItem::BeginClip, DisplayItem::Fill,
                                                           DisplayItem::EndMask, DisplayItem::EndLayer});
    CHECK(map_rect(items[3]) == Rect{15, 20, 25, 40});
}

TEST_CASE("svg display list: a singular patternTransform is ignored like a singular gradientTransform",
          "[svg][display_list]") {
    // A patternTransform that cannot be inverted maps the whole tile onto a line: it is ignored
    // (the identity), as a singular gradientTransform is, and the pattern is used untransformed.
    const svg::DisplayList items = convert(
        "<pattern id='p' patternUnits='userSpaceOnUse' width='10' height='10' patternTransform='matrix(0 0 0 0 0 0)'>"
        "<rect width='5' height='5'/></pattern><rect width='20' height='20' fill='url(#p)'/>");
    REQUIRE(items.size() == 1);
    REQUIRE(items[0].pattern);
    CHECK(items[0].pattern->transform == Affine::identity());
    CHECK(items[0].pattern->tile == Rect{0, 0, 10, 10});
}

TEST_CASE("svg display list: a radial gradient with fr equal to r", "[svg][display_list]") {
    // With fr = r around one centre there is no cone between the two circles; as Skia and resvg
    // draw it (pad spread), the first stop's colour fills the circle and the last one the rest.
    // In bounding-box units the circle is centred at (0.5, 0.5) with radius 0.5.
    const svg::DisplayList items = convert(
        "<radialGradient id='g' fr='0.5'><stop offset='0' stop-color='black'/>"
        "<stop offset='1' stop-color='white'/></radialGradient><rect width='20' height='20' fill='url(#g)'/>");
    REQUIRE(items.size() == 1);
    REQUIRE(items[0].shader);
    float c[4];
    double t = -1;
    REQUIRE(items[0].shader->parameter({0.5, 0.6}, t));  // inside the circle
    items[0].shader->color_at(t, c);
    CHECK(c[0] == Approx(0));
    CHECK(c[3] == Approx(1));
    REQUIRE(items[0].shader->parameter({0.02, 0.02}, t));  // a corner, outside it
    items[0].shader->color_at(t, c);
    CHECK(c[0] == Approx(1));
    CHECK(c[3] == Approx(1));
}
