// LeakSanitizer and the GL stack. Mesa's GLX and its software DRI driver keep small records for
// the process's lifetime, and at exit the libraries holding them are gone: GLFW unloads libGL
// and the X extension libraries at glfwTerminate, Mesa its driver at XCloseDisplay. LSan then
// reports those records as leaks from modules it can neither name nor suppress. Keeping the
// libraries loaded (RTLD_NODELETE) keeps the records reachable, as in a program that never
// terminates GLFW: no suppression is needed, and a leak of our own still shows. Done as GLFW is
// first initialised (glfw_session.cpp), so that only a process that opens the screen pays for
// loading the GL stack (Mesa's driver links LLVM): most runs of the programs that can open
// windows never do.
#include <dlfcn.h>
#include <limits.h>

#include <initializer_list>
#include <string>

#include "lsan_gl.hpp"

namespace l2 {
namespace {

void* keep_loaded(const char* lib) {
  return dlopen(lib, RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE);
}

}  // namespace

void keep_gl_loaded() {
  for (const char* lib : {"libGL.so.1", "libGLX.so.0", "libglapi.so.0", "libXrandr.so.2",
                          "libXcursor.so.1", "libXinerama.so.1", "libXi.so.6"})
    keep_loaded(lib);
  // Mesa's DRI drivers live in dri/ beside libGLX_mesa, wherever the distribution puts it.
  void* mesa = keep_loaded("libGLX_mesa.so.0");
  char dir[PATH_MAX] = {};
  if (mesa && dlinfo(mesa, RTLD_DI_ORIGIN, dir) == 0)
    keep_loaded((std::string(dir) + "/dri/swrast_dri.so").c_str());
}

}  // namespace l2
