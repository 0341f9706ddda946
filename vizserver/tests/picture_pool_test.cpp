#include "vizserver/picture_pool.hpp"
#include "vizserver/compositing_server.hpp"

#include <gtest/gtest.h>

namespace l2::viz {
namespace {

ComposedFrame frame_of(PicturePool& pool, std::uint32_t number) {
  ComposedFrame f;
  f.frame = number;
  f.displays.push_back(pool.take(4, 2));
  f.displays.push_back(pool.take(3, 3));
  return f;
}

TEST(PicturePool, ASharedFramesPicturesComeBackWhenItsLastHolderLetsGo) {
  const auto pool = PicturePool::make(4);
  FramePtr first = pool->share(frame_of(*pool, 0));
  const std::uint8_t* wide = first->displays[0].data();
  const std::uint8_t* square = first->displays[1].data();
  FramePtr other_holder = first;
  first.reset();
  EXPECT_EQ(pool->kept(), 0u);  // still held
  other_holder.reset();
  EXPECT_EQ(pool->kept(), 2u);
  // Each size gets its own picture back, whatever the order asked in.
  const RgbImage s = pool->take(3, 3);
  const RgbImage w = pool->take(4, 2);
  EXPECT_EQ(s.data(), square);
  EXPECT_EQ(w.data(), wide);
  EXPECT_EQ(pool->take(4, 2).width(), 4);  // none left: a new one
}

TEST(PicturePool, KeepsNoMoreThanItsLimitAndFramesMayOutliveIt) {
  auto pool = PicturePool::make(3);
  FramePtr a = pool->share(frame_of(*pool, 0));
  FramePtr b = pool->share(frame_of(*pool, 1));
  a.reset();
  b.reset();
  EXPECT_EQ(pool->kept(), 3u);
  FramePtr c = pool->share(frame_of(*pool, 2));
  pool.reset();  // c's pictures are freed when it goes, not given to a pool that is gone
  EXPECT_EQ(c->displays[1].width(), 3);
}

TEST(PicturePool, TheAssemblersNextFrameReusesTheSharedOnesPictures) {
  FrameAssembler a({{8, 4}}, 1, Rgb{9, 9, 9});
  ASSERT_TRUE(a.connect(0).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 0}).ok());
  FramePtr first = a.pictures().share(std::move(a.take_complete().at(0)));
  const std::uint8_t* bytes = first->displays[0].data();
  first.reset();
  ASSERT_TRUE(a.finish(0, FrameDone{0, 1, 0}).ok());
  const ComposedFrame second = std::move(a.take_complete().at(0));
  EXPECT_EQ(second.displays[0].data(), bytes);
  EXPECT_EQ(second.displays[0], RgbImage(8, 4, Rgb{9, 9, 9}));
}

}  // namespace
}  // namespace l2::viz
