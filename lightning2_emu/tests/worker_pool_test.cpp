// WorkerPool when the system will not start its threads.
#include "lightning2_emu/worker_pool.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <system_error>
#include <thread>

namespace l2 {
namespace {

using namespace std::chrono_literals;

// This process's address-space size in bytes (first field of /proc/self/statm, in pages).
long long address_space_bytes() {
  long long pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  return pages * ::sysconf(_SC_PAGESIZE);
}

// Exit status of child `pid`, or -1 if it has not ended within `within` (it is then killed).
int exit_within(pid_t pid, std::chrono::milliseconds within) {
  const auto deadline = std::chrono::steady_clock::now() + within;
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(10ms);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(WorkerPool, ThreadsThatCannotStartAreAnErrorNotAHang) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizers' shadow memory does not fit under an address-space limit";
#endif
  // In a child whose address space has room for a few thread stacks (8 MiB each) but not 200:
  // `lightning2_emu route --threads 5000` under `ulimit -v` hung in the constructor.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const rlimit limit{static_cast<rlim_t>(address_space_bytes() + (64 << 20)),
                       static_cast<rlim_t>(address_space_bytes() + (64 << 20))};
    if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(3);
    try {
      WorkerPool pool(200);
      ::_exit(1);  // every thread started: the limit did not bite
    } catch (const std::system_error&) {
      ::_exit(0);
    } catch (...) {
      ::_exit(2);
    }
  }
  EXPECT_EQ(exit_within(pid, 10s), 0) << "-1: hung; 1: no thread failed to start; 2: other error";
}

}  // namespace
}  // namespace l2
