#pragma once
// Output files appear whole or not at all: write to a temporary file beside the target (same
// folder, so rename is atomic; same extension, so format detection by extension still works),
// then rename it over the target. If commit() is never reached the temporary file is removed.
#include <filesystem>
#include <string_view>

namespace lenslab {

class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path target);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& temporaryPath() const { return temporary_; }
  const std::filesystem::path& targetPath() const { return target_; }
  // Renames the temporary file onto the target; throws InputError if that fails.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  bool committed_ = false;
};

// Writes `text` to `target` atomically.
void writeTextFileAtomically(const std::filesystem::path& target, std::string_view text);

}  // namespace lenslab
