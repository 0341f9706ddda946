// Pictures and movies on the wall through `l2wall run`: every pixel of the routed displays is
// the source pixel the view samples (picture_view.hpp), worked out here from the source itself;
// a pipeserver showing a picture far larger than its memory use holds only part of it; a
// missing, damaged or empty file is refused in one line.
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cmath>
#include <functional>

#include "pipeserver/picture_view.hpp"
#include "wall_run.hpp"
#include "wide_wall.hpp"

extern char** environ;

namespace l2 {
namespace {

using namespace testing_support;
using Source = std::function<Rgb(long x, long y)>;

// The test picture's pixels, a formula, so the expected displays need no copy of the picture:
// R and G give the position within 256 pixels, B which 64 x 64 tile.
Rgb pattern(long x, long y) {
  return {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y),
          static_cast<std::uint8_t>((x >> 6) + 3 * (y >> 6))};
}

constexpr int kPictureSide = 16384;
constexpr int kTile = 64;

template <typename T>
void put(std::string& out, T value) {  // little-endian, as the header says
  for (std::size_t i = 0; i < sizeof(T); ++i) out += static_cast<char>(value >> (8 * i));
}

// An uncompressed tiled TIFF of the pattern, written here byte by byte: OpenImageIO took many
// times as long to write it, and a tile of the pattern is one of 4096 (its column and row
// within 256 pixels and its B), each made once.
void write_pattern_tiff(const fs::path& path, int side) {
  const std::uint32_t across = static_cast<std::uint32_t>(side / kTile);
  const std::uint32_t tiles = across * across, tile_bytes = kTile * kTile * 3;
  constexpr std::uint32_t kEntries = 11, kBits = 8 + 2 + kEntries * 12 + 4;
  const std::uint32_t offsets = kBits + 6, counts = offsets + 4 * tiles, data = counts + 4 * tiles;
  std::string head = "II";
  put<std::uint16_t>(head, 42);
  put<std::uint32_t>(head, 8);
  put<std::uint16_t>(head, kEntries);
  const auto entry = [&head](std::uint16_t tag, std::uint16_t type, std::uint32_t count,
                             std::uint32_t value) {
    put(head, tag), put(head, type), put(head, count), put(head, value);
  };
  constexpr std::uint16_t kShort = 3, kLong = 4;
  entry(256, kLong, 1, static_cast<std::uint32_t>(side));  // width
  entry(257, kLong, 1, static_cast<std::uint32_t>(side));  // height
  entry(258, kShort, 3, kBits);                            // 8 bits per sample, at kBits
  entry(259, kShort, 1, 1);                                // no compression
  entry(262, kShort, 1, 2);                                // RGB
  entry(277, kShort, 1, 3);                                // samples per pixel
  entry(284, kShort, 1, 1);                                // interleaved
  entry(322, kLong, 1, kTile);                             // tile width
  entry(323, kLong, 1, kTile);                             // tile height
  entry(324, kLong, tiles, offsets);
  entry(325, kLong, tiles, counts);
  put<std::uint32_t>(head, 0);  // no next directory
  for (int i = 0; i < 3; ++i) put<std::uint16_t>(head, 8);
  for (std::uint32_t t = 0; t < tiles; ++t) put(head, data + t * tile_bytes);
  for (std::uint32_t t = 0; t < tiles; ++t) put(head, tile_bytes);
  std::ofstream out(path, std::ios::binary);
  out.write(head.data(), static_cast<std::streamsize>(head.size()));
  std::vector<std::string> made(16 * 256);
  for (int y0 = 0; y0 < side; y0 += kTile) {
    for (int x0 = 0; x0 < side; x0 += kTile) {
      const Rgb corner = pattern(x0, y0);
      std::string& tile = made[static_cast<std::size_t>(
          ((x0 & 255) / kTile * 4 + (y0 & 255) / kTile) * 256 + corner.b)];
      if (tile.empty()) {
        for (int y = y0; y < y0 + kTile; ++y) {
          for (int x = x0; x < x0 + kTile; ++x) {
            const Rgb c = pattern(x, y);
            tile += static_cast<char>(c.r), tile += static_cast<char>(c.g),
                tile += static_cast<char>(c.b);
          }
        }
      }
      out.write(tile.data(), static_cast<std::streamsize>(tile.size()));
    }
  }
  ASSERT_TRUE(out.good()) << path;
}

// Source pixel index of canvas pixel `x` on a canvas `size` wide, by picture_view.hpp's rule.
long sampled(double centre, double scale, int size, int x) {
  return static_cast<long>(std::floor(centre + (x + 0.5 - size / 2.0) * scale));
}

// Pixels of display `d` of frame `frame` (as kept by the run) that differ from the source seen
// through `view`, each pipeserver's frame stamp aside (it holds the frame number).
long wrong_pixels(const WallRun& run, const fs::path& wall_file, int frame, const SourceView& view,
                  int source_w, int source_h, const Source& source) {
  const Wall wall = wall_file.empty() ? default_wall() : load_wall(wall_file);
  return wrong_canvas_pixels(run, wall, frame, [&](int u, int v) {
    const long sx = sampled(view.centre_x, view.scale_x, wall.canvas_width, u);
    const long sy = sampled(view.centre_y, view.scale_y, wall.canvas_height, v);
    const bool inside = sx >= 0 && sx < source_w && sy >= 0 && sy < source_h;
    return inside ? source(sx, sy) : Rgb{};
  });
}

Canvas canvas_of_file(const fs::path& wall_file) {
  const Wall wall = wall_file.empty() ? default_wall() : load_wall(wall_file);
  return {wall.canvas_width, wall.canvas_height};
}

class Media : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / fmt::format("l2wall-media-{}", getpid());
    fs::create_directories(dir_);
    write_pattern_tiff(picture(), kPictureSide);
    wide_wall_ = write_wide_wall(dir_);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static fs::path picture() { return dir_ / "pattern-16k.tif"; }

  static fs::path dir_;
  static fs::path wide_wall_;
};
fs::path Media::dir_;
fs::path Media::wide_wall_;

TEST_F(Media, PictureFramesAreThePicturesPixelsOnTheDefaultWall) {
  WallRun run("picture", {"--scene", "picture", "--content", picture().string(), "--frames", "2",
                          "--refresh", "0", "--keep", "every"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  for (int k = 0; k < 2; ++k) {
    const SourceView view = picture_view(k, kPictureSide, kPictureSide, canvas_of_file({}));
    EXPECT_EQ(wrong_pixels(run, {}, k, view, kPictureSide, kPictureSide, pattern), 0)
        << "frame " << k;
  }
  expect_clean(run);
}

// A PNG (stored as scanlines: no row can be read without those before it) larger than the
// picture cache's default: decoded once, at frame 0, not again at every frame that samples it
// across. Before, every frame decoded it anew and took about as long as frame 0 (a large
// picture ended runs as "did not deliver frame 1"). The pixels are the picture's on every frame.
TEST_F(Media, ALargePngIsDecodedOnceNotEveryFrame) {
  constexpr int kWidth = 12288, kHeight = 4096;  // 144 MiB decoded, beyond the 64 MiB cache
  const fs::path png = dir_ / "large.png";
  {
    RgbImage picture(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) picture.set(x, y, pattern(x, y));
    write_png(png, picture);
  }
  WallRun run("large-png", {"--scene", "picture", "--content", png.string(), "--frames", "3",
                            "--refresh", "0", "--keep", "every"});
  const ExitStatus status = run.wait(300s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  for (int k = 0; k < 3; ++k) {
    const SourceView view = picture_view(k, kWidth, kHeight, canvas_of_file({}));
    EXPECT_EQ(wrong_pixels(run, {}, k, view, kWidth, kHeight, pattern), 0) << "frame " << k;
  }
  // Render times from pipeserver 0's report: frames 1 and 2 read from the cache, frame 0
  // decoded the picture. A third is a wide margin either way (before: about two thirds).
  std::ifstream log(run.out() / "pipeserver-0.log");
  std::vector<double> render_ms;
  for (std::string line; std::getline(log, line);) {
    double ms = 0;
    if (std::sscanf(line.c_str(), "frame %*d render_ms %lf", &ms) == 1) render_ms.push_back(ms);
  }
  ASSERT_EQ(render_ms.size(), 3u);
  EXPECT_LT(render_ms[1], render_ms[0] / 3) << "frame 0 " << render_ms[0] << " ms";
  EXPECT_LT(render_ms[2], render_ms[0] / 3) << "frame 0 " << render_ms[0] << " ms";
  expect_clean(run);
}

TEST_F(Media, PictureFillsTheWideWall) {
  WallRun run("picture-wide", {"--wall", wide_wall_.string(), "--scene", "picture", "--content",
                               picture().string(), "--frames", "2", "--refresh", "0"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const SourceView view = picture_view(1, kPictureSide, kPictureSide, canvas_of_file(wide_wall_));
  EXPECT_EQ(wrong_pixels(run, wide_wall_, 1, view, kPictureSide, kPictureSide, pattern), 0);
  expect_clean(run);
}

// The peak resident memory of `pipeserver --out DIR` with `args`, in KiB.
long pipeserver_peak_kib(const fs::path& out, std::vector<std::string> args) {
  args.insert(args.begin(), L2_PIPESERVER_PATH);
  args.insert(args.end(), {"--count", "2", "--out", out.string()});
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ), 0);
  int status = 0;
  rusage usage{};
  EXPECT_EQ(wait4(pid, &status, 0, &usage), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  return usage.ru_maxrss;
}

// The picture is 768 MiB of pixels; a pipeserver reads it through an image cache of bounded
// size. Its libraries (OSMesa, OpenImageIO's) are a large part of any pipeserver's memory, so
// what the picture adds is measured against the same pipeserver showing the swap scene.
TEST_F(Media, PipeserverHoldsAPartOfThePicture) {
  const fs::path out = dir_ / "scanout";
  const long picture_kib = 3L * kPictureSide * kPictureSide / 1024;
  const long swap = pipeserver_peak_kib(out, {"--scene", "swap"});
  // The cache's limit given: the default is sized for the machine, which may hold the picture.
  const long shown = pipeserver_peak_kib(
      out, {"--scene", "picture", "--content", picture().string(), "--picture-cache-mb", "64"});
  EXPECT_LT(shown, picture_kib / 2) << "peak RSS " << shown << " KiB";
  EXPECT_LT(shown - swap, picture_kib / 6) << "peak RSS " << shown << " KiB, swap scene " << swap;
}

// Runs `ffmpeg` with `args`; true when it exited 0.
bool ffmpeg(std::vector<std::string> args) {
  args.insert(args.begin(), {"/usr/bin/ffmpeg", "-loglevel", "error", "-y"});
  ChildProcess process(args);
  const auto status = process.wait_for(60s);
  return status && status->ok();
}

struct DecodedMovie {
  int width = 0, height = 0;
  std::vector<std::vector<std::uint8_t>> frames;  // RGB, rows top to bottom
  Source frame(std::size_t k) const {
    return [this, k](long x, long y) {
      const std::uint8_t* p = frames[k].data() + 3 * (y * width + x);
      return Rgb{p[0], p[1], p[2]};
    };
  }
};

// A lossless movie (FFV1, bgr0) of FFmpeg's test pattern and its frames as the ffmpeg tool
// decodes them.
DecodedMovie make_movie(const fs::path& movie, int frames) {
  DecodedMovie m{200, 150, {}};
  const std::string size = fmt::format("testsrc2=size={}x{}:rate=10", m.width, m.height);
  EXPECT_TRUE(ffmpeg({"-f", "lavfi", "-i", size, "-frames:v", std::to_string(frames), "-c:v",
                      "ffv1", "-pix_fmt", "bgr0", movie.string()}));
  const fs::path raw = movie.string() + ".rgb";
  EXPECT_TRUE(ffmpeg({"-i", movie.string(), "-f", "rawvideo", "-pix_fmt", "rgb24", raw.string()}));
  const std::string bytes = slurp(raw);
  const std::size_t frame_bytes = static_cast<std::size_t>(m.width) * m.height * 3;
  EXPECT_EQ(bytes.size(), frame_bytes * static_cast<std::size_t>(frames));
  for (std::size_t at = 0; at + frame_bytes <= bytes.size(); at += frame_bytes) {
    m.frames.emplace_back(bytes.begin() + static_cast<long>(at),
                          bytes.begin() + static_cast<long>(at + frame_bytes));
  }
  return m;
}

// Five movie frames over seven application frames: frames 5 and 6 are movie frames 0 and 1.
TEST_F(Media, MovieFrameKIsApplicationFrameK) {
  const DecodedMovie movie = make_movie(dir_ / "pattern.mkv", 5);
  ASSERT_EQ(movie.frames.size(), 5u);
  WallRun run("movie", {"--scene", "movie", "--content", (dir_ / "pattern.mkv").string(),
                        "--frames", "7", "--refresh", "0", "--keep", "every"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const SourceView view = movie_view(movie.width, movie.height, canvas_of_file({}));
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(wrong_pixels(run, {}, k, view, movie.width, movie.height, movie.frame(k % 5)), 0)
        << "frame " << k;
  }
  // Consecutive movie frames differ: a pipeserver showing the same frame twice would be seen.
  EXPECT_NE(movie.frames[0], movie.frames[1]);
  expect_clean(run);
}

// The movie's clock: a 10 frames/s movie on a wall refreshing at 20 Hz shows each movie frame
// for two application frames (frames 0-5: movie frames 0, 0, 1, 1, 2, 2), on every pipeserver
// alike; `--movie-rate 0` keeps frame for frame.
TEST_F(Media, AMoviePlaysByItsOwnClock) {
  const DecodedMovie movie = make_movie(dir_ / "clock.mkv", 5);
  ASSERT_EQ(movie.frames.size(), 5u);
  const SourceView view = movie_view(movie.width, movie.height, canvas_of_file({}));
  WallRun run("movie-clock", {"--scene", "movie", "--content", (dir_ / "clock.mkv").string(),
                              "--frames", "6", "--refresh", "20", "--keep", "every"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(wrong_pixels(run, {}, k, view, movie.width, movie.height, movie.frame(k / 2)), 0)
        << "frame " << k;
  }
  expect_clean(run);

  WallRun exact("movie-exact",
                {"--scene", "movie", "--content", (dir_ / "clock.mkv").string(), "--frames", "3",
                 "--refresh", "20", "--movie-rate", "0", "--keep", "every"});
  ASSERT_TRUE(exact.wait(120s).ok()) << exact.output();
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(wrong_pixels(exact, {}, k, view, movie.width, movie.height, movie.frame(k)), 0)
        << "frame " << k;
  }
}

TEST_F(Media, MovieOnTheWideWall) {
  const DecodedMovie movie = make_movie(dir_ / "wide.mkv", 3);
  ASSERT_EQ(movie.frames.size(), 3u);
  WallRun run("movie-wide",
              {"--wall", wide_wall_.string(), "--scene", "movie", "--content",
               (dir_ / "wide.mkv").string(), "--frames", "3", "--refresh", "0", "--keep", "every"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const SourceView view = movie_view(movie.width, movie.height, canvas_of_file(wide_wall_));
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(wrong_pixels(run, wide_wall_, k, view, movie.width, movie.height, movie.frame(k)), 0)
        << "frame " << k;
  }
  expect_clean(run);
}

// A 4:3 movie stretched over the 3x1 wall: every display pixel is a movie pixel, none black;
// the default (fit) leaves the outer parts of the wall black.
TEST_F(Media, AMovieStretchedCoversTheWideWall) {
  const DecodedMovie movie = make_movie(dir_ / "stretch.mkv", 2);
  ASSERT_EQ(movie.frames.size(), 2u);
  WallRun run("movie-stretch", {"--wall", wide_wall_.string(), "--scene", "movie", "--content",
                                (dir_ / "stretch.mkv").string(), "--frames", "2", "--refresh", "0",
                                "--fit", "stretch", "--keep", "every"});
  ASSERT_TRUE(run.wait(120s).ok()) << run.output();
  const Canvas canvas = canvas_of_file(wide_wall_);
  const SourceView view = movie_view(movie.width, movie.height, canvas, SourceFit::Stretch);
  EXPECT_NE(view.scale_x, view.scale_y);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(wrong_pixels(run, wide_wall_, k, view, movie.width, movie.height, movie.frame(k)), 0)
        << "frame " << k;
  }
  // The left edge of the canvas shows the movie's left edge, not a bar.
  const SourceView fitted = movie_view(movie.width, movie.height, canvas);
  EXPECT_LT(sampled(fitted.centre_x, fitted.scale_x, canvas.width, 0), 0);
  EXPECT_EQ(sampled(view.centre_x, view.scale_x, canvas.width, 0), 0);
}

// l2wall's output of a run refused before any pipeserver starts, and its exit code.
std::pair<int, std::string> refused(const std::string& name, std::vector<std::string> args) {
  WallRun run(name, args);
  const int code = run.wait(30s).code;
  EXPECT_TRUE(run.pipeservers().empty());
  return {code, run.output()};
}

TEST_F(Media, MissingDamagedOrEmptyContentIsOneLine) {
  const std::string usage = "Run with --help for more information.\n";
  EXPECT_EQ(refused("no-content", {"--scene", "picture"}),
            std::pair(2, "l2wall: --scene picture needs --content FILE\n" + usage));
  EXPECT_EQ(
      refused("missing", {"--scene", "movie", "--content", "/nonexistent/movie.mkv"}),
      std::pair(2, "l2wall: --content: File does not exist: /nonexistent/movie.mkv\n" + usage));
  EXPECT_EQ(
      refused("wrong-scene", {"--scene", "mesh", "--content", picture().string()}),
      std::pair(2, "l2wall: --content is an option of --scene picture, movie or vnc, not mesh\n" +
                       usage));

  const fs::path empty = dir_ / "empty.tif";
  std::ofstream{empty};
  EXPECT_EQ(refused("empty-picture", {"--scene", "picture", "--content", empty.string()}),
            std::pair(1, "l2wall: " + empty.string() +
                             ": cannot read: Could not open file: Cannot read TIFF header\n"));
  const fs::path damaged = dir_ / "damaged.tif";
  std::ofstream(damaged) << std::string("II*\0", 4) << "not a directory offset";
  EXPECT_EQ(refused("damaged-picture", {"--scene", "picture", "--content", damaged.string()}),
            std::pair(1, "l2wall: " + damaged.string() +
                             ": cannot read: a TIFF file: Could not open file: Failed to read "
                             "directory at offset 544501614\n"));

  const fs::path no_movie = dir_ / "empty.mkv";
  std::ofstream{no_movie};
  EXPECT_EQ(refused("empty-movie", {"--scene", "movie", "--content", no_movie.string()}),
            std::pair(1, "l2wall: " + no_movie.string() +
                             ": cannot read as a movie: Invalid data found when processing "
                             "input\n"));
  // The container's header and no frame: a movie that was cut short, or recorded nothing.
  const fs::path frameless = dir_ / "frameless.mkv";
  ASSERT_TRUE(ffmpeg({"-f", "lavfi", "-i", "testsrc2=size=64x48:rate=10", "-frames:v", "0", "-c:v",
                      "ffv1", "-pix_fmt", "bgr0", frameless.string()}));
  EXPECT_EQ(refused("frameless-movie", {"--scene", "movie", "--content", frameless.string()}),
            std::pair(1, "l2wall: " + frameless.string() + ": holds no video frames\n"));
  const fs::path sound = dir_ / "sound.wav";
  ASSERT_TRUE(ffmpeg({"-f", "lavfi", "-i", "sine", "-t", "0.1", sound.string()}));
  EXPECT_EQ(refused("sound-movie", {"--scene", "movie", "--content", sound.string()}),
            std::pair(1, "l2wall: " + sound.string() + ": holds no video stream\n"));
}

}  // namespace
}  // namespace l2
