// "Did you mean": the nearest command or option name to a typo (core/NearestName.h).
#include "core/NearestName.h"

#include <gtest/gtest.h>

namespace lenslab {
namespace {

TEST(NearestName, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(editDistance("render", "render"), 0);
  EXPECT_EQ(editDistance("rendr", "render"), 1);    // a deletion
  EXPECT_EQ(editDistance("renderr", "render"), 1);  // an insertion
  EXPECT_EQ(editDistance("rander", "render"), 1);   // a substitution
  EXPECT_EQ(editDistance("lenght", "length"), 1);   // two neighbours swapped
  EXPECT_EQ(editDistance("", "view"), 4);
  EXPECT_EQ(editDistance("sweep", "info"), 5);
}

TEST(NearestName, SuggestsTheNearestWhenItIsATypo) {
  const std::vector<std::string> commands = {"render", "raycast", "capture", "sweep", "info", "view"};
  EXPECT_EQ(nearestName("rendr", commands), "render");
  EXPECT_EQ(nearestName("capure", commands), "capture");
  EXPECT_EQ(nearestName("veiw", commands), "view");
  EXPECT_EQ(nearestName("ray", commands), "raycast");  // an abbreviation
  EXPECT_EQ(nearestName("banana", commands), std::nullopt);
  EXPECT_EQ(nearestName("x", commands), std::nullopt);
  const std::vector<std::string> options = {"--focus-distance", "--focus-at", "--focal-length", "--width", "--height"};
  EXPECT_EQ(nearestName("--focal-lenght", options), "--focal-length");
  EXPECT_EQ(nearestName("--widht", options), "--width");
  EXPECT_EQ(nearestName("--focus", options), std::nullopt);  // begins two: no guess
  EXPECT_EQ(nearestName("--hieght", options), "--height");
}

TEST(NearestName, TwoEquallyNearNamesGiveNoGuess) {
  EXPECT_EQ(nearestName("cat", {"bat", "hat"}), std::nullopt);
  EXPECT_EQ(nearestName("cat", {"bat", "hats"}), "bat");
}

}  // namespace
}  // namespace lenslab
