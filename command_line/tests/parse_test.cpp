#include "command_line/parse.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace l2 {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsReplacementsAndSwaps) {
  EXPECT_EQ(edit_distance("--refresh", "--refresh"), 0u);
  EXPECT_EQ(edit_distance("--refrsh", "--refresh"), 1u);  // one left out
  EXPECT_EQ(edit_distance("--wal", "--wall"), 1u);
  EXPECT_EQ(edit_distance("--refreshh", "--refresh"), 1u);  // one too many
  EXPECT_EQ(edit_distance("--rafresh", "--refresh"), 1u);   // one wrong
  EXPECT_EQ(edit_distance("--rferesh", "--refresh"), 1u);   // two swapped
  EXPECT_EQ(edit_distance("", "--out"), 5u);
  EXPECT_EQ(edit_distance("--out", "--wall"), 4u);
}

TEST(ClosestName, OnlyWhenClose) {
  const std::vector<std::string> names = {"--wall", "--refresh", "--frames", "--out",
                                          "--pipeserver-program"};
  EXPECT_EQ(closest_name("--refrsh", names), "--refresh");
  EXPECT_EQ(closest_name("--wal", names), "--wall");
  EXPECT_EQ(closest_name("--fames", names), "--frames");
  // A long name takes up to a third of its length in edits.
  EXPECT_EQ(closest_name("--pipesrver-progrm", names), "--pipeserver-program");
  EXPECT_EQ(closest_name("--no-such-option", names), "");
  EXPECT_EQ(closest_name("--x", names), "");
  EXPECT_EQ(closest_name("--wall", names), "");  // given right: nothing to suggest
}

// What parse_command_line prints for `args` to a program of two subcommands.
std::string usage_error(std::vector<std::string> args) {
  CLI::App app{"test"};
  app.require_subcommand(1);
  CLI::App* run = app.add_subcommand("run", "run");
  double refresh = 60;
  int frames = 1;
  bool live = false, upside_down = false;
  run->add_option("--refresh", refresh, "rate");
  run->add_option("--frames", frames, "frames");
  run->add_option_group("live", "live")->add_flag("--live", live, "live mode");
  CLI::App* plot = app.add_subcommand("plot", "plot");
  plot->add_flag("--upside-down", upside_down, "backwards");
  args.insert(args.begin(), "/bin/prog");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  ::testing::internal::CaptureStderr();
  const std::optional<int> status =
      parse_command_line(app, static_cast<int>(argv.size()), argv.data());
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(status, kExitUsageError) << err;
  return err.substr(0, err.find('\n'));
}

TEST(ParseCommandLine, AnUnknownOptionNamesTheClosestOneOfItsSubcommand) {
  EXPECT_EQ(usage_error({"run", "--refrsh", "60"}),
            "prog: The following arguments were not expected: 60 --refrsh (did you mean "
            "--refresh?)");
  EXPECT_EQ(usage_error({"run", "--refrsh=60"}),
            "prog: The following argument was not expected: --refrsh=60 (did you mean "
            "--refresh?)");
  EXPECT_EQ(usage_error({"run", "--liv"}),
            "prog: The following argument was not expected: --liv (did you mean --live?)");
  // Only the options of the subcommand given: --upside-down is plot's.
  EXPECT_EQ(usage_error({"run", "--upside-dwn"}),
            "prog: The following argument was not expected: --upside-dwn");
  EXPECT_EQ(usage_error({"run", "--fames", "2", "--refrsh", "60"}),
            "prog: The following arguments were not expected: 60 --refrsh 2 --fames (did you "
            "mean --frames for --fames, --refresh for --refrsh?)");
  EXPECT_EQ(usage_error({"run", "--no-such-option"}),
            "prog: The following argument was not expected: --no-such-option");
}

}  // namespace
}  // namespace l2
