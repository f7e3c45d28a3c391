// libFuzzer target: the file of system font fallback's answers kept across processes
// (src/text/fallback_cache.hpp), which is read back from the user's cache folder and so is
// untrusted. The input is the file's text. Checked: the reader ends every input in data or
// nothing (never a throw or a fault), accepted data is within the bounds the header states, writes
// back and reads again to the same data and the same text, and its stamp can be checked against
// the machine (the stamp names paths and variables the input chose; checking only reads them).
#include <cstdint>
#include <string>
#include <string_view>

#include "harness.hpp"
#include "text/fallback_cache.hpp"

using namespace casteljau;
using namespace casteljau::text_detail;

namespace {

bool same(const FallbackCacheData& a, const FallbackCacheData& b) {
    return a.stamp == b.stamp && a.faces == b.faces && a.answers == b.answers;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    fuzz::run([&] {
        const auto parsed = parse_fallback_cache(text);
        if (!parsed) return;
        fuzz::require(parsed->stamp.size() <= kMaxCacheStamp && parsed->faces.size() <= kMaxCacheFaces &&
                          parsed->answers.size() <= kMaxCacheAnswers,
                      "accepted data within the bounds");
        for (const auto& [key, face] : parsed->answers) {
            fuzz::require(!key.empty() && key.size() <= kMaxCacheKeyLength, "keys within bounds");
            fuzz::require(face >= -1 && face < static_cast<int>(parsed->faces.size()), "answers name a face");
        }
        const auto written = format_fallback_cache(*parsed);
        fuzz::require(written.has_value(), "accepted data writes back");
        fuzz::require(*written == text, "accepted text is exactly what the writer writes");
        const auto again = parse_fallback_cache(*written);
        fuzz::require(again && same(*again, *parsed), "written data reads back the same");
        if (parsed->stamp.size() <= 64) (void)stamp_is_current(parsed->stamp);
    });
    return 0;
}
