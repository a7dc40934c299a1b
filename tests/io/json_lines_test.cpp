// The manifest's file (io/JsonLines.h): whole lines or none. A full disk is simulated with
// RLIMIT_FSIZE and SIGXFSZ ignored: a write past the limit is cut short, then fails with EFBIG.
#include "core/Error.h"
#include "io/JsonLines.h"

#include "../common/temp_dir_test.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

class JsonLinesTest : public test::TempDirTest {};

std::string contentOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeRaw(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary);
  out << bytes;
}

TEST_F(JsonLinesTest, APartialLastLineIsCutOffBeforeAppending) {
  const fs::path file = dir_ / "manifest.jsonl";
  writeRaw(file, "{\"frame\":0}\n{\"frame\":1,\"fi");
  EXPECT_EQ(readCompleteLines(file), std::vector<std::string>{"{\"frame\":0}"});
  appendLine(file, "{\"frame\":2}");
  EXPECT_EQ(contentOf(file), "{\"frame\":0}\n{\"frame\":2}\n");
  // Nothing but a part of a line: the file is that line's, so it empties.
  writeRaw(file, "{\"fra");
  appendLine(file, "{\"frame\":3}");
  EXPECT_EQ(contentOf(file), "{\"frame\":3}\n");
}

TEST_F(JsonLinesTest, ALineThatDoesNotFitLeavesNoPartOfIt) {
  const fs::path file = dir_ / "manifest.jsonl";
  appendLine(file, std::string(100, 'a'));
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  const auto oldSignal = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limit = old;
  limit.rlim_cur = 150;  // the second line's first 49 bytes fit
  setrlimit(RLIMIT_FSIZE, &limit);
  std::string message;
  try {
    appendLine(file, std::string(100, 'b'));
  } catch (const InputError& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldSignal);
  EXPECT_NE(message.find("manifest.jsonl: cannot append to it: File too large"), std::string::npos) << message;
  EXPECT_EQ(contentOf(file), std::string(100, 'a') + "\n");
}

TEST_F(JsonLinesTest, CheckAppendableRefusesWhatCannotBeAppendedTo) {
  const fs::path file = dir_ / "manifest.jsonl";
  EXPECT_NO_THROW(checkAppendable(file, "--manifest"));  // made by the first line
  fs::create_directory(dir_ / "folder.jsonl");
  EXPECT_THROW(checkAppendable(dir_ / "folder.jsonl", "--manifest"), InputError);
  writeRaw(file, "");
  EXPECT_NO_THROW(checkAppendable(file, "--manifest"));
}

TEST_F(JsonLinesTest, CheckAppendableRefusesAReadOnlyFile) {
  if (::geteuid() == 0)
    GTEST_SKIP() << "root may append to a read-only file: the read-only case is in cli_capture (as nobody)";
  const fs::path file = dir_ / "manifest.jsonl";
  writeRaw(file, "");
  ::chmod(file.c_str(), 0444);
  EXPECT_THROW(checkAppendable(file, "--manifest"), InputError);
}

}  // namespace
}  // namespace lenslab
