// LeakSanitizer's check at exit with many threads holding a block of a dlopen'ed module's
// thread-local storage. Up to GCC 13 (LLVM 16) the sanitizer runtime's __tls_get_addr
// interceptor takes a block that starts 16 bytes into a page for one with glibc 2.19's header
// and reads the two words before it, here ASan's own chunk header, as the block's start and
// size; the check at exit then scans that range and its tracer dies ("Tracer caught signal
// 11"). Where a block lands is a matter of allocation order, so a program with a few such
// blocks (every program that opens a window or reads a picture) failed now and then; this one
// has enough that some block always lands there. The ASan test preset turns the interceptor
// off (intercept_tls_get_addr=0); the probe exits 0 only then.
#include <dlfcn.h>
#include <pthread.h>
#include <unistd.h>

#include <cstdio>

namespace {

char* (*touch)() = nullptr;
pthread_barrier_t all_touched;

void* hold_a_block(void*) {
  touch();
  pthread_barrier_wait(&all_touched);
  for (;;) pause();  // alive at exit: LeakSanitizer scans its thread-local storage
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: dtls_probe MODULE\n");
    return 2;
  }
  void* module = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!module) {
    std::fprintf(stderr, "dtls_probe: %s\n", dlerror());
    return 1;
  }
  touch = reinterpret_cast<char* (*)()>(dlsym(module, "l2_dtls_touch"));
  if (!touch) {
    std::fprintf(stderr, "dtls_probe: %s has no l2_dtls_touch\n", argv[1]);
    return 1;
  }
  constexpr int kThreads = 200;
  pthread_barrier_init(&all_touched, nullptr, kThreads + 1);
  for (int i = 0; i < kThreads; ++i) {
    pthread_t thread;
    if (pthread_create(&thread, nullptr, hold_a_block, nullptr) != 0) {
      std::fprintf(stderr, "dtls_probe: cannot start thread %d\n", i);
      return 1;
    }
  }
  pthread_barrier_wait(&all_touched);
  return 0;
}
