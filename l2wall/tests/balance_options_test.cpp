// Which balancing a run asks for (the wall's [balance], --balance over its mode), and where
// l2wall refuses it, in the words the user sees.
#include <gtest/gtest.h>

#include "l2wall/live_run.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

Wall strips_wall() {
  Wall wall = default_wall();
  wall.source = "walls/x.toml";
  wall.balance.mode = BalanceMode::Strips;
  wall.balance.line = 14;
  return wall;
}

// A stereo wall refuses balancing asked on the command line as its wall file's [balance] is.
TEST(BalanceOptions, AStereoWallRefusesBalancingFromTheCommandLine) {
  Wall stereo = default_wall();
  stereo.stereo.mode = StereoMode::Passive;
  RunOptions o;
  o.balance = "strips";
  EXPECT_EQ(balance_refusal(o, stereo, RunPlace::OneMachine).reason(),
            "--balance: stereo walls do not support balancing yet");
  o.balance = "static";
  EXPECT_TRUE(balance_refusal(o, stereo, RunPlace::OneMachine).ok());
}

// An active stereo wall: an odd count of eye frames would leave a frame's right eye unshown, a
// session's windows could move between a frame's eyes; over MPI as on one machine (the
// cluster_mpi_stereo_tests run it); any other wall passes.
TEST(BalanceOptions, AnActiveStereoWallRefusesOddFrames) {
  Wall active = default_wall();
  active.stereo.mode = StereoMode::Active;
  RunOptions o;
  o.frames = 4;
  EXPECT_TRUE(stereo_refusal(o, active).ok());
  o.frames = 5;
  EXPECT_EQ(stereo_refusal(o, active).reason(),
            "--frames 5: an active stereo wall's frames are eye frames (left and right of each "
            "application frame): give an even count");
  o.frames = 4;
  o.scene = "session";
  EXPECT_EQ(stereo_refusal(o, active).reason(),
            "--scene session: active stereo walls do not support it yet (its windows or desktop "
            "could change between a frame's left and right eye)");
  o.scene = "movie";
  EXPECT_EQ(stereo_refusal(o, active).reason(),
            "--scene movie: active stereo walls do not support it yet (it would play at half "
            "speed)");
  EXPECT_TRUE(stereo_refusal(o, default_wall()).ok());
}

TEST(BalanceOptions, TheOptionSetsTheModeOverTheWalls) {
  RunOptions o;
  EXPECT_EQ(run_balance(o, strips_wall()).mode, BalanceMode::Strips);
  o.balance = "static";
  EXPECT_EQ(run_balance(o, strips_wall()).mode, BalanceMode::Static);
  o.balance = "kd";
  EXPECT_EQ(run_balance(o, default_wall()).mode, BalanceMode::Kd);
}

TEST(BalanceOptions, EveryPathBalancesAndEachOneMachinePathAloneSurvivesALoss) {
  RunOptions o;
  EXPECT_TRUE(balance_refusal(o, strips_wall(), RunPlace::OneMachine).ok());
  o.path = PathChoice::Both;
  EXPECT_TRUE(balance_refusal(o, strips_wall(), RunPlace::OneMachine).ok());
  o.survive_host_loss = true;
  EXPECT_EQ(balance_refusal(o, strips_wall(), RunPlace::OneMachine).reason(),
            "--survive-host-loss: runs on --path dvi or vizserver, not both (a frame shown stale "
            "differs between them: older pixels on the DVI path, the background on the "
            "vizserver path)");
  o.path = PathChoice::Vizserver;
  EXPECT_TRUE(balance_refusal(o, strips_wall(), RunPlace::OneMachine).ok());
  o.survive_host_loss = false;
  o.path = PathChoice::Dvi;
  o.balance = "strips";
  EXPECT_TRUE(run_balance(o, default_wall()).balancing());
  // MPI balances, on either path; a rank that dies ends the job unless mpirun keeps it.
  EXPECT_TRUE(balance_refusal(o, default_wall(), RunPlace::MpiEndingOnLoss).ok());
  o.path = PathChoice::Both;
  EXPECT_TRUE(balance_refusal(o, default_wall(), RunPlace::MpiEndingOnLoss).ok());
  o.path = PathChoice::Dvi;
  o.survive_host_loss = true;
  EXPECT_EQ(balance_refusal(o, default_wall(), RunPlace::MpiEndingOnLoss).reason(),
            "--survive-host-loss: over MPI (--mpi) needs an mpirun that keeps the job when a rank "
            "dies: mpirun --mca orte_enable_recovery 1 --mca orte_abort_on_non_zero_status 0 ...");
  // An mpirun that keeps the job: a pipeserver rank that dies is survived.
  EXPECT_TRUE(balance_refusal(o, default_wall(), RunPlace::MpiKeepingJob).ok());
  Wall survive = strips_wall();
  survive.balance.survive_host_loss = true;
  EXPECT_EQ(balance_refusal(RunOptions{}, survive, RunPlace::MpiEndingOnLoss).reason(),
            "walls/x.toml:14: balance.survive_host_loss: over MPI (--mpi) needs an mpirun that "
            "keeps the job when a rank dies: mpirun --mca orte_enable_recovery 1 --mca "
            "orte_abort_on_non_zero_status 0 ...");
  EXPECT_TRUE(balance_refusal(RunOptions{}, survive, RunPlace::MpiKeepingJob).ok());
  o.survive_host_loss = false;
  // Static asks for nothing to refuse.
  o.balance = "static";
  o.path = PathChoice::Vizserver;
  EXPECT_FALSE(run_balance(o, strips_wall()).balancing());
  EXPECT_TRUE(balance_refusal(o, strips_wall(), RunPlace::MpiEndingOnLoss).ok());
}

// Surviving a dead pipeserver is the same on the command line and in the wall file, and needs a
// balancing run (only it re-plans).
TEST(BalanceOptions, SurvivingAHostLossNeedsBalancing) {
  RunOptions o;
  EXPECT_FALSE(run_balance(o, strips_wall()).survive_host_loss);
  o.survive_host_loss = true;
  EXPECT_TRUE(run_balance(o, strips_wall()).survive_host_loss);
  EXPECT_TRUE(balance_refusal(o, strips_wall(), RunPlace::OneMachine).ok());
  EXPECT_EQ(balance_refusal(o, default_wall(), RunPlace::OneMachine).reason(),
            "--survive-host-loss needs balancing: --balance strips or kd, or a wall file's "
            "[balance]");
  Wall wall = strips_wall();
  wall.balance.survive_host_loss = true;
  EXPECT_TRUE(run_balance(RunOptions{}, wall).survive_host_loss);
  RunOptions static_run;
  static_run.balance = "static";
  EXPECT_EQ(balance_refusal(static_run, wall, RunPlace::OneMachine).reason(),
            "walls/x.toml:14: balance.survive_host_loss needs balancing, which --balance static "
            "turns off");
}

// The run says as it starts what it survives, in tilelayout's words: the default wall survives
// no loss, and a run there must not look as if it would.
TEST(BalanceOptions, SurvivalSaysWhatTheWallSurvives) {
  RunOptions o;
  EXPECT_EQ(survival_note(o, strips_wall()), "");
  o.survive_host_loss = true;
  EXPECT_EQ(survival_note(o, strips_wall()),
            "--survive-host-loss: the wall survives the loss of no pipeserver (framebuffers "
            "800x600); 1: needs framebuffer_height >= 910; a pipeserver that dies ends the run");
  Wall roomy = strips_wall();
  roomy.framebuffer_height = 2400;
  roomy.balance.survive_host_loss = true;
  EXPECT_EQ(survival_note(RunOptions{}, roomy),
            "walls/x.toml:14: balance.survive_host_loss: the wall survives the loss of 2 "
            "pipeservers (framebuffers 800x2400); 3: needs framebuffer_height >= 2443 with [mesh] "
            "board_max_height = 2443");
}

// --resistance and --tile-cost set the wall's [balance] values over its own, and ask for a
// balancing run (only it plans layouts to resist).
TEST(BalanceOptions, ResistanceFromTheWallOrTheCommandLine) {
  Wall wall = strips_wall();
  wall.balance.resistance = 0.1;
  wall.balance.tile_cost = 0.15;
  RunOptions o;
  EXPECT_DOUBLE_EQ(run_balance(o, wall).resistance, 0.1);
  EXPECT_DOUBLE_EQ(run_balance(o, wall).tile_cost, 0.15);
  o.resistance = 0;
  o.tile_cost = 0.3;
  EXPECT_DOUBLE_EQ(run_balance(o, wall).resistance, 0);
  EXPECT_DOUBLE_EQ(run_balance(o, wall).tile_cost, 0.3);
  EXPECT_TRUE(balance_refusal(o, wall, RunPlace::OneMachine).ok());
  EXPECT_EQ(balance_refusal(o, default_wall(), RunPlace::OneMachine).reason(),
            "--resistance needs balancing: --balance strips or kd, or a wall file's [balance]");
  o.resistance.reset();
  EXPECT_EQ(balance_refusal(o, default_wall(), RunPlace::OneMachine).reason(),
            "--tile-cost needs balancing: --balance strips or kd, or a wall file's [balance]");
}

}  // namespace
}  // namespace l2
