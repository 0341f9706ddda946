// The image cache's limit each pipeserver of a picture or session run is started with, where
// --picture-cache-mb is not given: a sixteenth of the machine's memory shared among them, at
// least 512 MiB; given, it is passed on as typed.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "l2wall/run_backends.hpp"
#include "pipeserver/picture_cache.hpp"

namespace l2 {
namespace {

TEST(PictureCacheDefault, ASixteenthOfTheMachineSharedAtLeast512) {
  EXPECT_DOUBLE_EQ(default_picture_cache_mb(65536, 2), 2048);  // 64 GiB, two pipeservers
  EXPECT_DOUBLE_EQ(default_picture_cache_mb(16384, 1), 1024);  // 16 GiB alone
  EXPECT_DOUBLE_EQ(default_picture_cache_mb(24576, 4), 512);   // 384 MiB each: the floor
  EXPECT_DOUBLE_EQ(default_picture_cache_mb(0, 0), 512);       // a machine that does not say
}

TEST(PictureCacheDefault, AddedToPictureAndSessionRunsOnly) {
  PipeserverLaunch picture;
  picture.scene = "picture";
  picture.scene_args = {"--content", "big.tif"};
  add_picture_cache_default(picture, 4, 131072);  // 128 GiB, four pipeservers
  EXPECT_EQ(picture.scene_args,
            (std::vector<std::string>{"--content", "big.tif", "--picture-cache-mb", "2048"}));

  PipeserverLaunch given;
  given.scene = "session";
  given.scene_args = {"--picture-cache-mb", "16"};
  add_picture_cache_default(given, 4, 131072);
  EXPECT_EQ(given.scene_args, (std::vector<std::string>{"--picture-cache-mb", "16"}));

  PipeserverLaunch mesh;
  mesh.scene = "mesh";
  add_picture_cache_default(mesh, 4, 131072);
  EXPECT_TRUE(mesh.scene_args.empty());
}

}  // namespace
}  // namespace l2
