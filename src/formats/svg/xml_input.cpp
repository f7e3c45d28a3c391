// Formats stage, SVG: the XML input of xml_input.hpp (gzip inflation, SVG namespace prefixes).
#include "formats/svg/xml_input.hpp"

#include <zlib.h>

#include <algorithm>
#include <climits>
#include <cstdint>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"

namespace casteljau::svg {

// Inflates gzip data (an .svgz), up to Limits::svgz_bytes. Throws Error(InvalidData) for
// corrupt data, Error(Limit) past the limit.
std::string gunzip(std::string_view data) {
    z_stream z{};
    if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) throw Error(ErrorKind::InvalidData, "zlib initialisation failed");
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = static_cast<uInt>(std::min<std::size_t>(data.size(), UINT32_MAX));
    std::string out;
    const std::size_t max_bytes = current_limits().svgz_bytes;
    char buf[65536];
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
        z.next_out = reinterpret_cast<Bytef*>(buf);
        z.avail_out = sizeof buf;
        rc = inflate(&z, Z_NO_FLUSH);
        if (rc != Z_OK && rc != Z_STREAM_END) {
            inflateEnd(&z);
            throw Error(ErrorKind::InvalidData, "corrupt gzip data (.svgz)");
        }
        out.append(buf, sizeof buf - z.avail_out);
        if (out.size() > max_bytes) {
            inflateEnd(&z);
            throw Error(ErrorKind::Limit, "an .svgz inflates to more than " + std::to_string(max_bytes) + " bytes");
        }
        if (rc == Z_OK && z.avail_in == 0 && z.avail_out != 0) {
            inflateEnd(&z);
            throw Error(ErrorKind::InvalidData, "truncated gzip data (.svgz)");
        }
    }
    inflateEnd(&z);
    return out;
}

constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";

// Elements written with a prefix bound to the SVG namespace (<svg:svg xmlns:svg="...">) get their
// local name, so the reader sees <svg>; elements of other namespaces keep their prefixed names, and
// unprefixed elements under a default namespace other than SVG's get the prefix "foreign:", so
// they are skipped as unknown. Where no default namespace is declared, unprefixed elements are
// taken as SVG. `prefixes` holds the prefixes bound to the SVG namespace in scope.
void normalise_namespaces(pugi::xml_node node, std::vector<std::string> prefixes) {
    struct Scope {
        pugi::xml_node node;
        std::vector<std::string> prefixes;
        bool default_is_svg = true;
    };
    std::vector<Scope> stack;
    stack.push_back({node, std::move(prefixes)});
    while (!stack.empty()) {
        auto [n, scope, default_is_svg] = std::move(stack.back());
        stack.pop_back();
        for (const pugi::xml_attribute& a : n.attributes()) {
            const std::string_view name = a.name();
            if (name == "xmlns") default_is_svg = a.value() == kSvgNamespace;
            if (name.substr(0, 6) != "xmlns:") continue;
            const std::string prefix(name.substr(6));
            std::erase(scope, prefix);
            if (a.value() == kSvgNamespace) scope.push_back(prefix);
        }
        const std::string_view name = n.name();
        if (const std::size_t colon = name.find(':'); colon != std::string_view::npos) {
            const std::string prefix(name.substr(0, colon));
            if (std::find(scope.begin(), scope.end(), prefix) != scope.end())
                n.set_name(std::string(name.substr(colon + 1)).c_str());
        } else if (!default_is_svg) {
            n.set_name(("foreign:" + std::string(name)).c_str());
        }
        for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
            if (c.type() == pugi::node_element) stack.push_back({c, scope, default_is_svg});
    }
}

}  // namespace casteljau::svg
