#pragma once
// The one way a number from a user (a command-line option, a field of a file) is read and checked:
// it must spell a number, be finite (nan, inf and overflowing values such as 1e309 are refused,
// which a plain range check lets through: nan compares false with every bound), and lie in its
// field's range. The message names the field, quotes at most kMaxQuotedChars of what was given,
// and says what would be valid in the field's unit:
//   --time: nan is not a number of seconds; give a finite value from -1e+09 to 1e+09
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace lenslab {

// What a field takes: inclusive bounds (±infinity: none) and its unit in words, plural
// ("seconds", "millimetres", "dB", "pixels").
struct NumberRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  std::string_view unit;
};

// User text quoted in a message: at most kMaxQuotedChars, else cut with an ellipsis ("…").
constexpr std::size_t kMaxQuotedChars = 60;
std::string excerpt(std::string_view text);

// A number as messages print it: the shortest text that reads back as the same double (1e+09).
std::string numberText(double value);

// What is wrong with `value` for a field of `range`, or nullopt when it is fine. `given` is the
// text the user wrote (quoted in the message), or empty to print the value.
std::optional<std::string> numberProblem(double value, const NumberRange& range, std::string_view given = {});
// What is wrong with `text` as a number of `range` (not a number at all, or numberProblem's).
// A leading '+' is allowed, as CLI11 and strtod allow it.
std::optional<std::string> numberTextProblem(std::string_view text, const NumberRange& range);

// `value`, or InputError "<field>: <numberProblem>".
double checkedNumber(std::string_view field, double value, const NumberRange& range);
// `text` read as a number of `range`, or InputError "<field>: <numberTextProblem>".
double readNumber(std::string_view field, std::string_view text, const NumberRange& range);

}  // namespace lenslab
