#include "view_command.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <thread>

#include "balance/control_messages.hpp"
#include "command_line/options.hpp"
#include "control_page/access_token.hpp"
#include "control_page/control_server.hpp"
#include "image/png_io.hpp"
#include "image/turn.hpp"
#include "l2wall/stop_signal.hpp"
#include "live_page.hpp"
#include "pipeserver_log.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

struct ViewOptions {
  std::string out;
  std::string wall;  // empty: the built-in default wall, as for `l2wall run`
  std::string http = "127.0.0.1:0";
  int frame = -1;  // -1: the last frame kept
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The frames OUT/frame-K/ holds, ascending.
std::vector<int> kept_frames(const fs::path& out) {
  std::vector<int> frames;
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    int k = 0;
    if (name.rfind("frame-", 0) != 0 || !e.is_directory()) continue;
    const auto [end, ec] = std::from_chars(name.data() + 6, name.data() + name.size(), k);
    if (ec == std::errc{} && end == name.data() + name.size()) frames.push_back(k);
  }
  std::sort(frames.begin(), frames.end());
  return frames;
}

// Every PNG in OUT and the folders in it, named by its path with '/' as '~'.
std::vector<NamedPicture> pictures_in(const fs::path& out) {
  std::vector<NamedPicture> pictures;
  const std::regex safe("[A-Za-z0-9._~-]{1,200}");
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    if (!e.is_regular_file() || e.path().extension() != ".png") continue;
    std::string name = fs::relative(e.path(), out).generic_string();
    std::replace(name.begin(), name.end(), '/', '~');
    if (std::regex_match(name, safe)) pictures.push_back({name, e.path()});
  }
  std::sort(pictures.begin(), pictures.end(),
            [](const NamedPicture& a, const NamedPicture& b) { return a.name < b.name; });
  return pictures;
}

std::vector<PagePipeserver> pipeservers_in(const fs::path& out) {
  std::vector<PagePipeserver> all;
  for (int i = 0; fs::exists(out / fmt::format("pipeserver-{}.log", i)); ++i) {
    PagePipeserver p;
    p.index = i;
    PipeserverLogTail log((out / fmt::format("pipeserver-{}.log", i)).string());
    log.read_new([&](const PipeserverLogLine& line) { take_log_line(p, line); });
    all.push_back(std::move(p));
  }
  return all;
}

// Frame `frame`'s tiles: from layouts.txt (a balanced run), or the wall's plan.
std::vector<PageTile> tiles_of(const fs::path& out, const Wall& wall, int frame) {
  std::ifstream layouts(out / "layouts.txt");
  std::string line, last;
  for (int k = 0; k <= frame && std::getline(layouts, line); ++k) last = line;
  if (!last.empty()) {
    try {
      return page_tiles(decode_layout(last));
    } catch (const std::exception&) {
      // a damaged layouts.txt: the wall's own plan below
    }
  }
  return page_tiles(plan_layout(wall));
}

// Frame `frame`'s latency in refreshes from OUT/report.csv (column latency_frames), as the live
// page showed it; -1 where the run did not measure it (the vizserver path: "n/a").
long latency_of_frame(const fs::path& out, int frame) {
  std::ifstream csv(out / "report.csv");
  std::string line;
  const std::string row = std::to_string(frame) + ",";
  while (std::getline(csv, line)) {
    if (line.rfind(row, 0) != 0) continue;
    std::stringstream fields(line);
    std::string field;
    for (int column = 0; column <= 3 && std::getline(fields, field, ','); ++column) {
    }
    long latency = -1;
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), latency);
    return ec == std::errc{} && end == field.data() + field.size() ? latency : -1;
  }
  return -1;
}

RunState finished_state(const ViewOptions& o, const Wall& wall, int frame) {
  RunState s = wall_state(wall);
  s.live = false;
  s.summary = read_text(fs::path(o.out) / "summary.txt");
  s.ended = s.summary.substr(0, s.summary.find('\n'));
  std::smatch m;
  if (std::regex_search(s.ended, m, std::regex("([0-9.]+) fps"))) s.fps = std::stod(m[1]);
  s.frame = frame;
  if (frame >= 0) s.latency_frames = latency_of_frame(o.out, frame);
  s.tiles = tiles_of(o.out, wall, frame);
  s.pipeservers = pipeservers_in(o.out);
  for (const NamedPicture& p : pictures_in(o.out)) s.pictures.push_back(p.name);
  s.pictures_version = 1;
  return s;
}

// The displays of frame-K as saved; a display not saved shows nothing.
std::shared_ptr<std::vector<RgbImage>> displays_of(const fs::path& dir, const Wall& wall) {
  auto shown = std::make_shared<std::vector<RgbImage>>();
  for (const Display& d : wall.displays) {
    const fs::path file = dir / fmt::format("display-{}.png", d.id);
    shown->push_back(fs::exists(file) ? to_canvas(read_png(file), d.orientation) : RgbImage());
  }
  return shown;
}

int view(const ViewOptions& o) {
  if (!fs::exists(fs::path(o.out) / "summary.txt"))
    throw std::runtime_error(
        fmt::format("{}: no summary.txt: not the --out folder of a run", o.out));
  const Wall wall = o.wall.empty() ? default_wall() : load_wall(o.wall);
  const std::vector<int> frames = kept_frames(o.out);
  int frame = o.frame;
  if (frame < 0 && !frames.empty()) frame = frames.back();
  if (frame >= 0 && !std::binary_search(frames.begin(), frames.end(), frame))
    throw std::runtime_error(fmt::format("--frame {}: {} holds no frame-{}/ (kept: {})", frame,
                                         o.out, frame, fmt::join(frames, ", ")));
  const Result<HttpAddress> address = parse_http_address(o.http);
  if (!address.ok()) throw std::invalid_argument("--http: " + address.reason());
  ControlServer server(*address, make_access_token());
  server.refuse_steering("the run is over: nothing to steer");
  if (frame >= 0)
    server.publish_displays(displays_of(fs::path(o.out) / fmt::format("frame-{}", frame), wall));
  server.publish_pictures(pictures_in(o.out));
  server.publish(finished_state(o, wall, frame));
  std::fprintf(stderr, "l2wall view: %s (Ctrl-C ends)\n", server.url().c_str());
  catch_stop_signals();
  while (stop_signal_received() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return 0;
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* v = app.add_subcommand(
      "view",
      "serve the control page of a finished run from its --out folder: the displays of a kept "
      "frame, the summary, the pipeservers' times, the tiles and every picture in the folder");
  v->add_option("OUT", o->out, "the --out folder of an `l2wall run`")
      ->required()
      ->check(CLI::ExistingDirectory);
  add_wall_option(*v, o->wall, "the run's wall (default: the built-in default wall)");
  v->add_option("--http", o->http, "where to serve the page, [ADDR:]PORT as for `l2wall run`")
      ->check([](const std::string& s) { return parse_http_address(s).reason(); }, "[ADDR:]PORT")
      ->capture_default_str();
  v->add_option("--frame", o->frame,
                "the kept frame whose displays the page shows (default: the last kept)")
      ->check(CLI::NonNegativeNumber);
  v->callback([o] {
    int code = 1;
    try {
      code = view(*o);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "l2wall view: %s\n", e.what());
    }
    std::cout << std::flush;
    throw CLI::RuntimeError(code);
  });
}

}  // namespace l2
