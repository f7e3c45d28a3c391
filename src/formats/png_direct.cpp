// Encode stage: PNG for the default row filters, the rows libpng would write deflated by
// libdeflate, or by zlib when the image is too large to hold filtered (src/formats/png_direct.hpp).
#include "formats/png_direct.hpp"
#include "formats/png_paeth.hpp"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <new>
#include <string>

#include "casteljau/error.hpp"
#include "core/pixel_memory.hpp"

namespace casteljau::png_detail {

namespace {

constexpr std::size_t kChunkData = 8192;  // libpng's IDAT size (PNG_ZBUF_SIZE)

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    const std::uint8_t b[4] = {static_cast<std::uint8_t>(v >> 24), static_cast<std::uint8_t>(v >> 16),
                               static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
    out.insert(out.end(), b, b + 4);
}

// Appends a chunk: length, type, data, CRC of type and data.
void put_chunk(std::vector<std::uint8_t>& out, const char (&type)[5], const std::uint8_t* data, std::size_t n) {
    put32(out, static_cast<std::uint32_t>(n));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    if (n) out.insert(out.end(), data, data + n);
    put32(out, static_cast<std::uint32_t>(crc32(0, out.data() + start, static_cast<uInt>(out.size() - start))));
}

void put_header(std::vector<std::uint8_t>& out, int width, int height, int colour_type) {
    static constexpr std::uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    out.insert(out.end(), kSignature, kSignature + 8);
    std::vector<std::uint8_t> ihdr;
    put32(ihdr, static_cast<std::uint32_t>(width));
    put32(ihdr, static_cast<std::uint32_t>(height));
    ihdr.insert(ihdr.end(), {8, static_cast<std::uint8_t>(colour_type), 0, 0, 0});
    put_chunk(out, "IHDR", ihdr.data(), ihdr.size());
    // What png_set_sRGB_gAMA_and_cHRM writes: gamma 1/2.2 (x 100000), perceptual intent, and
    // the sRGB white point and primaries (x 100000).
    std::vector<std::uint8_t> gama;
    put32(gama, 45455);
    put_chunk(out, "gAMA", gama.data(), gama.size());
    const std::uint8_t intent = 0;
    put_chunk(out, "sRGB", &intent, 1);
    std::vector<std::uint8_t> chrm;
    for (std::uint32_t v : {31270u, 32900u, 64000u, 33000u, 30000u, 60000u, 15000u, 6000u}) put32(chrm, v);
    put_chunk(out, "cHRM", chrm.data(), chrm.size());
}

// A pixel's straight colour.
Color straight(const std::uint8_t* p) {
    return p[3] == 255 ? Color{p[0], p[1], p[2], 255} : unpremultiply(PremulPixel{p[0], p[1], p[2], p[3]});
}

// One row of the pixmap as the file's samples (straight alpha, the channels `colour_type` has).
// Opaque pixels, most of a picture, are copied as they are: a 4-byte store per pixel whose last
// byte the next pixel overwrites (`q` has a byte to spare past the row).
void convert_row(const std::uint8_t* p, int width, int colour_type, std::uint8_t* q) {
    switch (colour_type) {
        case kRgb:
            for (int x = 0; x < width; ++x, p += 4, q += 3) {
                if (p[3] == 255) {
                    std::memcpy(q, p, 4);
                } else {
                    const Color c = straight(p);
                    q[0] = c.r;
                    q[1] = c.g;
                    q[2] = c.b;
                }
            }
            return;
        case kGrey:
            for (int x = 0; x < width; ++x, p += 4) *q++ = straight(p).r;
            return;
        case kGreyAlpha:
            for (int x = 0; x < width; ++x, p += 4, q += 2) {
                q[0] = straight(p).r;
                q[1] = p[3];
            }
            return;
        default:
            for (int x = 0; x < width; ++x, p += 4, q += 4) {
                const Color c = straight(p);
                q[0] = c.r;
                q[1] = c.g;
                q[2] = c.b;
                q[3] = p[3];
            }
    }
}

// The zlib stream of the filtered rows, with libpng's parameters.
class Deflater {
public:
    Deflater(int level, std::size_t image_bytes, bool filtered) {
        // libpng shrinks the window for images smaller than it (png_deflate_claim).
        int window_bits = 15;
        if (image_bytes <= 16384) {
            unsigned half = 1u << (window_bits - 1);
            while (image_bytes + 262 <= half) {
                half >>= 1;
                --window_bits;
            }
        }
        const int strategy = filtered ? Z_FILTERED : Z_DEFAULT_STRATEGY;
        std::memset(&z_, 0, sizeof z_);
        if (deflateInit2(&z_, level, Z_DEFLATED, window_bits, 8, strategy) != Z_OK) throw std::bad_alloc();
        buffer_.resize(1 << 16);
    }
    ~Deflater() { deflateEnd(&z_); }
    Deflater(const Deflater&) = delete;
    Deflater& operator=(const Deflater&) = delete;

    void add(const std::uint8_t* data, std::size_t n, int flush) {
        z_.next_in = const_cast<Bytef*>(data);
        z_.avail_in = static_cast<uInt>(n);
        while (true) {
            z_.next_out = buffer_.data();
            z_.avail_out = static_cast<uInt>(buffer_.size());
            const int ret = deflate(&z_, flush);
            if (ret != Z_OK && ret != Z_STREAM_END && ret != Z_BUF_ERROR)
                throw Error(ErrorKind::InvalidData, "PNG encoding failed: zlib error " + std::to_string(ret));
            stream.insert(stream.end(), buffer_.data(), buffer_.data() + (buffer_.size() - z_.avail_out));
            if (ret == Z_STREAM_END || (flush == Z_NO_FLUSH && z_.avail_in == 0 && z_.avail_out != 0)) return;
        }
    }

    std::vector<std::uint8_t> stream;

private:
    z_stream z_;
    std::vector<std::uint8_t> buffer_;
};

// libpng lowers the window size the zlib header announces to what a small image needs
// (optimize_cmf), and recomputes the header's check bits.
void optimize_window_field(std::uint8_t* s, std::size_t size, std::size_t image_bytes) {
    if (image_bytes > 16384 || size < 2) return;
    unsigned cmf = s[0];
    if ((cmf & 0x0f) != 8 || (cmf & 0xf0) > 0x70) return;
    unsigned info = cmf >> 4, half = 1u << (info + 7);
    if (image_bytes > half) return;
    do {
        half >>= 1;
        --info;
    } while (info > 0 && image_bytes <= half);
    cmf = (cmf & 0x0f) | (info << 4);
    s[0] = static_cast<std::uint8_t>(cmf);
    unsigned flg = s[1] & 0xe0;
    flg += 0x1f - ((cmf << 8) + flg) % 0x1f;
    s[1] = static_cast<std::uint8_t>(flg);
}

// Hands each row, filter byte first, to `take(row, bytes)`: unfiltered, or Paeth-filtered when
// that makes libpng's heuristic sum smaller.
template <class Take>
void filter_rows(const Pixmap& pixmap, int colour_type, std::size_t channels, bool paeth, Take&& take) {
    const int w = pixmap.width(), h = pixmap.height();
    const std::size_t row_bytes = static_cast<std::size_t>(w) * channels;
    // Each buffer holds the filter byte, then the row, then a byte convert_row may write.
    std::vector<std::uint8_t> row(row_bytes + 2, 0), prev(row_bytes + 2, 0), filtered(row_bytes + 1, 4);
    for (int y = 0; y < h; ++y) {
        convert_row(pixmap.row(y), w, colour_type, row.data() + 1);
        const std::uint8_t* chosen = row.data();
        if (paeth) {
            const RowSums sums = paeth_row(row.data() + 1, prev.data() + 1, row_bytes, channels, filtered.data() + 1);
            if (sums.paeth < sums.none) chosen = filtered.data();
        }
        take(chosen, row_bytes + 1);
        row.swap(prev);
    }
}

// One libdeflate compressor per thread and level: allocating one costs more than deflating a
// small tile.
libdeflate_compressor* compressor_for(int level) {
    struct Owned {
        libdeflate_compressor* c = nullptr;
        ~Owned() { libdeflate_free_compressor(c); }
    };
    thread_local Owned cache[10];
    Owned& slot = cache[level];
    if (!slot.c) slot.c = libdeflate_alloc_compressor(level);
    if (!slot.c) throw std::bad_alloc();
    return slot.c;
}

// A zlib stream deflated in one piece: the memory it was written into and how much of it is the
// stream.
struct Stream {
    struct Release {
        std::size_t capacity = 0;
        void operator()(std::uint8_t* p) const noexcept { platform::release_sparse(p, capacity); }
    };
    std::unique_ptr<std::uint8_t[], Release> bytes;
    std::size_t size = 0;

    explicit Stream(std::size_t capacity)
        : bytes(static_cast<std::uint8_t*>(platform::allocate_sparse(capacity)), Release{capacity}) {
        if (!bytes) throw std::bad_alloc();
    }
};

// The zlib stream of the filtered rows deflated in one piece by libdeflate, into a buffer of the
// bound libdeflate needs (about the size of the rows) of which only the stream, usually a small
// fraction, is touched (platform::allocate_sparse).
Stream deflate_whole(const Pixmap& pixmap, int colour_type, std::size_t channels, bool paeth, int level,
                     std::size_t filtered_bytes) {
    std::vector<std::uint8_t> rows;
    rows.reserve(filtered_bytes);
    filter_rows(pixmap, colour_type, channels, paeth,
                [&](const std::uint8_t* r, std::size_t n) { rows.insert(rows.end(), r, r + n); });
    libdeflate_compressor* c = compressor_for(level);
    const std::size_t bound = libdeflate_zlib_compress_bound(c, rows.size());
    Stream out(bound);
    out.size = libdeflate_zlib_compress(c, rows.data(), rows.size(), out.bytes.get(), bound);
    if (out.size == 0)
        throw Error(ErrorKind::InvalidData, "PNG encoding failed: libdeflate found no room for the stream");
    return out;
}

// The zlib stream of the filtered rows through zlib, one row at a time, with libpng's parameters.
std::vector<std::uint8_t> deflate_streaming(const Pixmap& pixmap, int colour_type, std::size_t channels, bool paeth,
                                            int level, std::size_t image_bytes) {
    Deflater z(level, image_bytes, paeth);
    filter_rows(pixmap, colour_type, channels, paeth,
                [&](const std::uint8_t* r, std::size_t n) { z.add(r, n, Z_NO_FLUSH); });
    z.add(nullptr, 0, Z_FINISH);
    return std::move(z.stream);
}

// The PNG file of `stream` (`size` bytes, window field lowered for small images as libpng does).
std::vector<std::uint8_t> png_file(int w, int h, int colour_type, std::uint8_t* stream, std::size_t size,
                                   std::size_t image_bytes) {
    optimize_window_field(stream, size, image_bytes);
    std::vector<std::uint8_t> out;
    out.reserve(256 + size + size / kChunkData * 12);
    put_header(out, w, h, colour_type);
    for (std::size_t at = 0; at < size; at += kChunkData)
        put_chunk(out, "IDAT", stream + at, std::min(kChunkData, size - at));
    put_chunk(out, "IEND", nullptr, 0);
    return out;
}

}  // namespace

std::vector<std::uint8_t> encode_png_direct(const Pixmap& pixmap, int colour_type, int level, bool paeth,
                                            std::size_t whole_limit) {
    const int w = pixmap.width(), h = pixmap.height();
    const std::size_t channels = (colour_type & 2 ? 3 : 1) + (colour_type & 4 ? 1 : 0);
    const std::size_t row_bytes = static_cast<std::size_t>(w) * channels;
    // libpng drops the filters that need a row above or a pixel to the left when there is none.
    paeth = paeth && w > 1 && h > 1;
    const std::size_t filtered_bytes = (row_bytes + 1) * static_cast<std::size_t>(h);
    const std::size_t image_bytes = row_bytes < 32768 && h < 32768 ? filtered_bytes : 0xffffffffu;

    if (filtered_bytes <= whole_limit) {
        const Stream s = deflate_whole(pixmap, colour_type, channels, paeth, level, filtered_bytes);
        return png_file(w, h, colour_type, s.bytes.get(), s.size, image_bytes);
    }
    std::vector<std::uint8_t> s = deflate_streaming(pixmap, colour_type, channels, paeth, level, image_bytes);
    return png_file(w, h, colour_type, s.data(), s.size(), image_bytes);
}

}  // namespace casteljau::png_detail
