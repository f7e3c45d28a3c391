// JPEG decoding (src/formats/jpeg.cpp): images encoded here with libjpeg decode to their size and
// close to their pixels; a file too short for the size it declares is refused before the image is
// allocated; truncations and corruptions end in InvalidData or an image, never a crash.
#include <catch2/catch.hpp>

#include <cstdio>
#include <jpeglib.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/image.hpp"

using namespace casteljau;

namespace {

// A w x h RGB (or greyscale) JPEG of a smooth gradient, baseline or progressive, from libjpeg.
std::vector<std::uint8_t> encode_jpeg(int w, int h, bool grey, bool progressive, int quality = 90) {
    jpeg_compress_struct c{};
    jpeg_error_mgr err{};
    c.err = jpeg_std_error(&err);
    jpeg_create_compress(&c);
    unsigned char* out = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&c, &out, &size);
    c.image_width = static_cast<JDIMENSION>(w);
    c.image_height = static_cast<JDIMENSION>(h);
    c.input_components = grey ? 1 : 3;
    c.in_color_space = grey ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, quality, TRUE);
    if (progressive) jpeg_simple_progression(&c);
    jpeg_start_compress(&c, TRUE);
    std::vector<unsigned char> row(static_cast<std::size_t>(w) * c.input_components);
    while (c.next_scanline < c.image_height) {
        const int y = static_cast<int>(c.next_scanline);
        for (int x = 0; x < w; ++x)
            for (int k = 0; k < c.input_components; ++k)
                row[static_cast<std::size_t>(x * c.input_components + k)] =
                    static_cast<unsigned char>(x * 200 / std::max(1, w - 1) + k * 10 + y % 20);
        JSAMPROW r[1] = {row.data()};
        jpeg_write_scanlines(&c, r, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    std::vector<std::uint8_t> bytes(out, out + size);
    std::free(out);
    return bytes;
}

}  // namespace

TEST_CASE("decode_jpeg: baseline and progressive, RGB and grey, decode to their size and pixels", "[jpeg]") {
    for (bool grey : {false, true})
        for (bool progressive : {false, true}) {
            INFO((grey ? "grey" : "RGB") << (progressive ? ", progressive" : ", baseline"));
            const auto bytes = encode_jpeg(37, 21, grey, progressive);
            CHECK(sniff_image(bytes) == ImageFormat::Jpeg);
            const Pixmap p = decode_image(bytes);
            REQUIRE(p.width() == 37);
            REQUIRE(p.height() == 21);
            // Opaque, and near the encoded gradient (quality 90: within a few levels).
            int worst = 0;
            for (int y = 0; y < 21; ++y)
                for (int x = 0; x < 37; ++x) {
                    const std::uint8_t* px = p.row(y) + 4 * x;
                    CHECK(px[3] == 255);
                    const int want = x * 200 / 36 + y % 20;
                    worst = std::max(worst, std::abs(px[0] - want));
                    if (grey) CHECK((px[0] == px[1] && px[1] == px[2]));
                }
            CHECK(worst <= 8);
        }
}

TEST_CASE("decode_jpeg: a file too short for its declared size is refused before allocating the image", "[jpeg]") {
    // Found by fuzz_image: 265 bytes declaring 4160 x 13824 pixels; libjpeg pads missing data, so
    // the decoder allocated and filled a 230 MB image. Huffman coding needs a bit per 8x8 block.
    const auto bytes =
        read_file(std::string(CASTELJAU_SOURCE_DIR) + "/fuzz/regressions/image/jpeg-265-bytes-declaring-57-megapixels");
    REQUIRE(bytes.size() == 265);
    try {
        (void)decode_jpeg(bytes);
        FAIL("decoded");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::InvalidData);
        CHECK_THAT(e.what(),
                   Catch::Contains("4160x13824 pixels need at least 112320 bytes of coded data, the file has 265"));
    }
    // A real 2000 x 1500 image cut to its first 1 KB: refused the same way.
    const auto big = encode_jpeg(2000, 1500, false, false, 50);
    const std::vector<std::uint8_t> head(big.begin(), big.begin() + 1024);
    CHECK_THROWS_AS(decode_jpeg(head), Error);
}

TEST_CASE("decode_jpeg: truncations and corruptions end in InvalidData or an image of the declared size", "[jpeg]") {
    const auto good = encode_jpeg(48, 40, false, true);
    std::mt19937 rng(11);
    int images = 0, errors = 0;
    for (int trial = 0; trial < 600; ++trial) {
        std::vector<std::uint8_t> bad = good;
        if (trial % 2 == 0) {
            bad.resize(static_cast<std::size_t>(rng() % good.size()));
        } else {
            for (int f = 0; f < 1 + trial % 4; ++f)
                bad[2 + rng() % (bad.size() - 2)] ^= static_cast<std::uint8_t>(1 + rng() % 255);
        }
        try {
            const Pixmap p = decode_image(bad);
            CHECK(p.width() >= 1);
            CHECK(p.height() >= 1);
            ++images;
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::InvalidData);
            ++errors;
        }
    }
    CHECK(images + errors == 600);
    CHECK(errors > 0);
}
