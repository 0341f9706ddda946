#include "control_page/control_server.hpp"

#include <fmt/format.h>
#include <httplib.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <condition_variable>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include "bounded_server.hpp"
#include "control_page/access_token.hpp"
#include "image/png_io.hpp"
#include "page_assets.hpp"
#include "scaled_picture.hpp"

namespace l2 {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto Unhandled = httplib::Server::HandlerResponse::Unhandled;

// A request body is at most a mode name: anything larger is refused unread, but a shared
// screen's frame (POST /api/share/frame), a JPEG of at most kMaxFrameBody.
constexpr std::size_t kMaxBody = 4096;
constexpr std::size_t kMaxFrameBody = std::size_t{16} << 20;
constexpr const char* kFramePath = "/api/share/frame";
constexpr int kMaxScale = 64;

void reply_json(httplib::Response& res, int status, const std::string& body) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(body, "application/json");
}

// What a request's Content-Length says; 0 without one.
std::size_t declared_length(const httplib::Request& req) {
  if (!req.has_header("Content-Length")) return 0;
  return std::strtoull(req.get_header_value("Content-Length").c_str(), nullptr, 10);
}

void refuse(httplib::Response& res, int status, const std::string& why) {
  reply_json(res, status, nlohmann::json{{"error", why}}.dump());
}

// The run's decision as the answer: what it did, or why not with the refusal's status.
void answer(httplib::Response& res, const ControlDecision& decision) {
  if (decision.status >= 300) return refuse(res, decision.status, decision.text);
  reply_json(res, decision.status, nlohmann::json{{"done", decision.text}}.dump());
}

std::string given_token(const httplib::Request& req) {
  if (req.has_header("X-L2-Token")) return req.get_header_value("X-L2-Token");
  return req.get_param_value("token");
}

}  // namespace

struct ControlServer::Impl {
  HttpAddress address;
  std::string token;
  BoundedServer server{ConnectionLimits{}};
  std::thread thread;
  int port = 0;
  ControlInbox inbox;
  std::shared_ptr<ShareInbox> shares = std::make_shared<ShareInbox>();
  std::chrono::milliseconds decision_wait{};

  std::mutex mutex;
  std::condition_variable read_happened;
  std::string state_json = "{}";
  std::uint64_t published = 0, read = 0;  // versions of the state: the last published, read
  Clock::time_point last_read{};
  std::shared_ptr<const std::vector<RgbImage>> displays;
  std::vector<NamedPicture> pictures;
  std::string steering_refused;  // why every POST is refused; empty: none is

  // Steering always needs the token; reading only beyond this machine.
  bool allowed(const httplib::Request& req, bool steering) const {
    if (!steering && address.loopback()) return true;
    return token_matches(given_token(req), token);
  }

  void routes() {
    // Only a frame may be large: a GET with a body past kMaxBody is refused before cpp-httplib
    // reads it into memory (a page never sends one); a POST's is read and dropped below.
    server.set_pre_routing_handler([](const httplib::Request& req, httplib::Response& res) {
      if (req.method != "GET" || declared_length(req) <= kMaxBody) return Unhandled;
      refuse(res, 413, fmt::format("a body of at most {} bytes here", kMaxBody));
      res.set_header("Connection", "close");
      return httplib::Server::HandlerResponse::Handled;
    });
    server.post_reading_body(
        kFramePath, [this](const httplib::Request& req, httplib::Response& res,
                           const httplib::ContentReader& body) { take_frame(req, res, body); });
    for (const PageAsset& a : page_assets()) {
      server.Get(std::string(a.path), [&a](const httplib::Request&, httplib::Response& res) {
        res.set_content(std::string(a.body), std::string(a.type) + "; charset=utf-8");
      });
    }
    server.Get("/api/state", [this](const httplib::Request& req, httplib::Response& res) {
      if (!allowed(req, false)) return refuse(res, 403, "this needs the run's token");
      reply_json(res, 200, read_state());
    });
    server.Get(R"(/api/display/(\d{1,3})\.png)",
               [this](const httplib::Request& req, httplib::Response& res) {
                 if (!allowed(req, false)) return refuse(res, 403, "this needs the run's token");
                 serve_display(req, res);
               });
    server.Get(R"(/api/picture/([A-Za-z0-9._~-]{1,200}))",
               [this](const httplib::Request& req, httplib::Response& res) {
                 if (!allowed(req, false)) return refuse(res, 403, "this needs the run's token");
                 serve_picture(req.matches[1].str(), res);
               });
    // What to steer is in the path and the query; a body is read and dropped (`curl -X POST URL`
    // sends none).
    server.post_reading_body(
        R"(/api/(pause|resume|save|stop|balance|window|share))",
        [this](const httplib::Request& req, httplib::Response& res,
               const httplib::ContentReader& body) {
          std::size_t length = 0;
          if (!body([&](const char*, std::size_t n) { return (length += n) <= kMaxBody; })) {
            if (length > kMaxBody)
              refuse(res, 413, fmt::format("a body of at most {} bytes here", kMaxBody));
            return;  // too long or cut short: cpp-httplib's status (413, 400) stands
          }
          if (!allowed(req, true)) return refuse(res, 403, "this needs the run's token");
          if (const std::string why = refusal(); !why.empty()) return refuse(res, 409, why);
          steer(req, res);
        });
  }

  std::string refusal() {
    const std::lock_guard lock(mutex);
    return steering_refused;
  }

  std::string read_state() {
    const std::lock_guard lock(mutex);
    read = published;
    last_read = Clock::now();
    read_happened.notify_all();
    return state_json;
  }

  void serve_display(const httplib::Request& req, httplib::Response& res) {
    const int id = std::stoi(req.matches[1].str());
    int scale = 1;
    if (req.has_param("scale")) {
      scale = std::atoi(req.get_param_value("scale").c_str());
      if (scale < 1 || scale > kMaxScale)
        return refuse(res, 400, fmt::format("scale: expected 1..{}", kMaxScale));
    }
    std::shared_ptr<const std::vector<RgbImage>> shown;
    {
      const std::lock_guard lock(mutex);
      shown = displays;
    }
    if (!shown || id >= static_cast<int>(shown->size()) ||
        (*shown)[static_cast<std::size_t>(id)].empty())
      return refuse(res, 404, fmt::format("display {} shows nothing yet", id));
    const RgbImage& picture = (*shown)[static_cast<std::size_t>(id)];
    res.set_header("Cache-Control", "no-store");
    res.set_content(encode_png(scale == 1 ? picture : every_nth_pixel(picture, scale)),
                    "image/png");
  }

  void serve_picture(const std::string& name, httplib::Response& res) {
    std::filesystem::path file;
    {
      const std::lock_guard lock(mutex);
      const auto it = std::find_if(pictures.begin(), pictures.end(),
                                   [&](const NamedPicture& p) { return p.name == name; });
      if (it == pictures.end()) return refuse(res, 404, "no such picture");
      file = it->file;
    }
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) return refuse(res, 500, "cannot read the picture");
    res.set_header("Cache-Control", "no-store");
    res.set_content(std::move(bytes), "image/png");
  }

  // The run's command line for a window ("move 1 100 80 300 200"): the run checks its words
  // and numbers, and says in the events what it did. Empty: the request lacks a parameter.
  static std::string window_command(const httplib::Request& req) {
    const std::string action = req.get_param_value("action");
    std::vector<const char*> keys{"id"};
    if (action == "move")
      keys.insert(keys.end(), {"x", "y", "w", "h"});
    else if (action != "raise" && action != "close")
      return {};
    std::string command = action;
    for (const char* key : keys) {
      const std::string value = req.get_param_value(key);
      if (value.empty() || value.size() > 12 || value.find(' ') != std::string::npos) return {};
      command += " " + value;
    }
    return command;
  }

  // A shared screen's frame: admitted for an open share before its body is read (at most one
  // body a share at a time), read up to kMaxFrameBody, decoded and kept (share_inbox.hpp). A
  // frame refused before its body is read is dropped by its route (post_reading_body).
  void take_frame(const httplib::Request& req, httplib::Response& res,
                  const httplib::ContentReader& body) {
    if (!allowed(req, true)) return refuse(res, 403, "this needs the run's token");
    if (const std::string why = refusal(); !why.empty()) return refuse(res, 409, why);
    const std::string given = req.get_param_value("window");
    if (given.empty() || given.size() > 5 ||
        given.find_first_not_of("0123456789") != std::string::npos)
      return refuse(res, 400, "frame refused: give ?window=ID, the share's window");
    const int window = std::stoi(given);
    if (!req.has_header("Content-Length"))
      return refuse(res, 411, "frame refused: give its Content-Length");
    if (declared_length(req) > kMaxFrameBody)
      return refuse(res, 413, fmt::format("frame refused: more than {} bytes", kMaxFrameBody));
    if (const ControlDecision d = shares->admit(window); d.status != 200)
      return refuse(res, d.status, d.text);
    std::string jpeg;
    const bool whole = body([&](const char* data, std::size_t n) {
      if (jpeg.size() + n > kMaxFrameBody) return false;
      jpeg.append(data, n);
      return true;
    });
    if (!whole) {
      shares->drop(window);
      return refuse(res, 400, "frame refused: its body was cut short");
    }
    answer(res, shares->put(window, jpeg));
  }

  // A share asked for: "W H CX CY NAME" for the run (CX CY: where on the canvas its window is
  // centred; -1 -1: the canvas's centre). Empty: a parameter is missing or not a number.
  static std::string share_command(const httplib::Request& req) {
    std::string command;
    for (const char* key : {"width", "height", "x", "y"}) {
      std::string value = req.get_param_value(key);
      if (value.empty() && (key[0] == 'x' || key[0] == 'y')) value = "-1";
      if (value.empty() || value.size() > 6 ||
          value.find_first_not_of("-0123456789") != std::string::npos)
        return {};
      command += value + " ";
    }
    std::string name;
    for (const char c : req.get_param_value("name"))
      if (c >= ' ' && c <= '~' && name.size() < 40) name += c;
    return command + (name.find_first_not_of(' ') == std::string::npos ? "browser" : name);
  }

  void steer(const httplib::Request& req, httplib::Response& res) {
    const std::string what = req.matches[1].str();
    ControlRequest r;
    if (what == "pause") r.action = ControlAction::Pause;
    if (what == "resume") r.action = ControlAction::Resume;
    if (what == "save") r.action = ControlAction::Save;
    if (what == "stop") r.action = ControlAction::Stop;
    if (what == "balance") {
      r.action = ControlAction::Balance;
      r.argument = req.get_param_value("mode");
      if (r.argument.empty()) return refuse(res, 400, "balance: give ?mode=");
    }
    if (what == "window") {
      r.action = ControlAction::Window;
      r.argument = window_command(req);
      if (r.argument.empty())
        return refuse(res, 400,
                      "window: give ?action=move&id=ID&x=X&y=Y&w=W&h=H, or action=raise or "
                      "close with id");
    }
    if (what == "share") {
      r.action = ControlAction::Share;
      r.argument = share_command(req);
      if (r.argument.empty())
        return refuse(res, 400, "share: give ?width=W&height=H (its frames' size), and x, y, name");
    }
    const std::uint64_t ticket = inbox.push(std::move(r));
    answer(res, inbox.wait(ticket, decision_wait));
  }
};

ControlServer::ControlServer(const HttpAddress& address, std::string token,
                             std::chrono::milliseconds decision_wait)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.address = address;
  s.decision_wait = decision_wait;
  s.token = std::move(token);
  s.server.set_payload_max_length(kMaxFrameBody);  // others: kMaxBody, refused as they are read
  // A page asks at once and often: a connection that sends nothing for 2 s is closed, so idle
  // peers do not hold their threads long (bounded_server.hpp bounds them in number and time).
  s.server.set_read_timeout(std::chrono::seconds(2));
  s.server.set_keep_alive_timeout(2);
  s.server.set_keep_alive_max_count(100);
  // Not cpp-httplib's default, which adds SO_REUSEPORT: a second run given the same port would
  // then share it with the first, each getting some of the page's requests.
  s.server.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
  });
  s.routes();
  const std::string where = fmt::format("{}:{}", address.host, address.port);
  s.port = address.port == 0
               ? s.server.bind_to_any_port(address.host)
               : (s.server.bind_to_port(address.host, address.port) ? address.port : -1);
  if (s.port <= 0) {
    throw std::runtime_error(fmt::format(
        "--http {}: cannot listen (the port is taken, or the address is not this machine's)",
        where));
  }
  s.server.deepen_backlog();
  s.thread = std::thread([&s] { s.server.listen_after_bind(); });
  // stop() before the server runs would be lost and the thread never end.
  while (!s.server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

ControlServer::~ControlServer() {
  impl_->inbox.close("the run is over: nothing to steer");  // no request waits on a run gone
  impl_->server.stop();
  impl_->thread.join();
  impl_->server.finish();  // no handler runs on once the state it reads is gone
}

int ControlServer::port() const {
  return impl_->port;
}

std::string ControlServer::url() const {
  const std::string host = impl_->address.host.find(':') != std::string::npos
                               ? "[" + impl_->address.host + "]"
                               : impl_->address.host;
  return fmt::format("http://{}:{}/?token={}", host, impl_->port, impl_->token);
}

void ControlServer::publish(const RunState& state) {
  std::string json = to_json(state);
  const std::lock_guard lock(impl_->mutex);
  impl_->state_json = std::move(json);
  ++impl_->published;
}

void ControlServer::publish_displays(std::shared_ptr<const std::vector<RgbImage>> displays) {
  const std::lock_guard lock(impl_->mutex);
  impl_->displays = std::move(displays);
}

void ControlServer::publish_pictures(std::vector<NamedPicture> files) {
  const std::lock_guard lock(impl_->mutex);
  impl_->pictures = std::move(files);
}

ControlInbox& ControlServer::inbox() {
  return impl_->inbox;
}

std::shared_ptr<ShareInbox> ControlServer::shares() const {
  return impl_->shares;
}

void ControlServer::refuse_steering(std::string why) {
  impl_->inbox.close(why);
  const std::lock_guard lock(impl_->mutex);
  impl_->steering_refused = std::move(why);
}

bool ControlServer::watched(std::chrono::milliseconds recently) const {
  const std::lock_guard lock(impl_->mutex);
  return impl_->last_read != Clock::time_point{} && Clock::now() - impl_->last_read <= recently;
}

void ControlServer::let_readers_see_the_end(std::chrono::milliseconds recently,
                                            std::chrono::milliseconds limit) {
  std::unique_lock lock(impl_->mutex);
  if (impl_->last_read == Clock::time_point{} || Clock::now() - impl_->last_read > recently) return;
  impl_->read_happened.wait_for(lock, limit, [&] { return impl_->read == impl_->published; });
}

}  // namespace l2
