// libFuzzer target: the CSS reader of SVG style sheets (src/formats/svg/css.hpp). The input is split
// at the first NUL byte: the part before is a style sheet, the part after is a style attribute's
// declarations; every parsed selector is matched against the elements of a small fixed document.
#include <pugixml.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/svg/css.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view all(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = all.find('\0');
    const std::string_view sheet_text = all.substr(0, nul);
    const std::string_view decl_text = nul == std::string_view::npos ? std::string_view{} : all.substr(nul + 1);
    casteljau::css::StyleSheet sheet;
    casteljau::css::parse_stylesheet(sheet_text, sheet);
    (void)casteljau::css::parse_declarations(decl_text);
    static const char* kDoc =
        "<svg id='root' class='a b'><g class='x'><rect id='r' class='c' "
        "data-k='v-1'/><circle/></g><g><g><path/></g></g></svg>";
    pugi::xml_document doc;
    doc.load_string(kDoc);
    for (const pugi::xpath_node& xn : doc.select_nodes("//*"))
        for (const casteljau::css::Rule& r : sheet.rules) (void)casteljau::css::matches(r.selector, xn.node());
    return 0;
}
