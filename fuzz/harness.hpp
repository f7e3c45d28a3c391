// The small harness every fuzz target shares: a reader that turns the fuzzer's bytes into the
// values a target needs (integers in a range, choices, doubles that are often hostile: NaN,
// infinities, 1e30, denormals, zero, values near the pixel grid), and the check that an input
// may only end in casteljau::Error. Targets define LLVMFuzzerTestOneInput and are built both as
// libFuzzer programs (CASTELJAU_BUILD_FUZZ, clang) and, with replay_main.cpp, as replay programs
// that ctest runs over the seed corpus and the regression corpus on every build.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <string_view>

#include "casteljau/error.hpp"

namespace casteljau::fuzz {

class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : p_(data), n_(size) {}

    bool empty() const { return n_ == 0; }
    std::size_t remaining() const { return n_; }

    std::uint8_t byte() {
        if (n_ == 0) return 0;
        --n_;
        return *p_++;
    }
    std::uint32_t u32() {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v = (v << 8) | byte();
        return v;
    }
    // An integer in [lo, hi].
    int range(int lo, int hi) {
        const std::uint32_t span = static_cast<std::uint32_t>(hi - lo) + 1u;
        return lo + static_cast<int>((hi - lo < 256 ? byte() : u32()) % span);
    }
    bool flag() { return byte() & 1; }
    // A coordinate-like double: mostly ordinary values in [-span, span] on a 1/64 grid or with a
    // random fraction, sometimes one of the values that break geometry code.
    double number(double span = 300) {
        const std::uint8_t kind = byte();
        switch (kind % 16) {
            case 0: {
                static const double kSpecial[] = {std::numeric_limits<double>::quiet_NaN(),
                                                  std::numeric_limits<double>::infinity(),
                                                  -std::numeric_limits<double>::infinity(),
                                                  1e30,
                                                  -1e30,
                                                  1e300,
                                                  std::numeric_limits<double>::denorm_min(),
                                                  -std::numeric_limits<double>::denorm_min(),
                                                  0.0,
                                                  -0.0,
                                                  std::numeric_limits<double>::max(),
                                                  1e-300,
                                                  0.5,
                                                  1 - 1e-16};
                return kSpecial[byte() % (sizeof kSpecial / sizeof kSpecial[0])];
            }
            case 1: {
                double d;
                std::uint64_t bits = (std::uint64_t(u32()) << 32) | u32();
                std::memcpy(&d, &bits, sizeof d);
                return d;
            }
            case 2: return static_cast<double>(static_cast<std::int32_t>(u32())) / 16.0;
            default: {
                const double grid = static_cast<double>(static_cast<std::int16_t>(u32() & 0xffff)) / 64.0;
                return std::fmod(grid, span);
            }
        }
    }
    // The rest of the input as text.
    std::string_view rest() {
        const std::string_view s(reinterpret_cast<const char*>(p_), n_);
        p_ += n_;
        n_ = 0;
        return s;
    }

private:
    const std::uint8_t* p_;
    std::size_t n_;
};

// Fails the run (abort, so that libFuzzer records the input) when `ok` is false.
inline void require(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
        std::abort();
    }
}

// Runs `body`; a casteljau::Error is an accepted outcome of bad input, anything else thrown is a
// finding.
template <class F>
void run(F&& body) {
    try {
        body();
    } catch (const casteljau::Error&) {}
}

}  // namespace casteljau::fuzz
