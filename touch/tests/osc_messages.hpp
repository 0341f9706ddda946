// OSC messages written as values, for the tests of what takes them (tuio_cursors, gestures).
#pragma once

#include <string>
#include <vector>

#include "touch/osc_packet.hpp"

namespace l2::testing_support {

inline OscArg s(const std::string& text) {
  OscArg a;
  a.type = 's';
  a.text = text;
  return a;
}
inline OscArg i(std::int64_t v, char type = 'i') {
  OscArg a;
  a.type = type;
  a.integer = v;
  return a;
}
inline OscArg f(double v, char type = 'f') {
  OscArg a;
  a.type = type;
  a.real = v;
  return a;
}
inline OscMessage cur(std::vector<OscArg> args) {
  return {"/tuio/2Dcur", std::move(args)};
}
inline OscMessage alive(const std::vector<int>& ids) {
  std::vector<OscArg> args{s("alive")};
  for (const int id : ids) args.push_back(i(id));
  return cur(args);
}
inline OscMessage set(int id, double x, double y) {
  return cur({s("set"), i(id), f(x), f(y), f(0), f(0), f(0)});
}
inline OscMessage fseq(int n) {
  return cur({s("fseq"), i(n)});
}

}  // namespace l2::testing_support
