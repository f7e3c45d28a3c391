// casteljau/threads.hpp: how many threads casteljau's own parallel work may use.
//
// Maps (render_map: projection and horizontal bands), tile pyramids (a metatile per thread) and
// large blurs split their work over threads. All of them draw helpers from one process-wide pool
// of thread_count() threads, the calling thread included: concurrent calls from several of the
// program's threads share it instead of each starting its own, and per-call settings
// (MapOptions::threads, TileOptions::threads) can only ask for fewer. The pool's threads start on
// first use and sleep between calls. The output never depends on the number of threads.
//
// Thread-safety: both functions may be called from any thread, but not from inside a callback
// that casteljau runs (set_thread_count waits for the pool's threads to finish what they are
// helping with). In a child process after fork() the pool is not used: calls run on the calling
// thread alone.
#pragma once

namespace casteljau {

// Sets the pool's size: 1 runs everything on the calling thread; 0 (the default) uses every
// hardware thread. Throws Error(ErrorKind::InvalidArgument) outside 0..256.
void set_thread_count(int threads);

// The pool's size (1..256).
int thread_count();

}  // namespace casteljau
