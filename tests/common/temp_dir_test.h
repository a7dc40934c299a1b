#pragma once
// A test fixture with a fresh, empty folder of its own (named after the test and the run's seed,
// removed afterwards), for tests that write files.
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <iterator>
#include <string>

namespace lenslab::test {

class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::UnitTest& run = *::testing::UnitTest::GetInstance();
    dir_ = std::filesystem::temp_directory_path() /
           ("lenslab-" + std::string(run.current_test_info()->test_suite_name()) + "-" +
            std::to_string(run.random_seed()) + "-" + run.current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Every name under the folder, dot files (temporaries, probes) and subfolders included.
  std::size_t fileCount() const {
    return static_cast<std::size_t>(std::distance(std::filesystem::recursive_directory_iterator(dir_),
                                                  std::filesystem::recursive_directory_iterator()));
  }

  std::filesystem::path dir_;
};

}  // namespace lenslab::test
