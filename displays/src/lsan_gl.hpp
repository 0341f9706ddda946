// The GL libraries kept loaded for the process's lifetime, for LeakSanitizer (lsan_gl.cpp says
// why).
#pragma once

namespace l2 {

// Loads (if not yet loaded) and pins GLFW's and Mesa's GL libraries; called before GLFW is first
// initialised. Quiet: a library that is missing is left to GLFW to report.
void keep_gl_loaded();

}  // namespace l2
