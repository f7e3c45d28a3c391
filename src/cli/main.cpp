// casteljau: command-line tool. A thin shell over the library (see run.cpp).
#include <csignal>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <iostream>

#include "cli/run.hpp"

int main(int argc, char** argv) {
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
