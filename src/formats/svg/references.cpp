// Formats stage, SVG: href links between elements (references.hpp).
#include "formats/svg/references.hpp"

#include <algorithm>

namespace casteljau::svg {

const char* href(const pugi::xml_node& n) {
    if (const char* h = n.attribute("href").value(); *h) return h;
    return n.attribute("xlink:href").value();
}

std::vector<pugi::xml_node> href_chain(const pugi::xml_node& first,
                                       const std::function<pugi::xml_node(std::string_view)>& lookup,
                                       std::initializer_list<std::string_view> names) {
    std::vector<pugi::xml_node> chain{first};
    while (chain.size() < 32) {
        const char* h = href(chain.back());
        if (*h != '#') break;
        const pugi::xml_node next = lookup(h + 1);
        if (!next || std::find(names.begin(), names.end(), std::string_view(next.name())) == names.end()) break;
        if (std::find(chain.begin(), chain.end(), next) != chain.end()) break;
        chain.push_back(next);
    }
    return chain;
}

}  // namespace casteljau::svg
