// The OpenGL functions a pipeserver draws with, as a table of pointers that each GL context
// (gl_context.hpp) loads from its own renderer: OSMesa's through OSMesaGetProcAddress, EGL's
// through eglGetProcAddress. Nothing here, nor in a program of your own drawing, calls a plain
// gl* symbol: a process holding both OSMesa and EGL (or a window's libGL, as l2wall does) would
// resolve each such symbol to one library only, and draw into no context, or the wrong one, under
// the other. libOSMesa is loaded by name and keeps its gl* symbols to itself, so a plain gl*
// call does not even link.
//
// Example (the current context's table; gl_context.hpp makes a context current):
//   const l2::GlApi& gl = l2::gl();
//   gl.ClearColor(0, 0, 0, 1);
//   gl.Clear(GL_COLOR_BUFFER_BIT);
//   auto* fn = reinterpret_cast<PFNGLBLENDCOLORPROC>(l2::gl_proc("glBlendColor"));  // any other
#pragma once

// The types, enumerants and PFNGL...PROC types; the prototypes of OpenGL 1.1 give the table
// its types (decltype only: nothing calls them).
#include <GL/gl.h>
#include <GL/glext.h>

namespace l2 {

// Every function of the table: OpenGL 1.1 (the fixed-function pipeline the scenes draw with),
// named without "gl".
// clang-format off
#define L2_GL_FUNCTIONS_1_1(X) \
  X(Begin) X(BindTexture) X(BlendFunc) X(Clear) X(ClearColor) X(ClearDepth) X(Color3f) \
  X(Color4f) X(ColorMaterial) X(ColorPointer) X(DeleteTextures) X(DepthFunc) X(Disable) \
  X(DisableClientState) X(DrawArrays) X(DrawElements) X(DrawPixels) X(Enable) \
  X(EnableClientState) X(End) X(Finish) X(Flush) X(GenTextures) X(GetError) X(GetIntegerv) \
  X(GetString) X(IsTexture) X(Lightfv) X(LightModelfv) X(LightModeli) X(LineWidth) \
  X(LoadIdentity) X(LoadMatrixd) X(LoadMatrixf) X(MatrixMode) X(MultMatrixf) X(Normal3f) \
  X(NormalPointer) X(Ortho) X(PixelStorei) X(PopAttrib) X(PopMatrix) X(PushAttrib) \
  X(PushMatrix) X(ReadBuffer) X(ReadPixels) X(Rotatef) X(Scalef) X(Scissor) X(ShadeModel) \
  X(TexCoord2f) X(TexCoordPointer) X(TexEnvi) X(TexImage2D) X(TexParameteri) X(TexSubImage2D) \
  X(Translatef) X(Vertex2f) X(Vertex3f) X(VertexPointer) X(Viewport)
// clang-format on

// Later versions' functions, by name and the type glext.h gives them.
#define L2_GL_FUNCTIONS_LATER(X)                         \
  X(MultiDrawArrays, PFNGLMULTIDRAWARRAYSPROC) /* 1.4 */ \
  X(WindowPos2i, PFNGLWINDOWPOS2IPROC)         /* 1.4 */

struct GlApi {
#define L2_GL_MEMBER(name) decltype(&::gl##name) name = nullptr;
  L2_GL_FUNCTIONS_1_1(L2_GL_MEMBER)
#undef L2_GL_MEMBER
#define L2_GL_MEMBER(name, type) type name = nullptr;
  L2_GL_FUNCTIONS_LATER(L2_GL_MEMBER)
#undef L2_GL_MEMBER
};

// The table of the GL context current on this thread (GlContext::make_current). Throws
// std::logic_error when none is.
const GlApi& gl();

// Any GL function of the current context's renderer by its name ("glBlendColor"), for what the
// table lacks; nullptr when the renderer has none of that name. Throws std::logic_error when no
// context is current.
void* gl_proc(const char* name);

}  // namespace l2
