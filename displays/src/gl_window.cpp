#include "gl_window.hpp"

#include <GLFW/glfw3.h>

#include "x11_readback.hpp"

#include "displays/display_error.hpp"
#include "glfw_session.hpp"

namespace l2 {

GlWindow::GlWindow(const WindowSpec& spec) {
  glfwDefaultWindowHints();
  // Legacy GL is all this needs and what every driver (Mesa's software one included) offers.
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
  // Several fullscreen windows: the one losing focus must stay on its monitor.
  glfwWindowHint(GLFW_AUTO_ICONIFY, GLFW_FALSE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_FALSE);
  window_ =
      glfwCreateWindow(spec.width, spec.height, spec.title.c_str(), spec.fullscreen_on, nullptr);
  if (!window_) {
    throw DisplayError("cannot open a " + std::to_string(spec.width) + "x" +
                       std::to_string(spec.height) + " window: " + last_glfw_error());
  }
  if (!spec.fullscreen_on && spec.x >= 0 && spec.y >= 0) glfwSetWindowPos(window_, spec.x, spec.y);
  glfwSetWindowUserPointer(window_, this);
  glfwSetCharCallback(window_, on_char);
  glfwSetKeyCallback(window_, on_key);
  glfwSetWindowCloseCallback(window_, on_close);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(spec.swap_interval);
}

GlWindow::~GlWindow() {
  glfwMakeContextCurrent(window_);
  for (const Texture& t : textures_) {
    if (t.id != 0) glDeleteTextures(1, &t.id);
  }
  glfwMakeContextCurrent(nullptr);
  glfwDestroyWindow(window_);
}

int GlWindow::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int GlWindow::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

void GlWindow::begin_frame(Rgb background) {
  glfwMakeContextCurrent(window_);
  const int w = framebuffer_width(), h = framebuffer_height();
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, h, 0, -1, 1);  // window pixels, origin top-left like the images
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_DITHER);  // dithering may change low bits on shallow visuals
  glClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

void GlWindow::draw_image(std::size_t slot, const RgbImage& image, const Rect& dst) {
  if (image.empty() || dst.empty()) return;
  if (textures_.size() <= slot) textures_.resize(slot + 1);
  Texture& t = textures_[slot];
  if (t.id == 0) {
    glGenTextures(1, &t.id);
    glBindTexture(GL_TEXTURE_2D, t.id);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glBindTexture(GL_TEXTURE_2D, t.id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows are tightly packed RGB
  if (t.width != image.width() || t.height != image.height()) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width(), image.height(), 0, GL_RGB,
                 GL_UNSIGNED_BYTE, image.data());
    t.width = image.width();
    t.height = image.height();
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width(), image.height(), GL_RGB, GL_UNSIGNED_BYTE,
                    image.data());
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  // Image row 0 is texture row 0 and the projection puts y = 0 at the top: no flip needed.
  const auto x0 = static_cast<float>(dst.x), y0 = static_cast<float>(dst.y);
  const auto x1 = static_cast<float>(dst.right()), y1 = static_cast<float>(dst.bottom());
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(x0, y0);
  glTexCoord2f(1, 0);
  glVertex2f(x1, y0);
  glTexCoord2f(1, 1);
  glVertex2f(x1, y1);
  glTexCoord2f(0, 1);
  glVertex2f(x0, y1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
}

void GlWindow::finish_drawing() {
  glfwMakeContextCurrent(window_);
  glFinish();
}

void GlWindow::swap() {
  glfwSwapBuffers(window_);
}

RgbImage GlWindow::read_shown(const Rect& area) {
  glfwMakeContextCurrent(window_);
  glFinish();
  return read_x11_window(window_, area);
}

RgbImage GlWindow::read_shown() {
  return read_shown({0, 0, framebuffer_width(), framebuffer_height()});
}

UserAction GlWindow::next_action() {
  if (actions_.empty()) return UserAction::None;
  const UserAction a = actions_.front();
  actions_.pop_front();
  return a;
}

// Characters, not key codes, so s and q follow the user's keyboard layout.
void GlWindow::on_char(GLFWwindow* w, unsigned int codepoint) {
  auto* self = static_cast<GlWindow*>(glfwGetWindowUserPointer(w));
  switch (codepoint) {
    case ' ':
      self->push(UserAction::PauseToggled);
      break;
    case 's':
    case 'S':
      self->push(UserAction::Screenshot);
      break;
    case 'q':
    case 'Q':
      self->push(UserAction::Quit);
      break;
    default:
      break;
  }
}

void GlWindow::on_key(GLFWwindow* w, int key, int /*scancode*/, int action, int /*mods*/) {
  if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) {
    static_cast<GlWindow*>(glfwGetWindowUserPointer(w))->push(UserAction::Quit);
  }
}

void GlWindow::on_close(GLFWwindow* w) {
  glfwSetWindowShouldClose(w, GLFW_FALSE);  // the run decides when to close, after its cleanup
  static_cast<GlWindow*>(glfwGetWindowUserPointer(w))->push(UserAction::Quit);
}

}  // namespace l2
