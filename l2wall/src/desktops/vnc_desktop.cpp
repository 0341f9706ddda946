// The desktop over RFB (libvncclient): one connection, held by the coordinator alone, asking
// for incremental updates. libvncclient reads each server message whole (HandleRFBServerMessage)
// and asks for the next incremental update itself once an update is in; this process takes
// messages only between frames' freezes, so a frozen frame never holds half an update.
#include <fmt/format.h>
#include <rfb/rfbclient.h>

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>

#include "desktop_source.hpp"

namespace l2 {

bool read_vnc_password(const std::string& file, std::string& password);  // vnc_password.cpp

namespace {

// libvncclient's log lines: kept (the last one says why a connection failed), never printed.
std::string& last_log() {
  static std::string line;
  return line;
}
void keep_log(const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  std::string& line = last_log();
  line = buffer;
  while (!line.empty() && (line.back() == '\n' || line.back() == ' ')) line.pop_back();
}

// This connection's state, reached from libvncclient's callbacks through the client's data.
struct Link {
  std::string password;
  bool has_password = false;
  bool asked_password = false;
  int width = 0, height = 0;  // the desktop's size when connected
  bool resized = false;
  DesktopFrames* frames = nullptr;  // set during take_updates
};
const int kLinkTag = 0;

Link& link_of(rfbClient* client) {
  return *static_cast<Link*>(rfbClientGetClientData(client, const_cast<int*>(&kLinkTag)));
}

char* give_password(rfbClient* client) {
  Link& l = link_of(client);
  l.asked_password = true;
  return strdup(l.has_password ? l.password.c_str() : "");
}

// The first call makes the framebuffer; a later one is the server resizing the desktop,
// which the run refuses (a framebuffer is still made, so libvncclient goes on safely).
rfbBool make_framebuffer(rfbClient* client) {
  Link& l = link_of(client);
  if (l.width != 0 && (client->width != l.width || client->height != l.height)) l.resized = true;
  if (l.width == 0) {
    l.width = client->width;
    l.height = client->height;
  }
  std::free(client->frameBuffer);
  const std::size_t bytes = static_cast<std::size_t>(client->width) * client->height * 4;
  client->frameBuffer = static_cast<std::uint8_t*>(std::calloc(bytes, 1));
  return client->frameBuffer != nullptr;
}

// The framebuffer is 32 bits a pixel, red in the lowest byte (rfbGetClient(8, 3, 4)'s
// format): each updated rectangle is copied into the live desktop as RGB.
void got_update(rfbClient* client, int x, int y, int w, int h) {
  Link& l = link_of(client);
  if (!l.frames || l.resized) return;
  const Rect r = intersect({x, y, w, h}, {0, 0, l.frames->width(), l.frames->height()});
  if (r.empty()) return;
  RgbImage& live = l.frames->live();
  for (int row = r.y; row < r.bottom(); ++row) {
    const std::uint8_t* in =
        client->frameBuffer + (static_cast<std::size_t>(row) * client->width + r.x) * 4;
    std::uint8_t* out = live.row(row).data() + static_cast<std::size_t>(r.x) * 3;
    for (int i = 0; i < r.w; ++i, in += 4, out += 3) {
      out[0] = in[0];
      out[1] = in[1];
      out[2] = in[2];
    }
  }
  l.frames->damaged(r);
}

class VncDesktop final : public DesktopSource {
 public:
  VncDesktop(std::string address, rfbClient* client, std::unique_ptr<Link> link)
      : address_(std::move(address)), client_(client), link_(std::move(link)) {}
  ~VncDesktop() override { rfbClientCleanup(client_); }
  VncDesktop(const VncDesktop&) = delete;
  VncDesktop& operator=(const VncDesktop&) = delete;

  int width() const override { return link_->width; }
  int height() const override { return link_->height; }

  void take_updates(DesktopFrames& frames, std::chrono::milliseconds wait) override {
    link_->frames = &frames;
    auto usecs = static_cast<unsigned>(wait.count() * 1000);
    for (;;) {
      const int ready = WaitForMessage(client_, usecs);
      if (ready < 0) gone();
      if (ready == 0) break;
      if (!HandleRFBServerMessage(client_)) gone();
      if (link_->resized) {
        throw DesktopError(fmt::format(
            "vnc {}: the desktop changed size from {}x{} to {}x{}; the run shows one size",
            address_, link_->width, link_->height, client_->width, client_->height));
      }
      usecs = 0;  // take what is there, wait no more
    }
    link_->frames = nullptr;
  }

 private:
  [[noreturn]] void gone() {
    link_->frames = nullptr;
    throw DesktopError(fmt::format("vnc {}: the server closed the connection", address_));
  }

  std::string address_;
  rfbClient* client_;
  std::unique_ptr<Link> link_;
};

}  // namespace

std::pair<std::string, int> vnc_endpoint(const std::string& address) {
  const std::size_t colon = address.find(':');
  const auto bad = [&] {
    return DesktopError(fmt::format(
        "vnc '{}': expected HOST:DISPLAY (port 5900 + DISPLAY) or HOST::PORT", address));
  };
  if (colon == std::string::npos || colon == 0) throw bad();
  const bool port = address.compare(colon, 2, "::") == 0;
  const std::string number = address.substr(colon + (port ? 2 : 1));
  if (number.empty() || number.size() > 5 ||
      number.find_first_not_of("0123456789") != std::string::npos)
    throw bad();
  const int n = std::stoi(number);
  const int at = port ? n : 5900 + n;
  if (at < 1 || at > 65535) throw bad();
  return {address.substr(0, colon), at};
}

std::unique_ptr<DesktopSource> connect_vnc(const std::string& address,
                                           const std::string& password_file) {
  const auto [host, port] = vnc_endpoint(address);
  auto link = std::make_unique<Link>();
  if (!password_file.empty()) {
    if (!read_vnc_password(password_file, link->password))
      throw DesktopError(fmt::format(
          "--vnc-password-file {}: cannot read a password from it (make it with vncpasswd -f)",
          password_file));
    link->has_password = true;
  }
  rfbClientLog = keep_log;
  rfbClientErr = keep_log;
  last_log().clear();
  rfbClient* client = rfbGetClient(8, 3, 4);
  if (!client) throw DesktopError("vnc: cannot make an RFB client");
  rfbClientSetClientData(client, const_cast<int*>(&kLinkTag), link.get());
  client->GetPassword = give_password;
  client->MallocFrameBuffer = make_framebuffer;
  client->GotFrameBufferUpdate = got_update;
  client->canHandleNewFBSize = TRUE;
  // Lossless encodings only: Tight's JPEG would change the desktop's pixels, and every wall
  // pixel is to be a desktop pixel.
  client->appData.enableJPEG = FALSE;
  client->serverHost = strdup(host.c_str());
  client->serverPort = port;
  Link& l = *link;
  // rfbInitClient frees the client when it fails.
  if (!rfbInitClient(client, nullptr, nullptr)) {
    const std::string why = last_log().empty() ? "no reason given" : last_log();
    if (l.asked_password && !l.has_password)
      throw DesktopError(fmt::format(
          "vnc {}: the server wants a password: give it with --vnc-password-file", address));
    if (l.asked_password)
      throw DesktopError(fmt::format("vnc {}: the server refused the password ({})", address, why));
    throw DesktopError(
        fmt::format("vnc {}: cannot connect to {} port {}: {}", address, host, port, why));
  }
  return std::make_unique<VncDesktop>(address, client, std::move(link));
}

}  // namespace l2
