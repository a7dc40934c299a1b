#include "TableCheck.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace lenslab::stability {
namespace {

// A figure taken out of a cell: a PSNR in dB (infinity for "identical") or a colour difference.
struct Figure {
  bool psnr = false;
  double value = 0.0;
  std::string text;  // as the cell writes it
};

// A cell's words, with each figure replaced by a placeholder, and its figures in order.
struct Split {
  std::string words;
  std::vector<Figure> figures;
};

bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

// The length of a decimal number at the start of `s` ([-+]digits[.digits][e[-+]digits]), 0 if none.
std::size_t numberLength(std::string_view s, bool allowExponent) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  const std::size_t digitsFrom = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  }
  if (i == digitsFrom || (i == digitsFrom + 1 && s[digitsFrom] == '.')) return 0;
  if (allowExponent && i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
    const std::size_t expFrom = j;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
    if (j > expFrom) i = j;
  }
  return i;
}

// `s` starts with `word` and no word character follows it.
bool startsWithWord(std::string_view s, std::string_view word) {
  return s.substr(0, word.size()) == word && (s.size() == word.size() || !wordChar(s[word.size()]));
}

Split split(const std::string& cell, BareNumbers bare) {
  Split out;
  const std::string_view s(cell);
  std::size_t i = 0;
  while (i < s.size()) {
    const std::string_view rest = s.substr(i);
    if (i == 0 || !wordChar(s[i - 1])) {
      if (startsWithWord(rest, "identical")) {
        out.figures.push_back({true, std::numeric_limits<double>::infinity(), "identical"});
        out.words += "{dB}";
        i += 9;
        continue;
      }
      if (const std::size_t n = numberLength(rest, false); n > 0 && startsWithWord(rest.substr(n), " dB")) {
        const std::string number(rest.substr(0, n));
        out.figures.push_back({true, std::strtod(number.c_str(), nullptr), std::string(rest.substr(0, n + 3))});
        out.words += "{dB}";
        i += n + 3;
        continue;
      }
      if (bare == BareNumbers::ColourDifference) {
        std::size_t n = numberLength(rest, true);
        if (n == 0 && startsWithWord(rest, "inf")) n = 3;
        if (n > 0 && (n == rest.size() || !wordChar(rest[n]))) {
          const std::string text(rest.substr(0, n));
          out.figures.push_back(
              {false, text == "inf" ? std::numeric_limits<double>::infinity() : std::strtod(text.c_str(), nullptr),
               text});
          out.words += "{x}";
          i += n;
          continue;
        }
      }
    }
    out.words += s[i];
    ++i;
  }
  return out;
}

// A PSNR figure as the RMS error it stands for (0 for "identical").
double rmsOf(const Figure& f) { return f.psnr ? std::pow(10.0, -f.value / 20.0) : f.value; }

bool agree(const Figure& a, const Figure& b) {
  const double x = rmsOf(a), y = rmsOf(b);
  if (std::isinf(x) || std::isinf(y)) return x == y;
  if (std::isnan(x) || std::isnan(y)) return false;
  const double d = std::abs(x - y);
  return d <= kRoundingFloor || d <= kRelativeTolerance * std::max(std::abs(x), std::abs(y));
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return std::string(s);
}

// The cells of one table line "| a | b | c |", '\|' inside a cell kept as part of it.
std::vector<std::string> cellsOf(const std::string& line) {
  std::vector<std::string> cells;
  std::string current;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      current += "\\|";
      ++i;
    } else if (line[i] == '|') {
      cells.push_back(unescapeCell(trimmed(current)));
      current.clear();
    } else {
      current += line[i];
    }
  }
  return cells;
}

}  // namespace

std::string escapeCell(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string unescapeCell(const std::string& cell) {
  std::string out;
  for (std::size_t i = 0; i < cell.size(); ++i) {
    if (cell[i] == '\\' && i + 1 < cell.size() && cell[i + 1] == '|') ++i;
    out += cell[i];
  }
  return out;
}

std::vector<TableRow> parseDocTable(const std::string& doc, const std::string& docName) {
  const auto a = doc.find(kTableBegin), b = doc.find(kTableEnd);
  if (a == std::string::npos || b == std::string::npos || b < a)
    throw std::runtime_error(docName + ": no stability table between " + kTableBegin + " and " + kTableEnd);
  std::vector<TableRow> rows;
  std::string group;
  std::size_t from = a + std::string_view(kTableBegin).size();
  while (from < b) {
    const std::size_t eol = std::min(doc.find('\n', from), b);
    const std::string line = trimmed(std::string_view(doc).substr(from, eol - from));
    from = eol + 1;
    if (line.empty() || line.front() != '|') continue;
    const std::vector<std::string> c = cellsOf(line);
    if (c.size() != 4) throw std::runtime_error(docName + ": a stability table row without 4 cells: " + line);
    if (c[1] == "case" || c[1].starts_with("---")) continue;  // the header and its separator
    if (!c[0].empty()) group = c[0];
    rows.push_back({group, c[1], c[2], c[3]});
  }
  return rows;
}

std::string cellDifference(const std::string& documented, const std::string& measured, BareNumbers bare) {
  const Split d = split(documented, bare), m = split(measured, bare);
  if (d.words != m.words) return "the words differ: the doc says \"" + documented + "\", this run \"" + measured + "\"";
  for (std::size_t i = 0; i < d.figures.size(); ++i)
    if (!agree(d.figures[i], m.figures[i])) {
      char floor[32], tolerance[160];
      std::snprintf(floor, sizeof floor, "%g", kRoundingFloor);
      std::string f = floor;  // "1e-05" as "1e-5"
      if (const auto e = f.find("e-0"); e != std::string::npos) f.erase(e + 2, 1);
      std::snprintf(tolerance, sizeof tolerance, "beyond the tolerance (%s within %.0f %% of the larger or within %s)",
                    d.figures[i].psnr ? "RMS errors" : "differences", 100 * kRelativeTolerance, f.c_str());
      return "figure " + std::to_string(i + 1) + " moved from " + d.figures[i].text + " (the doc) to " +
             m.figures[i].text + " (this run), " + tolerance;
    }
  return {};
}

}  // namespace lenslab::stability
