// A live `l2wall run --http 127.0.0.1:0` and an HTTP client of its control page, for tests: the
// page's URL (with the token) read from what l2wall printed, the state as JSON, the requests.
// Every wait has a ceiling far above what it takes (60 s) and ends early when the run ends.
#pragma once

#include <httplib.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <regex>

#include "wall_run.hpp"

namespace l2::testing_support {

class PageRun : public WallRun {
 public:
  PageRun(const std::string& name, std::vector<std::string> args)
      : WallRun(name, with_http(std::move(args))) {
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    const std::regex printed("control page: (http://127\\.0\\.0\\.1:(\\d+)/\\?token=([0-9a-f]+))");
    std::smatch m;
    for (std::string text = output(); !std::regex_search(text, m, printed); text = output()) {
      if (std::chrono::steady_clock::now() > deadline)
        throw std::runtime_error("l2wall printed no control page URL: " + text);
      std::this_thread::sleep_for(20ms);
    }
    url_ = m[1];
    token_ = m[3];
    client_.emplace("127.0.0.1", std::stoi(m[2]));
    client_->set_read_timeout(10s);
  }

  const std::string& url() const { return url_; }
  const std::string& token() const { return token_; }
  httplib::Client& client() { return *client_; }

  nlohmann::json state() {
    const auto r = client_->Get("/api/state");
    if (!r || r->status != 200) throw std::runtime_error("GET /api/state failed: " + output());
    // The waits read its fields unchecked: a state without its frame is an error here.
    nlohmann::json s = nlohmann::json::parse(r->body);
    if (!s.is_object() || !s.contains("frame"))
      throw std::runtime_error("GET /api/state: not the run's state: " + r->body);
    return s;
  }

  // POST /api/WHAT (WHAT may carry its own query) with the token: the run's answer, expected
  // with `status`; its body as JSON (null when there was no answer).
  nlohmann::json post(const std::string& what, int status = 200) {
    const std::string path =
        "/api/" + what + (what.find('?') == std::string::npos ? "?" : "&") + "token=" + token_;
    const auto r = client_->Post(path, "", "text/plain");
    if (!r) {
      ADD_FAILURE() << "POST " << what << ": no answer";
      return nullptr;
    }
    EXPECT_EQ(r->status, status) << "POST " << what << ": " << r->body;
    return nlohmann::json::parse(r->body, nullptr, false);
  }

  // The state once `done` says so.
  template <class F>
  nlohmann::json wait_for(F&& done) {
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    for (;;) {
      nlohmann::json s = state();
      if (done(s)) return s;
      if (std::chrono::steady_clock::now() > deadline) {
        ADD_FAILURE() << "the page's state never got there: " << s.dump();
        return s;
      }
      std::this_thread::sleep_for(20ms);
    }
  }
  nlohmann::json wait_for_frame(int frame) {
    return wait_for([frame](const nlohmann::json& s) { return s["frame"].get<int>() >= frame; });
  }

  // Display `id` as the page gets it, every `scale`th pixel.
  RgbImage display(int id, int scale = 1) {
    const auto r = client_->Get(fmt::format("/api/display/{}.png?scale={}", id, scale));
    if (!r || r->status != 200) throw std::runtime_error("GET display failed");
    const fs::path file = out().parent_path() / fmt::format("page-display-{}.png", id);
    std::ofstream(file, std::ios::binary) << r->body;
    return read_png(file);
  }

 private:
  static std::vector<std::string> with_http(std::vector<std::string> args) {
    args.insert(args.end(), {"--http", "127.0.0.1:0"});
    return args;
  }

  std::string url_, token_;
  std::optional<httplib::Client> client_;
};

}  // namespace l2::testing_support
