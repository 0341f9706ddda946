// DviLink with real shared memory and real child processes: frames cross byte-exact, a dead
// writer's segment is cleaned up, and every misuse is one clear error naming the segment.
#include "dvi_link/dvi_link.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace l2 {
namespace {

using namespace std::chrono_literals;

// The test's own picture for frame k: every byte differs between neighbours and frames.
std::uint8_t pattern(int x, int y, int channel, int k) {
  return static_cast<std::uint8_t>(x * 7 + y * 13 + channel * 101 + k * 37);
}

void draw_pattern(DviLinkWriter& w, int k) {
  for (int y = 0; y < w.height(); ++y) {
    std::span<std::uint8_t> row = w.back_row(y);
    for (int x = 0; x < w.width(); ++x) {
      for (int c = 0; c < 3; ++c) row[static_cast<std::size_t>(x * 3 + c)] = pattern(x, y, c, k);
    }
  }
}

// Number of bytes that differ from pattern k (0 = byte-exact).
int mismatches(const FrameView& v, int k) {
  int bad = 0;
  for (int y = 0; y < v.height; ++y) {
    std::span<const std::uint8_t> row = v.row(y);
    for (int x = 0; x < v.width; ++x) {
      for (int c = 0; c < 3; ++c)
        bad += row[static_cast<std::size_t>(x * 3 + c)] != pattern(x, y, c, k);
    }
  }
  return bad;
}

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const DviLinkError& e) {
    return e.what();
  }
  return "no error";
}

bool segment_exists(const std::string& name) {
  const int fd = ::shm_open(name.c_str(), O_RDONLY, 0);
  if (fd >= 0) ::close(fd);
  return fd >= 0;
}

// One byte through a pipe: how parent and child take turns.
void send_byte(int fd) {
  const char b = 1;
  ASSERT_EQ(::write(fd, &b, 1), 1);
}
bool receive_byte(int fd) {
  char b = 0;
  return ::read(fd, &b, 1) == 1;
}

// A child process that runs `body` and exits with its result; gtest state stays in the parent.
template <typename Body>
pid_t fork_child(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    int code = 0;
    try {
      code = body();
    } catch (...) {
      code = 99;
    }
    ::_exit(code);
  }
  return pid;
}

int wait_exit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(DviLinkName, IsPrefixedWithThePid) {
  EXPECT_EQ(dvi_link_name("pipe0"), "/l2-" + std::to_string(::getpid()) + "-pipe0");
  EXPECT_EQ(error_of([] { dvi_link_name("a/b"); }),
            "DVI link name \"/l2-" + std::to_string(::getpid()) +
                "-a/b\" is invalid: it must be '/' followed by 1 to 254 characters without '/'");
}

TEST(DviLink, ReaderOnAMissingSegmentIsAClearError) {
  const std::string name = dvi_link_name("missing");
  EXPECT_EQ(error_of([&] { DviLinkReader::open(name); }),
            "DVI link " + name + ": cannot open shared-memory segment: No such file or directory");
}

TEST(DviLink, FrameSizeOutOfRangeIsAClearError) {
  const std::string name = dvi_link_name("size");
  EXPECT_EQ(error_of([&] { DviLinkWriter::create(name, 0, 10); }),
            "DVI link " + name + ": frame size 0x10 is outside 1x1 .. 8192x8192");
  EXPECT_FALSE(segment_exists(name));
}

TEST(DviLink, ReaderSeesEachPublishedFrameInPlace) {
  DviLinkWriter writer = DviLinkWriter::create(dvi_link_name("inproc"), 7, 5);
  DviLinkReader reader = DviLinkReader::open(writer.name());
  EXPECT_EQ(reader.width(), 7);
  EXPECT_EQ(reader.height(), 5);
  EXPECT_FALSE(reader.latest().has_value());  // nothing published yet
  ASSERT_EQ(writer.back_frame().size(), 7u * 5u * 3u);
  draw_pattern(writer, 1);
  EXPECT_EQ(writer.publish(), 1u);
  std::optional<FrameView> v = reader.latest();
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->sequence, 1u);
  EXPECT_EQ(v->stride, 21u);
  EXPECT_EQ(mismatches(*v, 1), 0);
  // No new publish: the same frame again.
  EXPECT_EQ(reader.latest()->sequence, 1u);
  // Two publishes between reads: the reader gets the newest, never the older one.
  draw_pattern(writer, 2);
  writer.publish();
  draw_pattern(writer, 3);
  EXPECT_EQ(writer.publish(), 3u);
  v = reader.latest();
  EXPECT_EQ(v->sequence, 3u);
  EXPECT_EQ(mismatches(*v, 3), 0);
}

TEST(DviLink, BackRowOutsideTheFrameIsAnError) {
  DviLinkWriter writer = DviLinkWriter::create(dvi_link_name("row"), 4, 2);
  EXPECT_EQ(error_of([&] { writer.back_row(2); }),
            "DVI link " + writer.name() + ": row 2 is outside the frame (height 2)");
}

TEST(DviLink, ChildProcessWritesFramesTheParentReadsByteExact) {
  const std::string name = dvi_link_name("child");
  constexpr int kFrames = 20;
  int to_parent[2], to_child[2];
  ASSERT_EQ(::pipe(to_parent), 0);
  ASSERT_EQ(::pipe(to_child), 0);
  const pid_t child = fork_child([&] {
    DviLinkWriter writer = DviLinkWriter::create(name, 61, 17);
    send_byte(to_parent[1]);  // created
    for (int k = 1; k <= kFrames; ++k) {
      draw_pattern(writer, k);
      if (writer.publish() != static_cast<std::uint64_t>(k)) return 1;
      send_byte(to_parent[1]);
      if (!receive_byte(to_child[0])) return 2;  // parent checked frame k
    }
    return 0;
  });
  ASSERT_GT(child, 0);
  ASSERT_TRUE(receive_byte(to_parent[0]));
  DviLinkReader reader = DviLinkReader::open(name);
  EXPECT_EQ(reader.width(), 61);
  EXPECT_EQ(reader.height(), 17);
  EXPECT_TRUE(reader.writer_alive());
  for (int k = 1; k <= kFrames; ++k) {
    ASSERT_TRUE(receive_byte(to_parent[0]));
    std::optional<FrameView> v = reader.latest();
    ASSERT_TRUE(v.has_value());
    EXPECT_EQ(v->sequence, static_cast<std::uint64_t>(k));
    EXPECT_EQ(mismatches(*v, k), 0) << "frame " << k;
    send_byte(to_child[1]);
  }
  EXPECT_EQ(wait_exit(child), 0);
  // The writer's destructor unlinked the name; our mapping still shows the last frame.
  EXPECT_FALSE(segment_exists(name));
  EXPECT_FALSE(reader.writer_alive());
  EXPECT_EQ(mismatches(*reader.latest(), kFrames), 0);
  for (int fd : {to_parent[0], to_parent[1], to_child[0], to_child[1]}) ::close(fd);
}

// A writer killed without running destructors leaves its segment; whoever owns the name cleans up.
TEST(DviLink, ADeadWritersSegmentIsCleanedUpByTheOwner) {
  const std::string name = dvi_link_name("dead");
  int to_parent[2];
  ASSERT_EQ(::pipe(to_parent), 0);
  const pid_t child = fork_child([&] {
    DviLinkWriter writer = DviLinkWriter::create(name, 8, 4);
    std::fill(writer.back_frame().begin(), writer.back_frame().end(), std::uint8_t{0xAB});
    writer.publish();
    send_byte(to_parent[1]);
    ::raise(SIGKILL);
    return 0;
  });
  ASSERT_TRUE(receive_byte(to_parent[0]));
  EXPECT_EQ(wait_exit(child), 128 + SIGKILL);
  ASSERT_TRUE(segment_exists(name));
  {
    DviLinkReader reader = DviLinkReader::open(name);
    EXPECT_FALSE(reader.writer_alive());
    std::optional<FrameView> v = reader.latest();
    ASSERT_TRUE(v.has_value());
    for (int y = 0; y < 4; ++y) {
      EXPECT_THAT(v->row(y), ::testing::Each(std::uint8_t{0xAB}));
    }
  }
  EXPECT_TRUE(remove_stale(name));
  EXPECT_FALSE(segment_exists(name));
  EXPECT_FALSE(remove_stale(name));
  ::close(to_parent[0]);
  ::close(to_parent[1]);
}

TEST(DviLink, CreateReplacesADeadWritersSegmentButNotALiveOnes) {
  const std::string name = dvi_link_name("replace");
  const pid_t child = fork_child([&] {
    DviLinkWriter writer = DviLinkWriter::create(name, 8, 4);
    writer.publish();
    ::raise(SIGKILL);
    return 0;
  });
  EXPECT_EQ(wait_exit(child), 128 + SIGKILL);
  ASSERT_TRUE(segment_exists(name));
  DviLinkWriter writer = DviLinkWriter::create(name, 3, 2);
  DviLinkReader reader = DviLinkReader::open(name);
  EXPECT_EQ(reader.width(), 3);
  EXPECT_FALSE(reader.latest().has_value());  // a fresh link, not the dead one's frame
  EXPECT_EQ(error_of([&] { DviLinkWriter::create(name, 3, 2); }),
            "DVI link " + name + ": already exists and is in use by process " +
                std::to_string(::getpid()));
}

TEST(DviLink, OneReaderAtATime) {
  DviLinkWriter writer = DviLinkWriter::create(dvi_link_name("readers"), 4, 4);
  draw_pattern(writer, 5);
  writer.publish();
  std::optional<DviLinkReader> first(DviLinkReader::open(writer.name()));
  EXPECT_EQ(first->latest()->sequence, 1u);
  EXPECT_EQ(error_of([&] { DviLinkReader::open(writer.name()); }),
            "DVI link " + writer.name() + ": already has a reader (process " +
                std::to_string(::getpid()) + ")");
  first.reset();
  // The next reader takes over where the first left off.
  DviLinkReader second = DviLinkReader::open(writer.name());
  EXPECT_EQ(mismatches(*second.latest(), 5), 0);
  draw_pattern(writer, 6);
  writer.publish();
  EXPECT_EQ(mismatches(*second.latest(), 6), 0);
}

TEST(DviLink, SegmentsThatAreNotDviLinksAreRefused) {
  const std::string name = dvi_link_name("junk");
  const int fd = ::shm_open(name.c_str(), O_RDWR | O_CREAT | O_EXCL, 0600);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, 100), 0);
  EXPECT_EQ(error_of([&] { DviLinkReader::open(name); }),
            "DVI link " + name + ": segment is 100 bytes, too small for a DVI link header");
  ASSERT_EQ(::ftruncate(fd, 8192), 0);
  EXPECT_EQ(error_of([&] { DviLinkReader::open(name); }),
            "DVI link " + name + ": not a DVI link (magic 0x00000000)");
  // A segment without a valid header is not taken over by create(): it may be mid-creation.
  EXPECT_EQ(error_of([&] { DviLinkWriter::create(name, 4, 4); }),
            "DVI link " + name +
                ": already exists and is not a complete DVI link (if it was left behind, remove "
                "/dev/shm" +
                name + ")");
  ::close(fd);
  EXPECT_TRUE(remove_stale(name));
}

TEST(DviLink, ASegmentWhoseSizeDisagreesWithItsHeaderIsRefused) {
  DviLinkWriter writer = DviLinkWriter::create(dvi_link_name("size"), 4, 2);
  const int fd = ::shm_open(writer.name().c_str(), O_RDWR, 0);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, 5000), 0);  // 4096 header + 3 slots of 64 bytes = 4288 expected
  ::close(fd);
  EXPECT_EQ(
      error_of([&] { DviLinkReader::open(writer.name()); }),
      "DVI link " + writer.name() + ": header declares 4288 bytes but the segment is 5000 bytes");
}

// Another process's view of a link's header: the whole segment mapped again, fields written at
// the offsets dvi_link.cpp pins for version 1.
class HeaderCorruptor {
 public:
  explicit HeaderCorruptor(const std::string& name) {
    const int fd = ::shm_open(name.c_str(), O_RDWR, 0);
    EXPECT_GE(fd, 0);
    base_ = ::mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    ::close(fd);
    EXPECT_NE(base_, MAP_FAILED);
  }
  ~HeaderCorruptor() { ::munmap(base_, 4096); }
  template <typename T>
  void put(std::size_t offset, T value) {
    std::memcpy(static_cast<char*>(base_) + offset, &value, sizeof value);
  }
  static constexpr std::size_t kStride = 24, kSlotPitch = 48, kTotalBytes = 56, kMiddle = 72,
                               kReaderSlot = 76;

 private:
  void* base_ = nullptr;
};

TEST(DviLink, HeaderWrittenOverAfterOpeningMovesNoFrame) {
  // Reader and writer read stride and slot pitch from the shared header on every frame before:
  // a pitch written over moved the reader's frame 12 MB past its mapping.
  DviLinkWriter writer = DviLinkWriter::create(dvi_link_name("moved"), 4, 2);
  DviLinkReader reader = DviLinkReader::open(writer.name());
  HeaderCorruptor other(writer.name());
  other.put<std::uint64_t>(HeaderCorruptor::kSlotPitch, 12u << 20);
  other.put<std::uint64_t>(HeaderCorruptor::kStride, 999);
  ASSERT_EQ(writer.back_frame().size(), 4u * 2 * 3);
  draw_pattern(writer, 3);
  writer.publish();
  const std::optional<FrameView> frame = reader.latest();
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->stride, 12u);
  EXPECT_EQ(mismatches(*frame, 3), 0);
}

TEST(DviLink, SlotIndexThatDoesNotExistIsACorruptHeader) {
  // Only slots 0..2 exist; the index mask let 3 through, one slot past the segment's end.
  DviLinkWriter writer = DviLinkWriter::create(dvi_link_name("slot"), 4, 2);
  const std::string prefix = "DVI link " + writer.name() + ": corrupt header: ";
  {
    HeaderCorruptor other(writer.name());
    other.put<std::uint32_t>(HeaderCorruptor::kReaderSlot, 3);
  }
  EXPECT_EQ(error_of([&] { DviLinkReader::open(writer.name()); }),
            prefix + "the reader's frame names slot 3 of 3");
  HeaderCorruptor other(writer.name());
  other.put<std::uint32_t>(HeaderCorruptor::kReaderSlot, 2);
  DviLinkReader reader = DviLinkReader::open(writer.name());
  other.put<std::uint32_t>(HeaderCorruptor::kMiddle, 3 | 4);  // slot 3, fresh
  EXPECT_EQ(error_of([&] { reader.latest(); }), prefix + "the latest frame names slot 3 of 3");
  other.put<std::uint32_t>(HeaderCorruptor::kMiddle, 3);
  EXPECT_EQ(error_of([&] { writer.publish(); }), prefix + "the latest frame names slot 3 of 3");
}

TEST(DviLink, SlotPitchWhoseTotalWrapsAroundIsRefused) {
  // total = 4096 + 3 * pitch holds modulo 2^64 for a huge pitch when the slots' bytes are not a
  // multiple of 3: 4289 bytes, pitch 193 / 3 mod 2^64 (0xAAAAAAAAAAAAAAAB is 1/3 mod 2^64).
  DviLinkWriter writer = DviLinkWriter::create(dvi_link_name("wrap"), 4, 2);
  const int fd = ::shm_open(writer.name().c_str(), O_RDWR, 0);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, 4289), 0);
  ::close(fd);
  const std::uint64_t pitch = std::uint64_t{193} * 0xAAAAAAAAAAAAAAABull;
  ASSERT_EQ(4096 + 3 * pitch, 4289u);
  HeaderCorruptor other(writer.name());
  other.put<std::uint64_t>(HeaderCorruptor::kSlotPitch, pitch);
  other.put<std::uint64_t>(HeaderCorruptor::kTotalBytes, 4289);
  EXPECT_EQ(error_of([&] { DviLinkReader::open(writer.name()); }),
            "DVI link " + writer.name() + ": corrupt header");
}

// A child writes as fast as it can while the parent reads: every frame the parent sees is whole.
// The child runs at least 200 ms and until the parent has checked enough frames; at most 3 s.
TEST(DviLink, CrossProcessReaderNeverSeesATornFrame) {
  const std::string name = dvi_link_name("race");
  constexpr std::uint64_t kEnough = 50;
  int to_parent[2], to_child[2];
  ASSERT_EQ(::pipe(to_parent), 0);
  ASSERT_EQ(::pipe2(to_child, O_NONBLOCK), 0);
  const pid_t child = fork_child([&] {
    DviLinkWriter writer = DviLinkWriter::create(name, 128, 64);
    send_byte(to_parent[1]);
    const auto end = std::chrono::steady_clock::now() + 3s;
    char stop = 0;
    for (std::uint64_t n = 1; std::chrono::steady_clock::now() < end; ++n) {
      std::span<std::uint8_t> f = writer.back_frame();
      std::fill(f.begin(), f.end(), static_cast<std::uint8_t>(n));
      if (writer.publish() != n) return 1;
      if (stop == 0 && ::read(to_child[0], &stop, 1) != 1) stop = 0;
      if (stop != 0 && std::chrono::steady_clock::now() > end - 2800ms) break;  // ran 200 ms
    }
    return 0;
  });
  ASSERT_TRUE(receive_byte(to_parent[0]));
  DviLinkReader reader = DviLinkReader::open(name);
  std::uint64_t last = 0, frames = 0, torn = 0;
  int status = 0;
  // Until the child has exited (an exited but unreaped child still counts as alive for kill()).
  while (::waitpid(child, &status, WNOHANG) == 0) {
    std::optional<FrameView> v = reader.latest();
    if (!v || v->sequence == last) continue;
    EXPECT_GT(v->sequence, last);
    last = v->sequence;
    if (++frames == kEnough) send_byte(to_child[1]);
    const std::uint8_t want = static_cast<std::uint8_t>(v->sequence);
    for (int y = 0; y < v->height; ++y) {
      std::span<const std::uint8_t> row = v->row(y);
      torn += std::count_if(row.begin(), row.end(), [&](std::uint8_t b) { return b != want; }) > 0;
    }
  }
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(torn, 0u);
  EXPECT_GE(frames, kEnough);
  for (int fd : {to_parent[0], to_parent[1], to_child[0], to_child[1]}) ::close(fd);
}

}  // namespace
}  // namespace l2
