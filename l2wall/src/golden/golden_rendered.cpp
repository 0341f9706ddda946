#include "golden_rendered.hpp"

#include <fmt/format.h>

#include <cstring>
#include <fstream>

#include "base/child_process.hpp"
#include "base/stop_signals.hpp"
#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "l2wall/colour_stage.hpp"

namespace l2 {

namespace {

std::vector<std::string> lines_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

// How long a command stopped by a signal has to end its own way before it is killed.
constexpr std::chrono::seconds kStopGrace{30};

// A command as a child process with its output in `log`.
struct LoggedCommand {
  std::string what;  // "l2wall run"
  std::filesystem::path log;
  ChildProcess child;

  LoggedCommand(const std::vector<std::string>& args, std::filesystem::path log_file)
      : what(std::filesystem::path(args.at(0)).filename().string() + " " + args.at(1)),
        log(std::move(log_file)),
        child(shell_redirect(args, log)) {}

  // Throws when it failed or overstays, with the last line it wrote (usually the reason), or
  // when a stop signal came (GoldenStopped), once the child has ended: an `l2wall run` ends its
  // run on SIGTERM as on Ctrl-C, its pipeservers ended and their links removed, which takes
  // it a few seconds; killed at once, or left running as this process ended, it could not.
  void finish(std::chrono::seconds timeout) {
    using namespace std::chrono_literals;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    std::optional<ExitStatus> status;
    while (!status && std::chrono::steady_clock::now() < deadline) {
      if (const int signal = stop_signal_received()) {
        child.terminate(kStopGrace);
        throw GoldenStopped(signal);
      }
      status = child.wait_for(50ms);
    }
    if (!status) {
      child.terminate();
      throw std::runtime_error(fmt::format("{} did not finish within {} s (output: {})", what,
                                           timeout.count(), log.string()));
    }
    if (!status->ok()) {
      const auto lines = lines_of(log);
      throw std::runtime_error(fmt::format("{} {}: {} (output: {})", what, status->describe(),
                                           lines.empty() ? "no output" : lines.back(),
                                           log.string()));
    }
  }

  static std::vector<std::string> shell_redirect(const std::vector<std::string>& args,
                                                 const std::filesystem::path& log) {
    std::vector<std::string> argv{"/bin/sh", "-c", "log=$1; shift; exec \"$@\" >\"$log\" 2>&1",
                                  "sh", log.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
  }
};

}  // namespace

GoldenStopped::GoldenStopped(int signal)
    : std::runtime_error(fmt::format("stopped by signal {} ({})", signal, strsignal(signal))) {}

void throw_if_stopped() {
  if (const int signal = stop_signal_received()) throw GoldenStopped(signal);
}

namespace {

// The pixel a live pipeserver writes for frame `frame`: 24 bits of the frame number, R the low
// byte (l2wall/include/l2wall/frame_stamp.hpp).
Rgb stamp_colour(int frame) {
  return {static_cast<std::uint8_t>(frame & 0xFF), static_cast<std::uint8_t>(frame >> 8 & 0xFF),
          static_cast<std::uint8_t>(frame >> 16 & 0xFF)};
}

}  // namespace

int set_aside_moved_stamps(int frame, int pipeservers, const std::vector<RgbImage>& expected,
                           std::vector<RgbImage>& actual) {
  const Rgb stamp = stamp_colour(frame);
  struct Spot {
    std::size_t display;
    int x, y;
  };
  std::vector<Spot> spots;
  for (std::size_t d = 0; d < expected.size() && d < actual.size(); ++d) {
    const RgbImage &e = expected[d], &a = actual[d];
    if (e.width() != a.width() || e.height() != a.height()) continue;
    for (int y = 0; y < e.height(); ++y) {
      for (int x = 0; x < e.width(); ++x) {
        const Rgb pe = e.at(x, y), pa = a.at(x, y);
        if (pe == pa || (pe != stamp && pa != stamp)) continue;
        spots.push_back({d, x, y});
        if (spots.size() > static_cast<std::size_t>(2 * pipeservers)) return 0;
      }
    }
  }
  for (const Spot& s : spots) actual[s.display].set(s.x, s.y, expected[s.display].at(s.x, s.y));
  return static_cast<int>(spots.size());
}

void stamp_references(const TileLayout& layout, int frame, std::vector<RgbImage>& references) {
  const Rgb stamp = stamp_colour(frame);
  for (const PipeserverPlan& plan : layout.pipeservers) {
    // A stamp strip keeps the stamp off the displays: only a framebuffer without one marks them.
    if (plan.tiles.empty() || plan.has_stamp_strip()) continue;
    const DisplayTile& t = plan.tiles.front().tile;
    references.at(t.display).set(t.on_display.x, t.on_display.y, stamp);
  }
}

EntryDisplays produce_rendered(const TileLayout& layout, const std::filesystem::path& wall_file,
                               const GoldenEntry& entry, const RenderedRun& run) {
  std::filesystem::remove_all(run.work);
  make_folders(run.work);
  std::vector<std::string> live{run.l2wall,
                                "run",
                                "--wall",
                                wall_file.string(),
                                "--scene",
                                entry.scene,
                                "--frames",
                                std::to_string(entry.frame + 1),
                                "--keep",
                                std::to_string(entry.frame),
                                "--refresh",
                                "0",
                                "--no-progress",
                                "--out",
                                (run.work / "live").string()};
  if (entry.vizserver) live.insert(live.end(), {"--path", "both", "--compare"});
  const auto reference = run.work / "reference";
  std::vector<std::string> rendering_args{run.pipeserver_program,
                                          "--wall",
                                          wall_file.string(),
                                          "--scene",
                                          entry.scene,
                                          "--frame",
                                          std::to_string(entry.frame),
                                          "--reference",
                                          reference.string()};
  if (!run.session.empty()) {
    for (auto* args : {&live, &rendering_args})
      args->insert(args->end(), {"--session", run.session.string()});
  }
  // Both at once: the live run spends most of its time starting its pipeservers.
  LoggedCommand rendering(rendering_args, run.work / "reference.log");
  LoggedCommand running(live, run.work / "live.log");
  running.finish(run.timeout);
  rendering.finish(run.timeout);

  EntryDisplays out;
  const auto saved = run.work / "live" / fmt::format("frame-{}", entry.frame);
  for (const Display& d : layout.wall.displays) {
    const std::string name = fmt::format("display-{}", d.id);
    out.ids.push_back(d.id);
    out.emulator.push_back(read_png(saved / (name + ".png")));
    if (entry.vizserver) out.vizserver.push_back(read_png(saved / (name + "-vizserver.png")));
    out.reference.push_back(read_png(reference / (name + ".png")));
  }
  stamp_references(layout, entry.frame, out.reference);
  // The live run's saved displays are blended and colour matched (l2wall/colour_stage.hpp),
  // stamp and all: the reference goes through the same stage, after its stamps.
  const ColourStage stage(layout.wall);
  if (stage.applies()) {
    const DisplayPictures shown = stage.apply(
        [&](int d) -> const RgbImage& { return out.reference[static_cast<std::size_t>(d)]; });
    for (std::size_t i = 0; i < out.reference.size(); ++i) out.reference[i] = shown(out.ids[i]);
  }
  out.reference_name = "reference render";
  return out;
}

GlInfo pipeserver_gl_info(const std::string& pipeserver, const std::filesystem::path& work) {
  make_folders(work);
  const auto log = work / "gl-info.txt";
  LoggedCommand({pipeserver, "--gl-info"}, log).finish(std::chrono::seconds(60));
  GlInfo gl;
  for (const std::string& line : lines_of(log)) {
    if (line.rfind("gl_version: ", 0) == 0) gl.version = line.substr(12);
    if (line.rfind("gl_renderer: ", 0) == 0) gl.renderer = line.substr(13);
  }
  if (gl.version.empty()) {
    throw std::runtime_error(
        fmt::format("{} --gl-info named no GL version (output: {})", pipeserver, log.string()));
  }
  return gl;
}

}  // namespace l2
