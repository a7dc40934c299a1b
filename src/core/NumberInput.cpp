#include "core/NumberInput.h"

#include "core/Error.h"
#include "core/ParseNumber.h"

#include <charconv>
#include <cmath>

namespace lenslab {
namespace {

// "a finite value from 1 to 100", "a finite value of at least 0", "a finite value".
std::string validValues(const NumberRange& r) {
  const bool low = std::isfinite(r.min), high = std::isfinite(r.max);
  if (low && high) return "a finite value from " + numberText(r.min) + " to " + numberText(r.max);
  if (low) return "a finite value of at least " + numberText(r.min);
  if (high) return "a finite value of at most " + numberText(r.max);
  return "a finite value";
}

std::string ofUnit(const NumberRange& r) { return r.unit.empty() ? std::string() : " of " + std::string(r.unit); }

}  // namespace

std::string excerpt(std::string_view text) {
  if (text.size() <= kMaxQuotedChars) return std::string(text);
  std::size_t cut = kMaxQuotedChars;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return std::string(text.substr(0, cut)) + "…";
}

std::string numberText(double value) {
  if (value == 0.0) return "0";
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::optional<std::string> numberProblem(double value, const NumberRange& range, std::string_view given) {
  const std::string shown = given.empty() ? numberText(value) : excerpt(given);
  if (!std::isfinite(value)) return shown + " is not a finite number" + ofUnit(range) + "; give " + validValues(range);
  if (value < range.min || value > range.max) return shown + " is out of range; give " + validValues(range);
  return std::nullopt;
}

std::optional<std::string> numberTextProblem(std::string_view text, const NumberRange& range) {
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  const std::optional<double> value = parseDouble(digits);
  if (!value) {
    // from_chars refuses what overflows a double (1e309) as out of range: not finite either.
    double ignored = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), ignored);
    if (error == std::errc::result_out_of_range && end == digits.data() + digits.size())
      return excerpt(text) + " is not a finite number" + ofUnit(range) + "; give " + validValues(range);
    return excerpt(text) + " is not a number" + ofUnit(range) + "; give " + validValues(range);
  }
  return numberProblem(*value, range, text);
}

double checkedNumber(std::string_view field, double value, const NumberRange& range) {
  if (const auto problem = numberProblem(value, range)) throw InputError(std::string(field) + ": " + *problem);
  return value;
}

double readNumber(std::string_view field, std::string_view text, const NumberRange& range) {
  if (const auto problem = numberTextProblem(text, range)) throw InputError(std::string(field) + ": " + *problem);
  return *parseDouble(!text.empty() && text.front() == '+' ? text.substr(1) : text);
}

}  // namespace lenslab
