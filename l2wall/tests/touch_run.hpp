// Touch over TUIO through a live run (`l2wall run --tuio`), as a tracker sends it: a drag, a
// pinch and a tap on a session's windows, and the check that each change is shown on every
// display in the same frame. Used by the one-machine test (live_run_touch_test.cpp) and the
// same under mpirun (mpi/tests/mpi_touch_test.cpp), where the coordinator takes the touches.
#pragma once

#include <functional>
#include <limits>
#include <regex>

#include "base/socket.hpp"
#include "session_references.hpp"
#include "tuio_datagrams.hpp"
#include "wall_run.hpp"

namespace l2::testing_support {

// The default wall's canvas, which TUIO's 0..1 span.
constexpr float kCanvasW = 1300, kCanvasH = 980;

inline TuioFinger at(int id, float x, float y) {
  return {id, x / kCanvasW, y / kCanvasH};
}

struct Place {
  int id = 0;
  Rect r;
  friend bool operator==(const Place&, const Place&) = default;
};

// "WINDOWS k n id x y w h ..." to its windows, back to front.
inline std::vector<Place> places(const std::string& line) {
  std::istringstream in(line);
  std::string word;
  int frame = 0, n = 0;
  in >> word >> frame >> n;
  std::vector<Place> out(static_cast<std::size_t>(std::max(n, 0)));
  for (Place& p : out) in >> p.id >> p.r.x >> p.r.y >> p.r.w >> p.r.h;
  return out;
}

// The session: the swap scene's window 0 behind a picture window 1, as `windows` place them.
inline std::string session_text(const std::vector<Place>& windows) {
  std::string text;
  for (std::size_t z = 0; z < windows.size(); ++z) {
    const Place& p = windows[z];
    text += p.id == 0 ? "[[window]]\nsource = \"swap\"\n"
                      : "[[window]]\nsource = \"picture\"\ncontent = \"pattern.png\"\n"
                        "fit = \"1:1\"\n";
    text += fmt::format("x = {}\ny = {}\nwidth = {}\nheight = {}\nz = {}\n", p.r.x, p.r.y, p.r.w,
                        p.r.h, z);
  }
  return text;
}

class UdpSender {
 public:
  explicit UdpSender(int port) : fd_(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0)) {
    to_.sin_family = AF_INET;
    to_.sin_port = htons(static_cast<std::uint16_t>(port));
    to_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  }
  // A tracker's frames come some milliseconds apart: several steps of the frame loop.
  void send(const std::vector<std::uint8_t>& datagram) {
    EXPECT_EQ(::sendto(fd_.get(), datagram.data(), datagram.size(), 0,
                       reinterpret_cast<const sockaddr*>(&to_), sizeof to_),
              static_cast<ssize_t>(datagram.size()));
    std::this_thread::sleep_for(15ms);
  }

 private:
  Fd fd_;
  sockaddr_in to_{};
};

// The port l2wall says it listens on, once it has said it.
inline int tuio_port(const WallRun& run) {
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  const std::regex said("touch: TUIO on udp 127\\.0\\.0\\.1:(\\d+)");
  std::smatch m;
  for (std::string text = run.output(); !std::regex_search(text, m, said); text = run.output()) {
    if (std::chrono::steady_clock::now() > deadline) return 0;
    std::this_thread::sleep_for(20ms);
  }
  return std::stoi(m[1]);
}

// Waits until frame `k` is kept (a ceiling far above what it takes).
inline void wait_for_frame(const WallRun& run, int k) {
  wait_for_file(run.out() / fmt::format("frame-{}", k), 60s);
}

inline int kept_frames(const WallRun& run) {
  int k = 0;
  while (fs::exists(run.out() / fmt::format("frame-{}", k))) ++k;
  return k;
}

// What a tracker sends once the run shows frame 5: hostile datagrams, a drag, a pinch, a tap.
inline void send_touches(const WallRun& run, int port) {
  wait_for_frame(run, 5);
  UdpSender tracker(port);
  int fseq = 1;
  // Hostile input first: not OSC, and a finger at NaN. Neither moves anything.
  tracker.send({'n', 'o', 'p', 'e'});
  tracker.send(tuio_frame(fseq++, {{7, std::numeric_limits<float>::quiet_NaN(), 0.5f}}));
  tracker.send(tuio_frame(fseq++, {}));
  // A drag of window 1 from 350,250 by 300,220, in three steps: to 600,420.
  const std::pair<float, float> drag[] = {{350, 250}, {450, 330}, {550, 400}, {650, 470}};
  for (const auto& [x, y] : drag) tracker.send(tuio_frame(fseq++, {at(10, x, y)}));
  tracker.send(tuio_frame(fseq++, {}));
  // The pinch lands on the window where the wall shows it dragged.
  const int dragged_by = kept_frames(run) + 10;
  wait_for_frame(run, dragged_by);
  // 60 apart about 700,490, then 90 (1.5 times: 550,385 300x225), then 120 (500,350 400x300).
  tracker.send(tuio_frame(fseq++, {at(20, 670, 490), at(21, 730, 490)}));
  tracker.send(tuio_frame(fseq++, {at(20, 655, 490), at(21, 745, 490)}));
  tracker.send(tuio_frame(fseq++, {at(20, 640, 490), at(21, 760, 490)}));
  tracker.send(tuio_frame(fseq++, {}));
  // A tap on window 0 where window 1 does not cover it: raised in front.
  tracker.send(tuio_frame(fseq++, {at(30, 200, 150)}));
  tracker.send(tuio_frame(fseq++, {}));
}

// Window 1's places in the frames' order (`frames`: windows.txt's): each a step of the drag or
// the pinch, none after a later one, the drag's end and the pinch's end among them; then
// window 0 raised in front. `changed`: the frames whose windows differ from the frame before.
inline void expect_touch_steps(const std::vector<std::vector<Place>>& frames,
                               std::vector<int>& changed) {
  const std::vector<Rect> steps{{300, 200, 200, 150}, {400, 280, 200, 150}, {500, 350, 200, 150},
                                {600, 420, 200, 150}, {550, 385, 300, 225}, {500, 350, 400, 300}};
  std::size_t step = 0;
  bool dragged = false, raised_seen = false;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const std::vector<Place>& f = frames[k];
    ASSERT_EQ(f.size(), 2u) << "frame " << k;
    const Place& one = f[0].id == 1 ? f[0] : f[1];
    while (step < steps.size() && !(steps[step] == one.r)) ++step;
    ASSERT_LT(step, steps.size()) << "frame " << k << ": window 1 at an unexpected place or back";
    dragged = dragged || step == 3;
    const bool raised = f[1].id == 0;
    EXPECT_TRUE(!raised || step == 5) << "frame " << k << ": raised before the pinch ended";
    EXPECT_TRUE(raised || !raised_seen) << "frame " << k << ": lowered again";
    raised_seen = raised_seen || raised;
    if (k > 0 && !(frames[k] == frames[k - 1])) changed.push_back(static_cast<int>(k));
  }
  EXPECT_TRUE(dragged) << "the drag's end was never shown";
  EXPECT_EQ(step, 5u) << "the pinch's end was never shown";
  EXPECT_TRUE(raised_seen) << "window 0 was never raised";
}

// Runs `l2wall run --tuio` on a session (started by `launcher`, e.g. mpirun; empty: directly),
// sends the touches once frame 5 is shown, and checks what every display showed and the run's
// lines and summary. `wait` waits for the run's end.
inline void expect_touches_switch_in_one_frame(const std::string& name, const std::string& launcher,
                                               const std::vector<std::string>& extra,
                                               const std::function<ExitStatus(WallRun&)>& wait) {
  constexpr int kFrames = 150;
  const ScratchDir dir(name);
  RgbImage picture(320, 240);
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x)
      picture.set(x, y,
                  {static_cast<std::uint8_t>(x * 3), static_cast<std::uint8_t>(y * 5),
                   static_cast<std::uint8_t>(x ^ y)});
  write_png(dir / "pattern.png", picture);
  const std::vector<Place> start{{0, {100, 100, 400, 300}}, {1, {300, 200, 200, 150}}};
  std::ofstream(dir / "session.toml") << session_text(start);
  std::vector<std::string> args{"--scene",   "session",
                                "--session", (dir / "session.toml").string(),
                                "--frames",  std::to_string(kFrames),
                                "--keep",    "every",
                                "--tuio",    "127.0.0.1:0"};
  args.insert(args.end(), extra.begin(), extra.end());
  WallRun run(name, args, {}, false, launcher);
  const int port = tuio_port(run);
  ASSERT_NE(port, 0) << run.output();
  send_touches(run, port);
  const int sent_at = kept_frames(run);
  const ExitStatus status = wait(run);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  ASSERT_LT(sent_at + 10, kFrames) << "the run ended before the touches were shown";

  std::ifstream lines(run.out() / "windows.txt");
  std::vector<std::vector<Place>> frames;
  for (std::string line; std::getline(lines, line);) frames.push_back(places(line));
  ASSERT_GE(frames.size(), static_cast<std::size_t>(kFrames));
  std::vector<int> changed;  // frames whose windows differ from the frame before
  ASSERT_NO_FATAL_FAILURE(expect_touch_steps(frames, changed));

  // Every display of the frames around each change is the reference of that frame's places.
  for (const int k : changed) {
    if (k >= kFrames) continue;
    for (const int frame : {k - 1, k}) {
      const fs::path session = dir / fmt::format("at-{}.toml", frame);
      std::ofstream(session) << session_text(frames[static_cast<std::size_t>(frame)]);
      expect_references(run, frame, session);
    }
  }
  const std::string out = run.output();
  EXPECT_NE(out.find("l2wall: touch: window: move 1 600 420 200 150 from the next frame\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("l2wall: touch: window: move 1 500 350 400 300 from the next frame\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("l2wall: touch: window: raise 0 from the next frame\n"), std::string::npos)
      << out;
  EXPECT_NE(slurp(run.out() / "summary.txt")
                .find("touch: 3 gestures (1 tap, 1 drag, 1 pinch), 1 window moved, 1 raised; "
                      "1 packet, 1 message dropped\n"),
            std::string::npos)
      << slurp(run.out() / "summary.txt");
  expect_clean(run);
}

}  // namespace l2::testing_support
