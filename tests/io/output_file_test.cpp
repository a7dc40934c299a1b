// Outputs whole or not at all (io/AtomicFile.h) and checked before any work (io/OutputPath.h).
// A full disk is simulated with RLIMIT_FSIZE and SIGXFSZ ignored: write(2) past the limit then
// fails with EFBIG, the way it fails with ENOSPC on a full disk, without mounting anything.
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ImageFile.h"
#include "io/OutputPath.h"

#include "../common/temp_dir_test.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include <sys/resource.h>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

class OutputFileTest : public test::TempDirTest {};

// Writes past `bytes` fail with EFBIG while one lives; the old limit and signal action come back.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &old_);
    oldSignal_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = old_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, oldSignal_);
  }

 private:
  rlimit old_{};
  void (*oldSignal_)(int) = nullptr;
};

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

Image noise(int width, int height) {
  Image image(width, height);
  unsigned state = 1;
  for (float& v : image.rgba) v = static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f;
  return image;
}

TEST_F(OutputFileTest, NothingAppearsBeforeCommitAndNothingIsLeftWithoutIt) {
  {
    OutputSet outputs;
    outputs.add(dir_ / "a.txt", "a");
    EXPECT_FALSE(fs::exists(dir_ / "a.txt"));
    EXPECT_EQ(fileCount(), 1u) << "one temporary file";
  }
  EXPECT_EQ(fileCount(), 0u);
  OutputSet outputs;
  outputs.add(dir_ / "a.txt", "a");
  outputs.add(dir_ / "b.txt", "bb");
  outputs.commit();
  EXPECT_EQ(fs::file_size(dir_ / "b.txt"), 2u);
  EXPECT_EQ(fileCount(), 2u) << "no temporary file left";
}

// A disk that fills up on the second file takes the first one with it: nothing new is left,
// and the message names the file and the reason.
TEST_F(OutputFileTest, AFailedWriteLeavesNothingOfTheWholeSet) {
  const std::string small(100, 's'), large(8192, 'L');
  {
    OutputSet outputs;
    outputs.createFolders(dir_ / "new" / "deeper");
    outputs.add(dir_ / "new" / "small.txt", small);
    FileSizeLimit limit(4096);
    const std::string message = messageOf([&] { outputs.add(dir_ / "new" / "deeper" / "large.txt", large); });
    EXPECT_NE(message.find("large.txt: cannot write it: File too large"), std::string::npos) << message;
  }
  EXPECT_EQ(fileCount(), 0u) << "neither file, no temporary file, and not the folders made for them";
}

// The temporary file's name is short whatever the target's: a target of NAME_MAX bytes is written
// (a temporary name made longer than its target's used to fail with "File name too long").
TEST_F(OutputFileTest, ATargetNamedWithAllOfNameMaxIsWritten) {
  const fs::path target = dir_ / (std::string(251, 'n') + ".png");
  ASSERT_EQ(target.filename().string().size(), 255u);
  EXPECT_NO_THROW(writeImage(target, noise(4, 4)));
  EXPECT_TRUE(fs::exists(target));
  EXPECT_EQ(fileCount(), 1u);
  const std::string message =
      messageOf([&] { checkOutputPath(dir_ / ("n" + target.filename().string()), OutputKind::Image, "--out"); });
  EXPECT_NE(message.find("the file name is 256 bytes"), std::string::npos) << message;
}

TEST_F(OutputFileTest, FoldersThatWereThereStay) {
  fs::create_directories(dir_ / "kept");
  {
    OutputSet outputs;
    outputs.createFolders(dir_ / "kept" / "made");
  }
  EXPECT_TRUE(fs::is_directory(dir_ / "kept"));
  EXPECT_FALSE(fs::exists(dir_ / "kept" / "made"));
}

// OIIO's PNG writer returns true from write_image() and close() after a failed write; the image
// is encoded in memory and written with checked write(2) calls instead.
TEST_F(OutputFileTest, ImagesThatDoNotFitFailWithTheReason) {
  const Image image = noise(64, 64);  // 12 KiB of PNG, 64 KiB of EXR: neither compresses noise
  for (const char* name : {"a.png", "a.exr"}) {
    FileSizeLimit limit(4096);
    const std::string message = messageOf([&] { writeImage(dir_ / name, image); });
    EXPECT_NE(message.find(std::string(name) + ": cannot write it: File too large"), std::string::npos) << message;
  }
  EXPECT_EQ(fileCount(), 0u);
  writeImage(dir_ / "a.png", image);  // and without the limit, it fits
  EXPECT_GT(fs::file_size(dir_ / "a.png"), 4096u);
}

TEST_F(OutputFileTest, OverwritingKeepsTheOldFileUntilTheNewOneIsWhole) {
  writeTextFileAtomically(dir_ / "a.json", "old");
  {
    FileSizeLimit limit(1024);
    EXPECT_THROW(writeTextFileAtomically(dir_ / "a.json", std::string(4096, 'n')), InputError);
  }
  std::ifstream in(dir_ / "a.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "old");
  EXPECT_EQ(fileCount(), 1u);
}

TEST_F(OutputFileTest, CheckOutputPathRefusesWhatCouldNotBeWritten) {
  std::ofstream(dir_ / "file") << "x";
  fs::create_directories(dir_ / "folder.json");
  const auto refusal = [](const fs::path& p, OutputKind kind) {
    return messageOf([&] { checkOutputPath(p, kind, "--stats"); });
  };
  EXPECT_NE(refusal(dir_ / "missing" / "s.json", OutputKind::Json).find("/missing does not exist"), std::string::npos);
  EXPECT_NE(refusal(dir_ / "file" / "s.json", OutputKind::Json).find("/file is not a folder"), std::string::npos);
  EXPECT_NE(refusal(dir_ / "folder.json", OutputKind::Json).find("is a folder"), std::string::npos);
  EXPECT_NE(refusal(dir_ / "s.txt", OutputKind::Json).find("give a .json file name"), std::string::npos);
  EXPECT_NE(refusal(dir_ / "a.jpg", OutputKind::Image).find("unsupported image type"), std::string::npos);
  EXPECT_EQ(refusal(dir_ / "s.json", OutputKind::Json), "(no error)");
  EXPECT_EQ(refusal(dir_ / "sweep.md", OutputKind::Any), "(no error)");
  EXPECT_NE(refusal(dir_ / "missing" / "s.json", OutputKind::Json).rfind("--stats ", 0), std::string::npos)
      << "names the option";
  EXPECT_EQ(fileCount(), 2u) << "the probe file is gone again";
}

}  // namespace
}  // namespace lenslab
