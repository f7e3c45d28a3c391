// SIMD dispatch (src/core/simd_dispatch.*): casteljau's own CPU detection against Highway's,
// target restriction for tests, and no libhwy in the command-line tool.
#include <catch2/catch.hpp>

#include <hwy/targets.h>

#include <cstdio>
#include <string>

#include "core/simd_dispatch.hpp"

using namespace casteljau;

TEST_CASE("simd dispatch: the CPU detection agrees with Highway's own for every compiled target", "[simd]") {
    // Highway's runtime library (linked into the tests only) is the independent reference.
    const std::int64_t compiled = HWY_TARGETS & ~(HWY_EMU128 | HWY_SCALAR);
    INFO("casteljau " << std::hex << (simd::cpu_targets() & compiled) << ", Highway "
                      << (hwy::SupportedTargets() & compiled));
    CHECK((simd::cpu_targets() & compiled) == (hwy::SupportedTargets() & compiled));
    CHECK((simd::cpu_targets() & HWY_STATIC_TARGET) != 0);
}

TEST_CASE("simd dispatch: available targets run best first, and restricting chooses each", "[simd]") {
    const auto targets = simd::available_targets();
    REQUIRE(!targets.empty());
    for (std::size_t i = 1; i < targets.size(); ++i) CHECK(targets[i - 1] < targets[i]);
    const std::size_t best = simd::chosen().GetIndex();
    std::size_t previous = 0;
    for (std::int64_t t : targets) {
        INFO(simd::target_name(t));
        CHECK(std::string(simd::target_name(t)) != "other");
        simd::restrict_targets(t);
        const std::size_t index = simd::chosen().GetIndex();
        CHECK(index > previous);  // each worse target sits further down the dispatch table
        previous = index;
    }
    simd::restrict_targets(0);
    CHECK(simd::chosen().GetIndex() == best);
}

TEST_CASE("simd dispatch: the command-line tool does not load libhwy", "[simd]") {
    // libhwy's load-time initializer costs milliseconds per process; the library only uses Highway's
    // headers. ldd lists every shared library the executable loads, directly or not.
    const std::string cmd = std::string("ldd '") + CASTELJAU_CLI_PATH + "' 2>&1";
    std::FILE* p = ::popen(cmd.c_str(), "r");
    REQUIRE(p != nullptr);
    std::string out;
    char buf[512];
    while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
    const int status = ::pclose(p);
    INFO(out);
    REQUIRE(status == 0);
    CHECK(out.find("libc.so") != std::string::npos);  // ldd did list the libraries
    CHECK(out.find("libhwy") == std::string::npos);
}
