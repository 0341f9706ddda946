// Output on a file system that is full or read-only: a tmpfs of a few pages, mounted in a mount
// namespace of the test's own. OpenImageIO's PNG writer lost ENOSPC: a full file system left a
// picture cut short (or empty) under its name, and the write "succeeded".
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/mount.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>

#include "image/folders.hpp"
#include "image/png_io.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

// Empty, named by the test alone: a death test's statement runs in a fresh run of this binary,
// which makes the same folder (the parent removes it).
fs::path scratch_dir() {
  const fs::path dir =
      fs::temp_directory_path() /
      ("l2_full_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Whether this process may make a mount namespace and mount in it (root, or a container that
// allows it); the tests are skipped otherwise.
bool can_mount(const fs::path& dir) {
  const std::string probe =
      "unshare -m sh -c 'mount -t tmpfs tmpfs \"$0\"' '" + dir.string() + "' >/dev/null 2>&1";
  return std::system(probe.c_str()) == 0;
}

// In the death test's own process (a fresh run of this binary): `dir` becomes a tmpfs of
// `options` in a mount namespace only that process sees. Exits 2 when it cannot.
void mount_tmpfs(const fs::path& dir, const char* options) {
  if (::unshare(CLONE_NEWNS) != 0 || ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) ||
      ::mount("tmpfs", dir.c_str(), "tmpfs", 0, options) != 0) {
    std::perror("mount");
    std::exit(2);
  }
}

std::string failure_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

std::string file_contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Noise: it does not compress, so its PNG is larger than the file system.
RgbImage noise_picture(int side) {
  RgbImage image(side, side);
  unsigned state = 12345;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      state = state * 1103515245u + 12345u;
      image.set(x, y,
                {static_cast<std::uint8_t>(state >> 24), static_cast<std::uint8_t>(state >> 16),
                 static_cast<std::uint8_t>(state >> 8)});
    }
  }
  return image;
}

// Exits 1 with what differs from what was expected (death tests see only the exit and stderr).
void expect_or_exit(bool ok, const std::string& what) {
  if (ok) return;
  std::fprintf(stderr, "%s\n", what.c_str());
  std::exit(1);
}

TEST(FullFolderDeathTest, APictureThatDoesNotFitLeavesNothingUnderItsName) {
  const fs::path dir = scratch_dir();
  if (!can_mount(dir)) GTEST_SKIP() << "no mount namespace here (unshare -m and mount need root)";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        mount_tmpfs(dir, "size=64k");
        const RgbImage small(4, 4, {1, 2, 3});
        write_png(dir / "display-0.png", small);
        const std::string before = file_contents(dir / "display-0.png");
        const std::string new_one =
            failure_of([&] { write_png(dir / "display-1.png", noise_picture(200)); });
        expect_or_exit(
            new_one == (dir / "display-1.png").string() + ": cannot write: No space left on device",
            new_one);
        expect_or_exit(!fs::exists(dir / "display-1.png"), "display-1.png left");
        // Written over: the earlier picture stays as it was, whole.
        const std::string over =
            failure_of([&] { write_png(dir / "display-0.png", noise_picture(200)); });
        expect_or_exit(over.ends_with(": cannot write: No space left on device"), over);
        expect_or_exit(file_contents(dir / "display-0.png") == before, "display-0.png changed");
        expect_or_exit(read_png(dir / "display-0.png") == small, "display-0.png unreadable");
        // Nothing else: no temporary file left beside them.
        long entries = std::distance(fs::directory_iterator(dir), fs::directory_iterator());
        expect_or_exit(entries == 1, std::to_string(entries) + " files in the folder");
        // Text files go the same way.
        const std::string text =
            failure_of([&] { write_whole_file(dir / "summary.txt", std::string(100000, 'x')); });
        expect_or_exit(
            text == (dir / "summary.txt").string() + ": cannot write: No space left on device",
            text);
        expect_or_exit(!fs::exists(dir / "summary.txt"), "summary.txt left");
        std::exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  fs::remove_all(dir);
}

TEST(FullFolderDeathTest, AReadOnlyFolderIsNamedWithTheSystemsReason) {
  const fs::path dir = scratch_dir();
  if (!can_mount(dir)) GTEST_SKIP() << "no mount namespace here (unshare -m and mount need root)";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        mount_tmpfs(dir, "ro");
        const std::string folder = failure_of([&] { check_folder_writable(dir, "--out"); });
        expect_or_exit(folder == "--out " + dir.string() +
                                     ": cannot write into the folder: Read-only file system",
                       folder);
        const std::string file =
            failure_of([&] { write_png(dir / "display-0.png", noise_picture(2)); });
        expect_or_exit(
            file == (dir / "display-0.png").string() + ": cannot write: Read-only file system",
            file);
        std::exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  fs::remove_all(dir);
}

TEST(FullFolder, AWritableFolderPassesAndKeepsNoTrace) {
  const fs::path dir = scratch_dir();
  check_folder_writable(dir, "--out");
  EXPECT_TRUE(fs::is_empty(dir));
  write_whole_file(dir / "a.txt", "first");
  write_whole_file(dir / "a.txt", "second, longer");
  EXPECT_EQ(file_contents(dir / "a.txt"), "second, longer");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::create_directories(dir / "b.txt");
  EXPECT_EQ(failure_of([&] { write_whole_file(dir / "b.txt", "x"); }),
            (dir / "b.txt").string() + ": cannot write: a folder, not a file");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
