// Encode stage: PNG through libpng (include/casteljau/png.hpp).
//
// Decoding uses libpng's classic API with explicit transformations, so every PNG (palette with or
// without tRNS, grey 1/2/4/8/16 bits, grey+alpha, RGB, RGBA, 16-bit, Adam7-interlaced) comes out
// as straight RGBA8 with no gamma or colour conversion (gAMA, cHRM, sRGB and iCCP are ignored);
// 16-bit samples are scaled to 8 bits with rounding (png_set_scale_16). The size in the header is
// checked against casteljau::limits before any pixel memory is allocated. Encoding writes 8-bit
// samples with straight alpha in the smallest colour type that holds the pixels exactly (grey, grey
// + alpha, RGB or RGBA), with the zlib level and row filter of PngEncodeOptions, and an sRGB chunk
// (with the gAMA and cHRM that the PNG specification asks to accompany it). The default filters
// (none, or none or Paeth per row) are written by png_direct.cpp, the same rows deflated by
// libdeflate in less time; the others by libpng.
//
// libpng reports errors with longjmp. Each function here that calls setjmp holds only trivially
// destructible locals, and so do the callbacks libpng calls, so a longjmp never skips a C++
// destructor; every C++ object (Pixmap, vectors, the libpng handles' guards) lives in the caller.
#include "casteljau/png.hpp"
#include "formats/straight_alpha.hpp"

#include <png.h>

#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/limits.hpp"
#include "formats/png_direct.hpp"

namespace casteljau {

namespace {

// --- libpng plumbing ------------------------------------------------------------------------

// Shared by the read and write paths: where the error callback leaves libpng's message.
struct ErrorSink {
    char message[256] = "unknown libpng error";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp msg) {
    auto* sink = static_cast<ErrorSink*>(png_get_error_ptr(png));
    if (sink != nullptr) {
        std::snprintf(sink->message, sizeof sink->message, "%s", msg != nullptr ? msg : "unknown libpng error");
    }
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // warnings (bad ancillary chunks...) are ignored

struct ReadState {
    ErrorSink sink;
    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
    std::size_t pos = 0;
};

void read_from_memory(png_structp png, png_bytep out, std::size_t n) {
    auto* st = static_cast<ReadState*>(png_get_io_ptr(png));
    if (n > st->size - st->pos) png_error(png, "the data ends early (truncated file)");
    std::memcpy(out, st->data + st->pos, n);
    st->pos += n;
}

struct ReadHandles {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ReadHandles() = default;
    ReadHandles(const ReadHandles&) = delete;
    ReadHandles& operator=(const ReadHandles&) = delete;
    ~ReadHandles() { png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr); }
};

// Phase 1: signature and header chunks up to the first IDAT. No C++ objects with destructors here.
bool png_read_header(png_structp png, png_infop info, png_uint_32* width, png_uint_32* height) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    *width = png_get_image_width(png, info);
    *height = png_get_image_height(png, info);
    return true;
}

// Phase 2: converts any colour type and bit depth to RGBA8 and reads all rows (every Adam7 pass
// when interlaced) into `rows`, which the caller sized from the checked header. No C++ objects
// with destructors here.
bool png_read_rgba8(png_structp png, png_infop info, png_bytepp rows, std::size_t expected_rowbytes) {
    if (setjmp(png_jmpbuf(png))) return false;
    const int color_type = png_get_color_type(png, info);
    const int bit_depth = png_get_bit_depth(png, info);
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS) != 0) png_set_tRNS_to_alpha(png);
    if (bit_depth == 16) png_set_scale_16(png);
    if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    // Adds opaque alpha only where the image still has none after the tRNS expansion.
    if ((color_type & PNG_COLOR_MASK_ALPHA) == 0) png_set_filler(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_bit_depth(png, info) != 8 || png_get_channels(png, info) != 4 ||
        png_get_rowbytes(png, info) != expected_rowbytes)
        png_error(png, "could not convert the image to 8-bit RGBA");
    png_read_image(png, rows);
    return true;
}

struct WriteState {
    ErrorSink sink;
    std::vector<std::uint8_t>* out = nullptr;
};

void write_to_memory(png_structp png, png_bytep data, std::size_t n) {
    auto* st = static_cast<WriteState*>(png_get_io_ptr(png));
    bool ok = true;
    try {
        st->out->insert(st->out->end(), data, data + n);
    } catch (const std::bad_alloc&) { ok = false; }
    if (!ok) png_error(png, "out of memory while encoding");  // no C++ object is alive here
}

void flush_memory(png_structp) {}

struct WriteHandles {
    png_structp png = nullptr;
    png_infop info = nullptr;
    WriteHandles() = default;
    WriteHandles(const WriteHandles&) = delete;
    WriteHandles& operator=(const WriteHandles&) = delete;
    ~WriteHandles() { png_destroy_write_struct(&png, info != nullptr ? &info : nullptr); }
};

// The smallest colour type that holds every pixel of `pixmap` exactly. Premultiplication is
// injective for a given alpha, so equal premultiplied channels mean equal straight ones. Each row
// is reduced with bitwise operations on whole pixels, which the compiler vectorizes: the AND of
// the alphas is 255 only when all are, the OR of r ^ g and g ^ b is 0 only when every pixel is grey.
int smallest_colour_type(const Pixmap& pixmap) {
    bool opaque = true, grey = true;
    for (int y = 0; y < pixmap.height() && (opaque || grey); ++y) {
        const std::uint8_t* p = pixmap.row(y);
        unsigned alphas = 255, colour = 0;
        for (int x = 0; x < pixmap.width(); ++x, p += 4) {
            alphas &= p[3];
            colour |= static_cast<unsigned>(p[0] ^ p[1]) | static_cast<unsigned>(p[1] ^ p[2]);
        }
        opaque = opaque && alphas == 255;
        grey = grey && colour == 0;
    }
    if (grey) return opaque ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_GRAY_ALPHA;
    return opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA;
}

// The libpng filter set for `f`. Auto: no filter for grey pictures (antialiased art on a flat
// ground, whose long runs deflate finds best unfiltered), a per-row choice between none and Paeth
// for colour ones (Paeth keeps gradients and images small at a fraction of the cost of trying all
// five filters on every row).
int libpng_filter(PngFilter f, int colour_type) {
    switch (f) {
        case PngFilter::Auto:
            return (colour_type & PNG_COLOR_MASK_COLOR) ? (PNG_FILTER_NONE | PNG_FILTER_PAETH) : PNG_FILTER_NONE;
        case PngFilter::None: return PNG_FILTER_NONE;
        case PngFilter::Sub: return PNG_FILTER_SUB;
        case PngFilter::Up: return PNG_FILTER_UP;
        case PngFilter::Average: return PNG_FILTER_AVG;
        case PngFilter::Paeth: return PNG_FILTER_PAETH;
        case PngFilter::Adaptive: break;
    }
    return PNG_ALL_FILTERS;
}

struct EncodeSettings {
    int colour_type = PNG_COLOR_TYPE_RGB_ALPHA;
    int level = 6;
    int filter = PNG_ALL_FILTERS;
};

// Writes the whole image, un-premultiplying one row at a time into `row` (width x 4 bytes, owned
// by the caller) and keeping the channels `settings.colour_type` has. No C++ objects with
// destructors here.
bool png_write_pixels(png_structp png, png_infop info, const Pixmap* pixmap, png_bytep row,
                      const EncodeSettings* settings) {
    if (setjmp(png_jmpbuf(png))) return false;
    const int w = pixmap->width(), h = pixmap->height();
    const int type = settings->colour_type;
    png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8, type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_set_compression_level(png, settings->level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, settings->filter);
    png_write_info(png, info);
    const bool colour = (type & PNG_COLOR_MASK_COLOR) != 0, alpha = (type & PNG_COLOR_MASK_ALPHA) != 0;
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* p = pixmap->row(y);
        png_bytep q = row;
        for (int x = 0; x < w; ++x, p += 4) {
            if (p[3] == 255) {  // opaque: straight equals premultiplied
                *q++ = p[0];
                if (colour) {
                    *q++ = p[1];
                    *q++ = p[2];
                }
            } else {
                const Color c = unpremultiply(PremulPixel{p[0], p[1], p[2], p[3]});
                *q++ = c.r;
                if (colour) {
                    *q++ = c.g;
                    *q++ = c.b;
                }
            }
            if (alpha) *q++ = p[3];
        }
        png_write_row(png, row);
    }
    png_write_end(png, info);
    return true;
}

std::string quote(const std::string& path) { return "'" + path + "'"; }

}  // namespace

// --- PNG ------------------------------------------------------------------------------------

namespace png_detail {

std::vector<std::uint8_t> encode_png_libpng(const Pixmap& pixmap, int colour_type, int level, int filters) {
    EncodeSettings settings;
    settings.colour_type = colour_type;
    settings.level = level;
    settings.filter = filters;
    std::vector<std::uint8_t> out;
    out.reserve(4096);
    std::vector<std::uint8_t> row(pixmap.stride());
    WriteState state;
    state.out = &out;
    WriteHandles h;
    h.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state.sink, on_png_error, on_png_warning);
    if (h.png == nullptr) throw std::bad_alloc();
    h.info = png_create_info_struct(h.png);
    if (h.info == nullptr) throw std::bad_alloc();
    png_set_write_fn(h.png, &state, write_to_memory, flush_memory);
    if (!png_write_pixels(h.png, h.info, &pixmap, row.data(), &settings))
        throw Error(ErrorKind::InvalidData, std::string("PNG encoding failed: ") + state.sink.message);
    return out;
}

}  // namespace png_detail

std::vector<std::uint8_t> encode_png(const Pixmap& pixmap, const PngEncodeOptions& options) {
    if (pixmap.width() < 1 || pixmap.height() < 1)
        throw Error(ErrorKind::InvalidArgument, "cannot encode an empty Pixmap as PNG");
    if (options.compression_level < 0 || options.compression_level > 9)
        throw Error(ErrorKind::InvalidArgument,
                    "PNG compression level must be 0 to 9, got " + std::to_string(options.compression_level));
    const int colour_type = options.smallest_colour_type ? smallest_colour_type(pixmap) : PNG_COLOR_TYPE_RGB_ALPHA;
    const int filters = libpng_filter(options.filter, colour_type);
    if (filters == PNG_FILTER_NONE || filters == (PNG_FILTER_NONE | PNG_FILTER_PAETH))
        return png_detail::encode_png_direct(pixmap, colour_type, options.compression_level,
                                             filters != PNG_FILTER_NONE);
    return png_detail::encode_png_libpng(pixmap, colour_type, options.compression_level, filters);
}

namespace {

// libpng allocates an ancillary chunk's buffer at its declared length before reading the data, so
// a 3 KB file declaring a 2 GB text chunk would have it allocate 2 GB. The whole file is in memory
// here: walk the chunk headers first and refuse any chunk longer than what is left of the file.
// Returns the total length of the IDAT chunks.
std::uint64_t check_chunk_lengths(std::span<const std::uint8_t> bytes) {
    std::size_t at = 8;
    std::uint64_t idat = 0;
    while (at <= bytes.size() && bytes.size() - at >= 8) {
        const std::uint32_t length = (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
                                     (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
        const char type[5] = {static_cast<char>(bytes[at + 4]), static_cast<char>(bytes[at + 5]),
                              static_cast<char>(bytes[at + 6]), static_cast<char>(bytes[at + 7]), 0};
        const std::size_t left = bytes.size() - at - 8;
        if (length > left) {
            bool printable = true;
            for (int i = 0; i < 4; ++i) printable = printable && type[i] >= 0x21 && type[i] <= 0x7e;
            throw Error(ErrorKind::InvalidData,
                        "invalid PNG: chunk " +
                            (printable ? "'" + std::string(type) + "'" : std::string("of unknown type")) + " at byte " +
                            std::to_string(at) + " declares " + std::to_string(length) + " bytes but the file has " +
                            std::to_string(left) + " left (truncated or corrupt)");
        }
        if (std::string_view(type, 4) == "IDAT") idat += length;
        at += 12 + static_cast<std::size_t>(length);
        if (std::string_view(type, 4) == "IEND") break;
    }
    return idat;
}

}  // namespace

Pixmap decode_png(std::span<const std::uint8_t> bytes) {
    if (bytes.empty()) throw Error(ErrorKind::InvalidData, "not a PNG: the data is empty");
    if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0)
        throw Error(ErrorKind::InvalidData, "not a PNG: the PNG signature is missing");
    const std::uint64_t idat_bytes = check_chunk_lengths(bytes);
    ReadState state;
    state.data = bytes.data();
    state.size = bytes.size();
    ReadHandles h;
    h.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state.sink, on_png_error, on_png_warning);
    if (h.png == nullptr) throw std::bad_alloc();
    h.info = png_create_info_struct(h.png);
    if (h.info == nullptr) throw std::bad_alloc();
    png_set_read_fn(h.png, &state, read_from_memory);
    // Our own limits apply (below, as Error(Limit)); lift libpng's default 1e6-pixel side limit so
    // that every oversized header is reported the same way.
    png_set_user_limits(h.png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    // Compressed ancillary chunks (zTXt, iTXt, iCCP) inflate into buffers of their own: cap any
    // one chunk's buffer, and the number of ancillary chunks kept, at limits far above real files'.
    const Limits lim = current_limits();
    png_set_chunk_malloc_max(h.png, lim.png_chunk_bytes);
    png_set_chunk_cache_max(h.png, lim.png_ancillary_chunks);

    png_uint_32 width = 0, height = 0;
    if (!png_read_header(h.png, h.info, &width, &height))
        throw Error(ErrorKind::InvalidData, std::string("invalid PNG: ") + state.sink.message);
    if (width > static_cast<png_uint_32>(lim.canvas_dimension) ||
        height > static_cast<png_uint_32>(lim.canvas_dimension) ||
        static_cast<long long>(width) * static_cast<long long>(height) > lim.canvas_pixels)
        throw Error(ErrorKind::Limit, "PNG of " + std::to_string(width) + "x" + std::to_string(height) +
                                          " pixels exceeds the image limits (" + std::to_string(lim.canvas_dimension) +
                                          " pixels per side, " + std::to_string(lim.canvas_pixels) + " pixels in all)");
    if (width < 1 || height < 1) throw Error(ErrorKind::InvalidData, "invalid PNG: zero width or height");
    // Deflate expands at most 1032:1, so image data shorter than the filtered rows / 1032 cannot
    // hold the image: a header with the data missing or cut. Refuse it before allocating the image.
    {
        const int bits = png_get_bit_depth(h.png, h.info) * png_get_channels(h.png, h.info);
        const double row_bytes = std::ceil(static_cast<double>(width) * bits / 8) + 1;  // + filter byte
        const double needed = std::ceil(row_bytes * height / 1032);
        if (static_cast<double>(idat_bytes) < needed)
            throw Error(ErrorKind::InvalidData, "invalid PNG: " + std::to_string(width) + "x" + std::to_string(height) +
                                                    " pixels need at least " +
                                                    std::to_string(static_cast<long long>(needed)) +
                                                    " bytes of compressed data, the file has " +
                                                    std::to_string(idat_bytes) + " (truncated, or a corrupt size)");
    }

    Pixmap pixmap(static_cast<int>(width), static_cast<int>(height));
    std::vector<png_bytep> rows(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = pixmap.row(static_cast<int>(y));
    if (!png_read_rgba8(h.png, h.info, rows.data(), pixmap.stride()))
        throw Error(ErrorKind::InvalidData, std::string("invalid PNG: ") + state.sink.message);

    formats_detail::premultiply_in_place(pixmap);  // straight alpha in the file
    return pixmap;
}

void write_png(const Pixmap& pixmap, const std::string& path, const PngEncodeOptions& options) {
    write_file_atomic(path, encode_png(pixmap, options));
}

Pixmap read_png(const std::string& path) {
    const std::vector<std::uint8_t> bytes = read_file(path);
    try {
        return decode_png(bytes);
    } catch (const Error& e) { throw Error(e.kind(), quote(path) + ": " + e.what()); }
}

}  // namespace casteljau
