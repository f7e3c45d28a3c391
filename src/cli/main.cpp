// casteljau: command-line tool. A thin shell over the library (see run.cpp).
#include <csignal>
#include <cstdlib>
#include <cstring>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#if defined(__linux__)
#include <unistd.h>
#endif
#include <iostream>
#include <string>

#include "cli/run.hpp"

namespace {

// The map commands run the process again, once, with glibc's malloc asked to back its heap with
// transparent huge pages (the glibc.malloc.hugetlb tunable, read only at start-up): the first touch
// of the heap then costs a page fault per 2 MB instead of one per 4 KB, which on a virtual machine
// is a third of a small map's drawing time, against a few milliseconds for loading the program
// twice. Nothing happens where the tunable is set already (to any value), and if the exec fails
// the process goes on as it is.
void reexec_with_huge_page_heap(int argc, char** argv) {
#if defined(__GLIBC__) && defined(__linux__)
    if (argc < 2 || (std::strcmp(argv[1], "map") != 0 && std::strcmp(argv[1], "tiles") != 0)) return;
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return;
    std::string value = "glibc.malloc.hugetlb=1";
    if (tunables && *tunables) value = std::string(tunables) + ":" + value;
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
    execv("/proc/self/exe", argv);
#else
    (void)argc;
    (void)argv;
#endif
}

}  // namespace

int main(int argc, char** argv) {
    reexec_with_huge_page_heap(argc, argv);
    // Past a file-size limit (ulimit -f) the kernel sends SIGXFSZ, whose default action kills the
    // process without a word and leaves the temporary file behind; ignored, the write fails with
    // EFBIG and the writer reports it and removes its temporary file.
    std::signal(SIGXFSZ, SIG_IGN);
#ifdef __GLIBC__
    // The process lives for one job: memory it frees is kept for its next allocations instead of
    // being unmapped and mapped again, which costs a page fault per 4 KB touched (a small map's
    // drawing spends a fifth of its time there). Blocks of 64 MB and more still get their own
    // mapping, so freeing them returns them at once.
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
    return casteljau::cli::run(argc, argv, true, std::cout, std::cerr);
}
