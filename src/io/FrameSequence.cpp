#include "io/FrameSequence.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cctype>
#include <climits>
#include <cstdio>

namespace lenslab {

namespace {

// Where the one conversion is: [begin, end) of "%…d"; -1 when there is none.
struct Conversion {
  std::size_t begin = std::string::npos;
  std::size_t end = 0;
  int width = 0;
  bool zeros = false;
};

Conversion findConversion(const std::string& pattern, const std::string& option) {
  Conversion found;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    Conversion c;
    c.begin = i;
    if (j < pattern.size() && pattern[j] == '0') c.zeros = true;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && c.width < 100)
      c.width = c.width * 10 + (pattern[j++] - '0');
    if (j >= pattern.size() || pattern[j] != 'd' || c.width > 32)
      throw InputError(
          cat(option, " ", pattern, ": only %d, %Nd or %0Nd (N ≤ 32) may follow a % (write %% for a % sign)"));
    c.end = j + 1;
    if (found.begin != std::string::npos)
      throw InputError(cat(option, " ", pattern, ": give one frame number (one %d), not two"));
    found = c;
    i = j;
  }
  if (found.begin == std::string::npos)
    throw InputError(cat(option, " ", pattern,
                         ": give a pattern with one %d for the frame number, e.g. frames/frame_%04d.exr, so that "
                         "frames do not overwrite each other"));
  return found;
}

int parseInt(const std::string& text, const std::string& what) {
  if (text.empty() || text.size() > 9) throw InputError(what);
  for (const char ch : text)
    if (!std::isdigit(static_cast<unsigned char>(ch))) throw InputError(what);
  return std::stoi(text);
}

}  // namespace

void checkFramePattern(const std::string& pattern, const std::string& option) { (void)findConversion(pattern, option); }

std::string formatFramePath(const std::string& pattern, int frame) {
  const Conversion c = findConversion(pattern, "--out");
  std::string number = std::to_string(frame);
  if (static_cast<int>(number.size()) < c.width)
    number.insert(0, static_cast<std::size_t>(c.width) - number.size(), c.zeros ? '0' : ' ');
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (i == c.begin) {
      out += number;
      i = c.end - 1;
    } else if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] == '%') {
      out += '%';
      ++i;
    } else {
      out += pattern[i];
    }
  }
  return out;
}

std::optional<int> frameNamedBy(const std::string& pattern, const std::filesystem::path& path) {
  const auto normal = [](const std::filesystem::path& p) { return std::filesystem::absolute(p).lexically_normal(); };
  // Normalising leaves the conversion as it is: it holds no separator and no dot.
  const std::string normalPattern = normal(pattern).string(), text = normal(path).string();
  const Conversion c = findConversion(normalPattern, "--out");
  const std::string before = formatFramePath(normalPattern.substr(0, c.begin) + "%d", 0),
                    after = formatFramePath("%d" + normalPattern.substr(c.end), 0);
  // The literal text either side of the number ("0" stands for it in both).
  const std::string prefix = before.substr(0, before.size() - 1), suffix = after.substr(1);
  if (text.size() <= prefix.size() + suffix.size() || text.compare(0, prefix.size(), prefix) != 0 ||
      text.compare(text.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  std::string digits = text.substr(prefix.size(), text.size() - prefix.size() - suffix.size());
  digits.erase(0, digits.find_first_not_of(' '));
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  const int frame = std::stoi(digits);
  // Only the number's own spelling (its width and padding) names that frame.
  if (formatFramePath(normalPattern, frame) != text) return std::nullopt;
  return frame;
}

bool inRange(FrameRange range, int frame) {
  return frame >= range.first && frame <= range.last && (frame - range.first) % range.step == 0;
}

FrameRange parseFrameRange(const std::string& text, int frameCount) {
  const std::string usage =
      cat("--frames ", text, ": give A:B (inclusive), A:, :B or one frame N, within 0:", frameCount - 1,
          " (the path has ", frameCount, " frame", frameCount == 1 ? "" : "s",
          "), and :STEP after a range for every STEP-th frame (e.g. 0:", frameCount - 1, ":12)");
  FrameRange r{0, frameCount - 1, 1};
  const auto colon = text.find(':');
  if (colon == std::string::npos) {
    r.first = r.last = parseInt(text, usage);
  } else {
    const auto second = text.find(':', colon + 1);
    const std::string a = text.substr(0, colon);
    const std::string b = text.substr(colon + 1, second == std::string::npos ? std::string::npos : second - colon - 1);
    if (second != std::string::npos) {
      const std::string step = text.substr(second + 1);
      // The step's own message: 0, a negative or a fraction is the likely slip, not the range.
      const std::string stepUsage = cat("--frames ", text,
                                        ": the step after the second colon must be a whole number of "
                                        "frames, 1 or more (e.g. 0:",
                                        frameCount - 1, ":12 for every 12th frame)");
      if (step.find(':') != std::string::npos) throw InputError(usage);
      r.step = parseInt(step, stepUsage);
      if (r.step < 1) throw InputError(stepUsage);
    } else if (a.empty() && b.empty()) {
      throw InputError(usage);  // ":" alone
    }
    if (!a.empty()) r.first = parseInt(a, usage);
    if (!b.empty()) r.last = parseInt(b, usage);
  }
  if (r.first > r.last || r.last >= frameCount) throw InputError(usage);
  return r;
}

Shard parseShard(const std::string& text) {
  const std::string usage =
      cat("--shard ", text, ": give I/N, this process's index I from 0 to N-1 of N processes (e.g. 0/4)");
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw InputError(usage);
  Shard s{parseInt(text.substr(0, slash), usage), parseInt(text.substr(slash + 1), usage)};
  if (s.count < 1 || s.index >= s.count) throw InputError(usage);
  return s;
}

std::vector<int> shardFrames(FrameRange range, Shard shard) {
  std::vector<int> frames;
  const long long step = range.step;
  for (long long f = range.first + step * shard.index; f <= range.last; f += step * shard.count)
    frames.push_back(static_cast<int>(f));
  return frames;
}

std::uint32_t frameSeed(std::uint32_t seed, int frame) {
  // SplitMix64's finaliser over (seed, frame): neighbouring frames get unrelated seeds.
  std::uint64_t z = (std::uint64_t{seed} << 32 | static_cast<std::uint32_t>(frame)) + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<std::uint32_t>(z >> 32);
}

std::filesystem::path frameCameraPath(const std::filesystem::path& image) {
  std::filesystem::path p = image;
  p.replace_extension(".camera.json");
  return p;
}

}  // namespace lenslab
