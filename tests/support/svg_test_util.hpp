// Test helper: an SVG document of a given pixel size around a body of elements (with the SVG and
// XLink namespaces declared), for tests that draw small documents.
#pragma once

#include <zlib.h>

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace casteljau::test {

// `text` compressed as gzip (the bytes of an .svgz).
inline std::string gzip(const std::string& text) {
    std::vector<unsigned char> gz(compressBound(static_cast<uLong>(text.size())) + 64);
    z_stream z{};
    REQUIRE(deflateInit2(&z, 9, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) == Z_OK);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    z.avail_in = static_cast<uInt>(text.size());
    z.next_out = gz.data();
    z.avail_out = static_cast<uInt>(gz.size());
    REQUIRE(deflate(&z, Z_FINISH) == Z_STREAM_END);
    gz.resize(z.total_out);
    deflateEnd(&z);
    return std::string(gz.begin(), gz.end());
}

inline std::string svg_text(const std::string& body, int width, int height) {
    return "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' width='" +
           std::to_string(width) + "' height='" + std::to_string(height) + "'>" + body + "</svg>";
}

}  // namespace casteljau::test
