// The control page's HTTP server (`l2wall run --http`, `l2wall view`): one page with its script
// and style, all served from this program (the page works offline), and a small JSON API:
//
//   GET  /api/state                   the RunState last published, as JSON
//   GET  /api/display/ID.png?scale=N  display ID as last published, every Nth pixel (1: all)
//   GET  /api/picture/NAME            another picture of the run (`l2wall view`: its saved frames,
//                                     the golden check's and the verifier's pictures)
//   POST /api/pause, /api/resume, /api/save, /api/stop, /api/balance?mode=M, /api/window?...
//   POST /api/share?width=W&height=H&x=X&y=Y&name=N
//                                     a screen shared from the browser: the run opens a window
//   POST /api/share/frame?window=ID   body: one JPEG frame of that share (share_inbox.hpp)
//
// A POST waits for the run's decision on it and answers with it: 200 {"done":"..."}, or the
// refusal's status (400, 404, 409) with {"error":"..."}, the same text the page's events show;
// 503 when the run takes no request within the wait (nothing changed).
//
// Every POST needs the run's token (`?token=` or the X-L2-Token header), so nobody else on the
// network steers the wall; bound beyond loopback, the GETs of /api/ need it too. A refusal is
// 403 with a one-line JSON reason and changes nothing. The requests reach the run through the
// inbox; the run publishes what it shows. Served on threads of its own, their connections
// bounded in number, per client and in time (a flood is answered 503; src/bounded_server.hpp).
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "control_page/control_inbox.hpp"
#include "control_page/http_address.hpp"
#include "control_page/run_state.hpp"
#include "control_page/share_inbox.hpp"
#include "image/rgb_image.hpp"

namespace l2 {

struct NamedPicture {
  std::string name;  // "frame-9~display-0.png"
  std::filesystem::path file;
};

class ControlServer {
 public:
  // Listens on `address` and starts serving. Throws std::runtime_error in one line when it
  // cannot ("--http 127.0.0.1:8080: cannot listen (the port is taken, or the address is not
  // this machine's)"). A POST waits at most `decision_wait` for the run to take it: a run takes
  // requests between frames and while paused, so only a run starting or held up makes it wait.
  ControlServer(const HttpAddress& address, std::string token,
                std::chrono::milliseconds decision_wait = std::chrono::seconds(5));
  ~ControlServer();  // stops serving; requests in flight are answered first
  ControlServer(const ControlServer&) = delete;
  ControlServer& operator=(const ControlServer&) = delete;

  int port() const;
  // The page's address with the token: "http://127.0.0.1:8080/?token=...".
  std::string url() const;

  // What the page shows from now on. Cheap to call often: the pictures are shared, not copied
  // again, and encoded only when a page asks for them.
  void publish(const RunState& state);
  void publish_displays(std::shared_ptr<const std::vector<RgbImage>> displays);
  // Other pictures (PNG files) by name (`l2wall view`: the saved frames, the golden check's and
  // the verifier's), read from their files when asked for. Names are of letters, digits and
  // . _ - ~ only: a request names one of them, never a path.
  void publish_pictures(std::vector<NamedPicture> pictures);

  ControlInbox& inbox();
  // The screens shared into the run: the run opens and closes them, the server feeds frames.
  std::shared_ptr<ShareInbox> shares() const;
  // From now on every POST, waiting ones too, is refused with 409 and `why` ("the run is over:
  // ..."): a finished run has nothing to steer.
  void refuse_steering(std::string why);

  // Whether a page read /api/state within `recently`: a run with nobody watching need not
  // gather its displays' pictures (under MPI that is a fetch from every column rank).
  bool watched(std::chrono::milliseconds recently) const;

  // Whether a page read /api/state within `recently`; if so, waits (at most `limit`) until it
  // has read the state published last, so a run that ends shows the page how it ended.
  void let_readers_see_the_end(std::chrono::milliseconds recently, std::chrono::milliseconds limit);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace l2
