// `--renderer egl|osmesa|auto`: what a pipeserver renders its OpenGL with, one option meaning the
// same on `pipeserver` and on `l2wall run` (which checks it as a pipeserver does and passes it to
// every pipeserver, on one machine and over MPI). Words only, no GL: l2wall reads it without the
// renderer. What a choice decides on a machine is gl_context.hpp's decide_renderer().
//
// Example:
//   app.add_option("--renderer", name, kRendererHelp)->check(renderer_choice_check,
//   "egl|osmesa|auto"); const RendererChoice choice = parse_renderer_choice(name).value();
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace l2 {

enum class RendererChoice {
  Auto,    // EGL on a GPU, else OSMesa
  Egl,     // EGL, headless: the GPU's device, else Mesa's software device (llvmpipe)
  OsMesa,  // Mesa's off-screen software rasteriser
};

inline constexpr const char* kRendererChoiceNames = "egl|osmesa|auto";

inline std::optional<RendererChoice> parse_renderer_choice(std::string_view name) {
  if (name == "auto") return RendererChoice::Auto;
  if (name == "egl") return RendererChoice::Egl;
  if (name == "osmesa") return RendererChoice::OsMesa;
  return std::nullopt;
}

inline const char* renderer_choice_name(RendererChoice c) {
  switch (c) {
    case RendererChoice::Egl:
      return "egl";
    case RendererChoice::OsMesa:
      return "osmesa";
    case RendererChoice::Auto:
      break;
  }
  return "auto";
}

// For a CLI11 check: empty when `name` is a choice, else why not (one line).
inline std::string renderer_choice_check(const std::string& name) {
  if (parse_renderer_choice(name)) return {};
  return "expected egl, osmesa or auto, got " + name;
}

inline constexpr const char* kRendererHelp =
    "what renders the OpenGL: egl (EGL without a window system: the machine's GPU, or Mesa's "
    "llvmpipe where it has none), osmesa (Mesa's off-screen software rasteriser) or auto (EGL "
    "when EGL finds a GPU, else OSMesa, saying why). Both give the same pixels on llvmpipe; the "
    "run's summary says what each pipeserver decided on";

}  // namespace l2
