#include <gtest/gtest.h>

#include "scene/Suggest.hpp"

namespace efg {
namespace {

TEST(Suggest, EditDistance) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("material", "material"), 0u);
}

TEST(Suggest, ClosestMatchOnlyForPlausibleTypos) {
  const std::vector<std::string> keys = {"name", "blocks", "material", "section"};
  EXPECT_EQ(closest_match("materail", keys), "material");
  EXPECT_EQ(closest_match("block", keys), "blocks");
  EXPECT_FALSE(closest_match("velocity", keys).has_value());
}

}  // namespace
}  // namespace efg
