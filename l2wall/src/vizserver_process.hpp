// The vizserver path of a live run, seen from l2wall: the compositing server runs as its own
// process (the `vizserver` executable), listens for the pipeservers' tiles on --viz-host and
// --viz-port, and streams every swapped frame's displays back to this process over a TCP
// connection it opens to us (the display stream, docs/vizserver-protocol.md). Its first message
// says which port it bound, so port 0 has no race; its death is seen at once as the stream
// closing, and its exit status is reaped like a pipeserver's.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/child_process.hpp"
#include "viz_link/run_token.hpp"
#include "vizserver/compositing_server.hpp"
#include "vizserver/display_watcher.hpp"

namespace l2 {

struct VizLaunch {
  std::string program;  // the vizserver executable
  std::string host = "127.0.0.1";
  int port = 0;  // 0: a free one
  std::vector<std::pair<int, int>> display_sizes;
  int pipeservers = 0;
  int frames = 0;
  std::chrono::milliseconds start_timeout{60000};  // to listen, and for every HELLO
  std::filesystem::path log;                       // its listening and per-swap lines
  bool survive_losses = false;  // a pipeserver's early close awaits lose_pipeserver()
};

class VizserverProcess {
 public:
  // Starts the compositing server and waits (up to start_timeout, watching the process) until
  // it says which port it listens on. Throws RunFault: it did not start, died, or could not
  // listen (its reason).
  explicit VizserverProcess(const VizLaunch& launch);
  ~VizserverProcess();  // shut_down()
  VizserverProcess(const VizserverProcess&) = delete;
  VizserverProcess& operator=(const VizserverProcess&) = delete;

  // HOST:PORT for the pipeservers (127.0.0.1 when it listens on every interface).
  std::string address() const;
  pid_t pid() const { return process_ ? process_->pid() : -1; }
  // "L2_VIZ_TOKEN=<32 hex digits>": the run's token, in the environment of every pipeserver
  // that sends it tiles (its HELLO carries it; the server refuses a HELLO without it).
  std::string token_variable() const;
  // "compositing server (vizserver pid 4242)": how every message of the run names it.
  std::string name() const;

  // The displays of frame `frame` once the server swapped it; nullptr when not yet within
  // `timeout`, or when the stream ended or broke (then down() is true). Asking again for the
  // frame last returned gives it again.
  viz::FramePtr frame(int frame, std::chrono::milliseconds timeout);
  // The last frame returned by frame(), if any: what the displays show on this path.
  const viz::FramePtr& last() const { return last_; }

  // Tells the server pipeserver `pipeserver` is lost (LOST on the display stream; it was
  // started with --survive-loss): its frames stop waiting for it. A stream that cannot take it
  // is one that ended: down() says so.
  void lose_pipeserver(int pipeserver);
  // The process ended, or its display stream ended or broke.
  bool down();
  // Waits up to `grace` for a server whose stream ended to be reaped too, so the fault names
  // how it ended rather than racing its exit.
  void settle(std::chrono::milliseconds grace);
  // True when the server ended by its own judgement, saying why (exit code 1 after ERROR):
  // then its words name the cause, which may be a pipeserver.
  bool said_why() const;
  // "compositing server (vizserver pid 4242) killed by signal 9 (Killed) at frame 12; " +
  // on_displays — or "... failed at frame 12: <its reason>; " + on_displays (what the displays
  // show).
  std::string describe_down(int shown, const std::string& on_displays) const;

  // After the last frame: the server must end by itself, successfully, within `timeout`.
  void finish(std::chrono::milliseconds timeout);
  // Ends the server (SIGTERM, then SIGKILL) and reaps it, then stops the stream reader.
  void shut_down();

 private:
  void accept_stream(const Fd& listener, const VizLaunch& launch);

  std::string host_;
  std::uint16_t port_ = 0;
  viz::RunToken token_;
  std::optional<ChildProcess> process_;
  std::optional<ExitStatus> exit_;
  std::unique_ptr<viz::DisplayWatcher> watcher_;
  std::optional<std::string> stream_error_;  // why frame() stopped finding frames
  viz::FramePtr last_;
};

}  // namespace l2
