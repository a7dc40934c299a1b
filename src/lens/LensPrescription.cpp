#include "lens/LensPrescription.h"

#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/ParseNumber.h"
#include "core/Text.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace lenslab {
namespace {

constexpr const char* kColumns[] = {"radius_mm", "thickness_mm", "index", "aperture_mm", "abbe"};

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == ',')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != ',') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

class RowReader {
 public:
  RowReader(const std::string& source, int line, int row) : source_(source), line_(line), row_(row) {}

  [[noreturn]] void refuse(int column, const std::string& what) const {
    throw InputError(
        cat(source_, ": row ", row_, " (line ", line_, "), column ", column + 1, " (", kColumns[column], "): ", what));
  }

  double number(std::string_view text, int column) const {
    if (column == 0 && (text == "inf" || text == "-inf" || text == "infinity" || text == "-infinity")) return INFINITY;
    const std::optional<double> value = parseFiniteNumber(text);
    if (!value)
      refuse(column,
             cat("'", text, "' is not a number", column == 0 ? " (give mm, 0 for the stop, inf for a plane)" : ""));
    // Lengths through the number layer, in a stated range: a lens is millimetres to metres, and
    // 1e300 mm would overflow every sum along the axis.
    if (column == 0 || column == 1 || column == 3) {
      const double max = column == 0 ? kMaxLensRadiusMm : kMaxLensLengthMm;
      // (A negative thickness or aperture gets its own message below.)
      const NumberRange range{column == 0 ? -max : -INFINITY, max, "millimetres"};
      if (const std::optional<std::string> problem = numberProblem(*value, range, text))
        refuse(column, cat(*problem, column == 0 ? " (0 for the stop, inf for a plane)" : ""));
    }
    return *value;
  }

 private:
  const std::string& source_;
  int line_;
  int row_;
};

// Two neighbouring surfaces must not cross within the smaller clear aperture: an element (or an
// air gap) cannot be thinner than nothing at its edge. A file whose second column holds each
// surface's distance from the one before (a shifted column) is refused on its first row already.
void refuseCrossingSurfaces(const LensPrescription& lens) {
  for (std::size_t i = 0; i + 1 < lens.surfaces.size(); ++i) {
    const LensSurface& a = lens.surfaces[i];
    const LensSurface& b = lens.surfaces[i + 1];
    const double r = 0.5 * std::min(a.apertureMm, b.apertureMm);
    const double edge = a.thicknessMm + b.sagMm(r) - a.sagMm(r);
    if (edge < -1e-9 * std::max(1.0, r))
      throw InputError(cat(lens.source, ": rows ", i + 1, " and ", i + 2, " (lines ", a.line, " and ", b.line,
                           ") cross inside their clear aperture: ", a.thicknessMm, " mm apart on the axis but ", edge,
                           " mm at a height of ", r,
                           " mm; column 2 (thickness_mm) is the distance from each surface to the next"));
  }
}

}  // namespace

bool LensSurface::isPlane() const { return std::isinf(radiusMm); }

double LensSurface::curvaturePerMm() const { return isStop() || isPlane() ? 0.0 : 1.0 / radiusMm; }

double LensSurface::sagMm(double r) const {
  if (isStop() || isPlane()) return 0.0;
  return radiusMm - std::copysign(std::sqrt(std::max(0.0, radiusMm * radiusMm - r * r)), radiusMm);
}

std::size_t LensPrescription::stopIndex() const {
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].isStop()) return i;
  return surfaces.size();
}

bool LensPrescription::hasDispersion() const {
  bool any = false;
  for (const LensSurface& s : surfaces)
    if (s.indexAfter != 1.0) {
      if (s.abbeAfter <= 0.0) return false;
      any = true;
    }
  return any;
}

double LensPrescription::vertexMm(std::size_t i) const {
  double z = 0.0;
  for (std::size_t k = 0; k < i; ++k) z += surfaces[k].thicknessMm;
  return z;
}

LensPrescription parseLensPrescription(std::string_view text, const std::string& source) {
  LensPrescription lens;
  lens.source = source;
  int lineNumber = 0;
  std::size_t begin = 0;
  int stops = 0, withAbbe = 0, glassRows = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    ++lineNumber;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
      std::string_view comment = line.substr(hash + 1);
      while (!comment.empty() && (comment.front() == ' ' || comment.front() == '\t')) comment.remove_prefix(1);
      while (!comment.empty() && (comment.back() == ' ' || comment.back() == '\t' || comment.back() == '\r'))
        comment.remove_suffix(1);
      if (!comment.empty()) lens.comments.emplace_back(comment);
      line = line.substr(0, hash);
    }
    const std::vector<std::string_view> f = fields(line);
    if (f.empty()) continue;
    const int row = static_cast<int>(lens.surfaces.size()) + 1;
    if (row > kMaxLensSurfaces)
      throw InputError(cat(source, ": row ", row, " (line ", lineNumber, "): more than ", kMaxLensSurfaces,
                           " surface rows; lenslab traces at most ", kMaxLensSurfaces,
                           " (a camera lens has fewer than 60)"));
    const RowReader r(source, lineNumber, row);
    if (f.size() < 4 || f.size() > 5)
      throw InputError(cat(source, ": row ", row, " (line ", lineNumber, ") has ", f.size(),
                           " numbers; give 4 or 5: radius_mm thickness_mm index aperture_mm [abbe]"));
    LensSurface s;
    s.line = lineNumber;
    s.radiusMm = r.number(f[0], 0);
    s.thicknessMm = r.number(f[1], 1);
    s.indexAfter = r.number(f[2], 2);
    s.apertureMm = r.number(f[3], 3);
    s.abbeAfter = f.size() == 5 ? r.number(f[4], 4) : 0.0;
    if (s.thicknessMm < 0.0)
      r.refuse(1, cat(s.thicknessMm, " is negative; give the axial distance to the next surface, >= 0"));
    // (A file whose second column is each surface's distance from the one before starts so.)
    if (s.thicknessMm == 0.0 && r.number(f[2], 2) > 1.0)
      r.refuse(
          1, "0 for a glass: an element needs a centre thickness > 0 (the column is the distance to the next surface)");
    if (s.indexAfter == 0.0) s.indexAfter = 1.0;  // pbrt's files: 0 on the stop row, meaning air
    if (!(s.indexAfter >= 1.0 && s.indexAfter <= 4.0))
      r.refuse(2, cat(s.indexAfter, " is not a refractive index; give n_d in [1, 4], or 0 or 1 for air"));
    if (!(s.apertureMm > 0.0)) r.refuse(3, cat(s.apertureMm, " is not a diameter; give the clear aperture in mm, > 0"));
    if (s.abbeAfter < 0.0 || (s.abbeAfter > 0.0 && s.abbeAfter < 5.0) || s.abbeAfter > 150.0)
      r.refuse(4, cat(s.abbeAfter, " is not an Abbe number; give V_d in [5, 150], or 0 for none"));
    if (s.abbeAfter > 0.0 && s.indexAfter == 1.0) r.refuse(4, "air has no Abbe number; give 0 or leave the column out");
    if (!s.isStop() && !s.isPlane() && std::abs(s.radiusMm) < 0.5 * s.apertureMm)
      r.refuse(0, cat("|", s.radiusMm, "| is smaller than half the aperture (", s.apertureMm,
                      " mm): no sphere of that radius has such a rim; give |radius| >= aperture / 2"));
    if (s.isStop()) {
      ++stops;
      if (s.indexAfter != 1.0) r.refuse(2, cat("the stop (radius 0) sits in air; give 0 or 1, not ", s.indexAfter));
    }
    if (s.indexAfter != 1.0) {
      ++glassRows;
      if (s.abbeAfter > 0.0) ++withAbbe;
    }
    lens.surfaces.push_back(s);
  }
  if (lens.surfaces.size() < 2)
    throw InputError(
        cat(source, ": ", lens.surfaces.size(), " surface rows; a lens needs at least the stop and one surface"));
  if (stops != 1)
    throw InputError(
        cat(source, ": ", stops, " rows have radius 0; mark exactly one row, the aperture stop, with radius 0"));
  if (lens.surfaces.back().indexAfter != 1.0)
    throw InputError(
        cat(source, ": row ", lens.surfaces.size(), " (line ", lens.surfaces.back().line,
            "), column 3 (index): the last surface must leave the light in air (0 or 1), toward the film"));
  refuseCrossingSurfaces(lens);
  if (withAbbe != 0 && withAbbe != glassRows)
    throw InputError(cat(source, ": ", withAbbe, " of ", glassRows,
                         " glass rows give an Abbe number (column 5); give one on every glass row, or on none"));
  return lens;
}

}  // namespace lenslab
