#include "control_page/run_state.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace l2 {
namespace {

TEST(RunStateJson, CarriesWhatThePageDraws) {
  RunState s;
  s.wall_name = "two";
  s.canvas_width = 2048;
  s.canvas_height = 768;
  s.displays = {{0, 0, 0, 1024, 768, 0, {}}, {1, 1024, 0, 768, 1024, 1, {90, Flip::Vertical}}};
  s.frame = 41;
  s.paused = true;
  s.tiles = {{0, 0, 512, 384, 3}};
  s.pipeservers = {
      {2, "pid 99", {{40, 1.5, 2.25, 1}}, "", true, "osmesa (llvmpipe; --renderer osmesa)"}};
  s.events = {{40, "saved"}};
  s.balance_mode = "kd";
  s.balance_modes = {"static", "kd"};
  s.windows = {{7, "picture", -20, 30, 400, 300}};
  s.windows_movable = true;
  s.share_slots = 2;
  s.shares = {{5, "alice", 1280, 720, 30, 28, 2, 1, 0.5}};
  const auto j = nlohmann::json::parse(to_json(s));
  EXPECT_EQ(j["wall"]["name"], "two");
  EXPECT_EQ(j["wall"]["canvas"]["width"], 2048);
  ASSERT_EQ(j["displays"].size(), 2u);
  EXPECT_EQ(j["displays"][1]["x"], 1024);
  EXPECT_EQ(j["displays"][1]["swap_group"], 1);
  EXPECT_EQ(j["displays"][0]["rotation"], 0);
  EXPECT_EQ(j["displays"][0]["flip"], "none");
  EXPECT_EQ(j["displays"][1]["rotation"], 90);
  EXPECT_EQ(j["displays"][1]["flip"], "vertical");
  EXPECT_EQ(j["frame"], 41);
  EXPECT_EQ(j["paused"], true);
  EXPECT_EQ(j["tiles"][0]["pipeserver"], 3);
  EXPECT_EQ(j["tiles"][0]["width"], 512);
  EXPECT_EQ(j["pipeservers"][0]["index"], 2);
  EXPECT_EQ(j["pipeservers"][0]["lost"], true);
  EXPECT_EQ(j["pipeservers"][0]["renderer"], "osmesa (llvmpipe; --renderer osmesa)");
  EXPECT_EQ(j["pipeservers"][0]["recent"][0]["ready_wait_ms"], 2.25);
  EXPECT_EQ(j["pipeservers"][0]["recent"][0]["sync_retries"], 1);
  EXPECT_EQ(j["events"][0]["text"], "saved");
  EXPECT_EQ(j["balance"]["modes"][1], "kd");
  ASSERT_EQ(j["windows"]["shown"].size(), 1u);
  EXPECT_EQ(j["windows"]["shown"][0]["id"], 7);
  EXPECT_EQ(j["windows"]["shown"][0]["source"], "picture");
  EXPECT_EQ(j["windows"]["shown"][0]["x"], -20);
  EXPECT_EQ(j["windows"]["shown"][0]["height"], 300);
  EXPECT_EQ(j["windows"]["movable"], true);
  EXPECT_EQ(j["shares"]["slots"], 2);
  ASSERT_EQ(j["shares"]["shown"].size(), 1u);
  EXPECT_EQ(j["shares"]["shown"][0], nlohmann::json({{"window", 5},
                                                     {"name", "alice"},
                                                     {"width", 1280},
                                                     {"height", 720},
                                                     {"received", 30},
                                                     {"shown", 28},
                                                     {"dropped", 2},
                                                     {"refused", 1},
                                                     {"seconds_since_frame", 0.5}}));
}

TEST(RunStateJson, ANameThatIsNotUtf8StillGivesJson) {
  RunState s;
  s.wall_name = "wall\xff";
  const auto j = nlohmann::json::parse(to_json(s));
  EXPECT_EQ(j["wall"]["name"], "wall\xEF\xBF\xBD");  // U+FFFD
}

}  // namespace
}  // namespace l2
