// Test helpers for the PNG tests: a PNG writer with full control over colour type, bit depth,
// palette, tRNS and interlacing (libpng's classic writer), a raw chunk builder for hand-made
// headers, and stb_image as an independent decoder. Header-only; every function is inline or
// static so that several test files can include it.
#pragma once

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wpedantic"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace png_test {

// What to write: rows are already packed as PNG stores them (sub-byte samples MSB first, 16-bit
// samples big-endian).
struct Spec {
    png_uint_32 width = 1, height = 1;
    int bit_depth = 8;
    int color_type = PNG_COLOR_TYPE_RGB_ALPHA;
    bool interlace = false;
    std::vector<png_color> palette;
    std::vector<png_byte> trans_alpha;  // palette tRNS
    bool has_trans_color = false;       // grey/RGB tRNS
    png_color_16 trans_color{};
    std::vector<std::vector<png_byte>> rows;
};

struct Sink {
    std::vector<std::uint8_t> bytes;
};

inline void sink_write(png_structp png, png_bytep data, std::size_t n) {
    auto* s = static_cast<Sink*>(png_get_io_ptr(png));
    s->bytes.insert(s->bytes.end(), data, data + n);
}
inline void sink_flush(png_structp) {}
[[noreturn]] inline void sink_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
inline void sink_warning(png_structp, png_const_charp) {}

// setjmp scope: no C++ objects with destructors in here.
inline bool write_spec_rows(png_structp png, png_infop info, const Spec* spec, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, spec->width, spec->height, spec->bit_depth, spec->color_type,
                 spec->interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (!spec->palette.empty()) png_set_PLTE(png, info, spec->palette.data(), static_cast<int>(spec->palette.size()));
    if (!spec->trans_alpha.empty() || spec->has_trans_color)
        png_set_tRNS(png, info, spec->trans_alpha.empty() ? nullptr : spec->trans_alpha.data(),
                     static_cast<int>(spec->trans_alpha.size()), spec->has_trans_color ? &spec->trans_color : nullptr);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

inline std::vector<std::uint8_t> write_spec(const Spec& spec) {
    Sink sink;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, sink_error, sink_warning);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(png, &sink, sink_write, sink_flush);
    std::vector<png_bytep> rows;
    for (const auto& r : spec.rows) rows.push_back(const_cast<png_bytep>(r.data()));
    const bool ok = write_spec_rows(png, info, &spec, rows.data());
    png_destroy_write_struct(&png, &info);
    if (!ok) throw std::runtime_error("test PNG writer failed");
    return std::move(sink.bytes);
}

// Packs samples (already in [0, 2^depth)) into one PNG row.
inline std::vector<png_byte> pack(const std::vector<unsigned>& samples, int depth) {
    std::vector<png_byte> out;
    if (depth == 16) {
        for (unsigned s : samples) {
            out.push_back(static_cast<png_byte>(s >> 8));
            out.push_back(static_cast<png_byte>(s & 0xff));
        }
    } else if (depth == 8) {
        for (unsigned s : samples) out.push_back(static_cast<png_byte>(s));
    } else {
        const int per_byte = 8 / depth;
        out.assign((samples.size() + static_cast<std::size_t>(per_byte) - 1) / static_cast<std::size_t>(per_byte), 0);
        for (std::size_t i = 0; i < samples.size(); ++i) {
            const int shift = 8 - depth * (static_cast<int>(i % static_cast<std::size_t>(per_byte)) + 1);
            out[i / static_cast<std::size_t>(per_byte)] |= static_cast<png_byte>(samples[i] << shift);
        }
    }
    return out;
}

// A PNG chunk: length, type, data, CRC over type and data.
inline void append_chunk(std::vector<std::uint8_t>& out, const char type[4], const std::vector<std::uint8_t>& data) {
    auto be32 = [&](std::uint32_t v) {
        for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>(v >> s));
    };
    be32(static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    be32(static_cast<std::uint32_t>(crc32(0L, out.data() + start, static_cast<uInt>(out.size() - start))));
}

// Signature + IHDR (8-bit RGBA) with the given size + one IDAT holding a single compressed zero
// byte (far too little data for any image) + IEND.
inline std::vector<std::uint8_t> header_only_png(std::uint32_t width, std::uint32_t height) {
    std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<std::uint8_t> ihdr;
    for (std::uint32_t v : {width, height})
        for (int s = 24; s >= 0; s -= 8) ihdr.push_back(static_cast<std::uint8_t>(v >> s));
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // depth 8, RGBA, deflate, adaptive, no interlace
    append_chunk(out, "IHDR", ihdr);
    const Bytef zero[1] = {0};
    std::vector<std::uint8_t> idat(64);
    uLongf idat_size = static_cast<uLongf>(idat.size());
    if (compress2(idat.data(), &idat_size, zero, 1, 9) != Z_OK) throw std::runtime_error("zlib compress2 failed");
    idat.resize(idat_size);
    append_chunk(out, "IDAT", idat);
    append_chunk(out, "IEND", {});
    return out;
}

// Decodes with stb_image (an independent decoder) to straight RGBA8; empty on failure.
inline std::vector<std::uint8_t> stb_decode_rgba8(const std::vector<std::uint8_t>& bytes, int& width, int& height) {
    int channels = 0;
    stbi_uc* p = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, 4);
    if (p == nullptr) return {};
    std::vector<std::uint8_t> out(p, p + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(p);
    return out;
}

}  // namespace png_test
