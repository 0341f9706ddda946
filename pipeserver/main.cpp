// pipeserver: one render node of a Lightning-2 wall, with the built-in scenes (README.md).
#include "pipeserver/renderer.hpp"

int main(int argc, char** argv) {
  return l2::run_pipeserver(argc, argv);
}
