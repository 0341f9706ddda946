#include "displays/monitor_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "displays/display_error.hpp"

namespace l2 {
namespace {

using ::testing::HasSubstr;

Wall wall_with_monitors(std::vector<std::string> monitors) {
  Wall wall;
  wall.source = "walls/test.toml";
  for (std::size_t i = 0; i < monitors.size(); ++i) {
    Display d;
    d.id = static_cast<int>(i);
    d.width = 640;
    d.height = 480;
    d.monitor = monitors[i];
    wall.displays.push_back(d);
  }
  return wall;
}

const std::vector<MonitorInfo> kTwo = {{"DP-1", 0, 0, 1920, 1080}, {"HDMI-2", 1920, 0, 1280, 1024}};

std::string error_of(const Wall& wall, const std::vector<MonitorInfo>& monitors) {
  try {
    map_displays_to_monitors(wall, monitors);
  } catch (const DisplayError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MonitorMap, NamesAndIndicesPickMonitors) {
  EXPECT_EQ(map_displays_to_monitors(wall_with_monitors({"HDMI-2", "DP-1"}), kTwo),
            (std::vector<int>{1, 0}));
  EXPECT_EQ(map_displays_to_monitors(wall_with_monitors({"1", "0"}), kTwo),
            (std::vector<int>{1, 0}));
}

TEST(MonitorMap, DescribesTheMonitorsGlfwSees) {
  EXPECT_EQ(describe_monitors(kTwo),
            "2 monitors: [0] \"DP-1\" 1920x1080 at (0,0), [1] \"HDMI-2\" 1280x1024 at (1920,0)");
  EXPECT_EQ(describe_monitors({}), "0 monitors");
}

TEST(MonitorMap, FewerMonitorsThanDisplaysIsRefusedListingThem) {
  const std::vector<MonitorInfo> one = {{"screen", 0, 0, 1600, 1200}};
  EXPECT_EQ(error_of(wall_with_monitors({"0", "1"}), one),
            "walls/test.toml: --show monitors needs one monitor per display: 2 displays, but "
            "GLFW sees 1 monitor: [0] \"screen\" 1600x1200 at (0,0)");
}

TEST(MonitorMap, DisplayWithoutMonitorIsRefused) {
  EXPECT_EQ(error_of(wall_with_monitors({"DP-1", ""}), kTwo),
            "walls/test.toml: display 1 has no monitor (set its `monitor` to a name or index); "
            "GLFW sees 2 monitors: [0] \"DP-1\" 1920x1080 at (0,0), [1] \"HDMI-2\" 1280x1024 at "
            "(1920,0)");
}

TEST(MonitorMap, UnknownNameOrIndexIsRefused) {
  EXPECT_THAT(error_of(wall_with_monitors({"DP-3", "0"}), kTwo),
              HasSubstr("display 0: monitor \"DP-3\" not found; GLFW sees 2 monitors"));
  EXPECT_THAT(error_of(wall_with_monitors({"2", "0"}), kTwo),
              HasSubstr("display 0: monitor \"2\" not found"));
  EXPECT_THAT(error_of(wall_with_monitors({"-1", "0"}), kTwo),
              HasSubstr("display 0: monitor \"-1\" not found"));
}

TEST(MonitorMap, TwoDisplaysOnOneMonitorAreRefused) {
  EXPECT_THAT(error_of(wall_with_monitors({"DP-1", "0"}), kTwo),
              HasSubstr("displays 0 and 1 both use monitor [0] \"DP-1\""));
}

}  // namespace
}  // namespace l2
