// --keep: which frames' displays the run writes (SavedFrames, live_run.hpp).
#include <fmt/format.h>

#include <sstream>
#include <stdexcept>

#include "l2wall/live_run.hpp"

namespace l2 {

SavedFrames parse_saved_frames(const std::string& text) {
  SavedFrames saved;
  if (text == "every") {
    saved.every = true;
  } else if (text == "last") {
    saved.last = true;
  } else if (text != "none") {
    if (text.empty() || text.back() == ',')
      throw std::invalid_argument(fmt::format("--keep: '{}' ends without a frame number", text));
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
      std::size_t used = 0;
      int k = -1;
      try {
        k = std::stoi(item, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != item.size() || item.empty() || k < 0)
        throw std::invalid_argument(
            fmt::format("--keep: '{}' is not every, last, none or a frame number", item));
      saved.frames.insert(k);
    }
  }
  return saved;
}

}  // namespace l2
